/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The robots in lockstep windows (lockstep.h).
 *
 * With several threads, thread t runs robots t, t + T, t + 2T, ... (robots
 * next to each other by index are often alike, so interleaving spreads the
 * busy ones). A window is a few microseconds of work: a thread waiting for
 * the others spins on a counter a little while first, then sleeps on it
 * (a futex), so threads sharing their cores with other work do not burn
 * them: spinning alone made two threads slower than one on a busy machine. */
#include "lockstep.h"

#include <limits.h>
#include <linux/futex.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <sim_cycle_timers.h>

/* Robots a thread gets at least by default: fewer and the waiting costs
 * more than the sharing gains. */
#define ROBOTS_PER_THREAD 16
#define SPINS_BEFORE_SLEEP 500

static robot *robots;
static int n_robots;
static uint32_t nominal_hz;
static int profiling;

static int n_threads;
static pthread_t *workers;
static atomic_uint generation; /* a new window; the workers start it */
static atomic_int pending;     /* workers still in the window */
static atomic_int any_running; /* a robot has not stopped */
static atomic_int stopping;
static atomic_int workers_asleep; /* on generation */
static atomic_int main_asleep;    /* on pending */
static avr_cycle_count_t window_end;

int robot_finished(const robot *r) { return r->state == cpu_Done || r->state == cpu_Crashed; }

/* The simulated flash is erased at the bootloader: simavr 1.6 would run
 * through it. */
int robot_at_bootloader(const robot *r) { return r->avr->pc == KILOBOT_BOOTLOADER_ADDRESS; }

int lockstep_threads(void) { return n_threads; }

/* Cycle c of the nominal clock, in robot r's own cycles. */
static avr_cycle_count_t own_cycles(const robot *r, avr_cycle_count_t c) {
    return r->avr->frequency == nominal_hz ? c : c * r->avr->frequency / nominal_hz;
}

/* One instruction (or one sleep), its cycles charged to its function. */
static void step_profiled(robot *r) {
    avr_flashaddr_t pc = r->avr->pc;
    avr_cycle_count_t before = r->avr->cycle;
    /* simavr 1.6 runs a SLEEP and the sleep it starts in one avr_run. */
    int was_asleep = r->state == cpu_Sleeping || at_sleep_instruction(r->avr);
    r->state = avr_run(r->avr);
    profile_charge(pc, was_asleep, r->avr->cycle - before);
}

/* Fires again a cycle later until the next window re-registers it: simavr
 * 1.6 fires due timers before it computes how long a sleeping robot
 * sleeps, so a robot whose SLEEP ended right at the window's end would
 * otherwise find this timer spent and sleep on to its next tick, thousands
 * of cycles past the others (and hear their IR edges merged into one). */
static avr_cycle_count_t wake_up(struct avr_t *avr, avr_cycle_count_t when, void *param) {
    (void)avr;
    (void)param;
    return when + 1;
}

/* A robot asleep until a timer past this window's end cannot act in it:
 * it stays behind until the window its next timer falls in. An IR edge
 * for it is one of its timers (air/ir_channel.c, which wakes it up here),
 * so nothing reaches it late. This keeps a sleeping swarm cheap: a robot
 * sleeping between 1 ms ticks is run in one window of 125. */
static int dozing_through(robot *r, avr_cycle_count_t own_end) {
    if (r->state != cpu_Sleeping) return 0;
    if (r->wake_registered) {
        avr_cycle_timer_cancel(r->avr, wake_up, NULL);
        r->wake_registered = 0;
    }
    const avr_cycle_timer_slot_t *next = r->avr->cycle_timers.timer;
    if (next == NULL || next->when <= own_end) return 0;
    avr_cycle_count_t due =
        r->avr->frequency == nominal_hz ? next->when : next->when * nominal_hz / r->avr->frequency;
    r->doze_until = due > window_end ? due : window_end + 1;
    return 1;
}

/* Robot r up to the window's end; 1 when it has stopped. With several
 * robots a sleeping one is woken at the window's end, so it never skips
 * past what the others do. */
static int run_robot(robot *r) {
    if (r->doze_until > window_end) return 0;
    avr_cycle_count_t end = own_cycles(r, window_end);
    if (n_robots > 1 && !robot_finished(r) && r->avr->cycle < end) {
        if (dozing_through(r, end)) return 0;
        avr_cycle_timer_register(r->avr, end - r->avr->cycle, wake_up, NULL);
        r->wake_registered = 1;
    }
    while (!robot_finished(r) && r->avr->cycle < end) {
        if (!pc_in_flash(r->avr)) {
            r->state = cpu_Crashed; /* main.c's report says where the PC went */
            break;
        }
        power_down_before_step(r);
        register_store_check(r);
        if (profiling)
            step_profiled(r);
        else
            r->state = avr_run(r->avr);
        interrupt_watch_step(r);
        stack_watch_step(r);
        power_down_after_step(r);
        if (robot_at_bootloader(r)) r->state = cpu_Done; /* nothing there to run */
    }
    return robot_finished(r);
}

/* Thread t's share of the window; 1 when all its robots have stopped. */
static int run_share(int t) {
    int all_stopped = 1;
    for (int i = t; i < n_robots; i += n_threads) all_stopped &= run_robot(&robots[i]);
    return all_stopped;
}

static void futex_wait(void *word, int value) {
    syscall(SYS_futex, word, FUTEX_WAIT_PRIVATE, value, NULL, NULL, 0);
}

static void futex_wake(void *word) { syscall(SYS_futex, word, FUTEX_WAKE_PRIVATE, INT_MAX, NULL, NULL, 0); }

static void spin_once(void) {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

/* Until the main thread starts a new window (or stops). */
static unsigned wait_for_window(unsigned seen) {
    unsigned now;
    for (int spins = 0; (now = atomic_load(&generation)) == seen; spins++) {
        if (spins < SPINS_BEFORE_SLEEP) {
            spin_once();
            continue;
        }
        atomic_fetch_add(&workers_asleep, 1);
        if (atomic_load(&generation) == seen) futex_wait(&generation, (int)seen);
        atomic_fetch_sub(&workers_asleep, 1);
        spins = 0;
    }
    return now;
}

static void *worker(void *arg) {
    int t = (int)(intptr_t)arg;
    unsigned seen = 0;
    for (;;) {
        seen = wait_for_window(seen);
        if (atomic_load(&stopping)) return NULL;
        if (!run_share(t)) atomic_store_explicit(&any_running, 1, memory_order_relaxed);
        if (atomic_fetch_sub(&pending, 1) == 1 && atomic_load(&main_asleep)) futex_wake(&pending);
    }
}

/* Until every worker has finished the window. */
static void wait_for_workers(void) {
    int left;
    for (int spins = 0; (left = atomic_load(&pending)) != 0; spins++) {
        if (spins < SPINS_BEFORE_SLEEP) {
            spin_once();
            continue;
        }
        atomic_store(&main_asleep, 1);
        if ((left = atomic_load(&pending)) != 0) futex_wait(&pending, left);
        atomic_store(&main_asleep, 0);
        spins = 0;
    }
}

static void start_window(void) {
    atomic_fetch_add(&generation, 1);
    if (atomic_load(&workers_asleep) > 0) futex_wake(&generation);
}

static int threads_for(int requested, int n) {
    if (profiling || n < 2) return 1; /* the profile's tables are shared */
    if (requested > 0) return requested < n ? requested : n;
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    int by_swarm = n / ROBOTS_PER_THREAD;
    int t = cores < by_swarm ? (int)cores : by_swarm;
    return t > 1 ? t : 1;
}

void lockstep_begin(robot *all, int n, uint32_t hz, int threads, int profile) {
    robots = all;
    n_robots = n;
    nominal_hz = hz;
    profiling = profile;
    n_threads = threads_for(threads, n);
    if (n_threads == 1) return;
    workers = calloc((size_t)n_threads, sizeof *workers);
    for (int t = 1; workers != NULL && t < n_threads; t++) {
        if (pthread_create(&workers[t], NULL, worker, (void *)(intptr_t)t) != 0) {
            fprintf(stderr, "openswarm-sim: cannot start thread %d of %d; give --threads 1\n", t,
                    n_threads);
            exit(EXIT_CRASH);
        }
    }
}

int lockstep_window(avr_cycle_count_t end) {
    window_end = end;
    if (n_threads == 1) return run_share(0);
    atomic_store_explicit(&any_running, 0, memory_order_relaxed);
    atomic_store(&pending, n_threads - 1);
    start_window();
    int mine_stopped = run_share(0);
    wait_for_workers();
    return mine_stopped && !atomic_load_explicit(&any_running, memory_order_relaxed);
}

void lockstep_end(void) {
    if (n_threads == 1) return;
    atomic_store(&stopping, 1);
    start_window();
    for (int t = 1; t < n_threads; t++) pthread_join(workers[t], NULL);
    free(workers);
}
