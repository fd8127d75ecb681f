/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The robots in lockstep windows (lockstep.h).
 *
 * With several threads (window_workers.c), thread t runs robots t, t + T,
 * t + 2T, ... (robots next to each other by index are often alike, so
 * interleaving spreads the busy ones). */
#include "lockstep.h"

#include <sim_cycle_timers.h>

#include "board/invalid_opcode.h"
#include "loop_skip.h"
#include "window_workers.h"

/* Robots a thread gets at least by default: fewer and the waiting costs
 * more than the sharing gains. */
#define ROBOTS_PER_THREAD 16

static robot *robots;
static int n_robots;
static uint32_t nominal_hz;
static int profiling;

static int n_threads;
static avr_cycle_count_t window_end;
static int skipping; /* loop_skip.h: on */

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

static void cancel_wake_up(robot *r) {
    if (r->wake_registered) {
        avr_cycle_timer_cancel(r->avr, wake_up, NULL);
        r->wake_registered = 0;
    }
}

/* Robot r is left alone until the window its timer at own cycle `when`
 * falls in (UINT64_MAX: none), and at least until the next window. */
static void doze_until_timer(robot *r, avr_cycle_count_t when) {
    avr_cycle_count_t due = when == UINT64_MAX ? UINT64_MAX
                            : r->avr->frequency == nominal_hz ? when
                                                                : when * nominal_hz / r->avr->frequency;
    r->doze_until = due > window_end ? due : window_end + 1;
}

/* A robot asleep until a timer past this window's end cannot act in it:
 * it stays behind until the window its next timer falls in. An IR edge
 * for it is one of its timers (air/ir_channel.c, which wakes it up here),
 * so nothing reaches it late. This keeps a sleeping swarm cheap: a robot
 * sleeping between 1 ms ticks is run in one window of 125. */
static int dozing_through(robot *r, avr_cycle_count_t own_end) {
    if (r->state != cpu_Sleeping) return 0;
    cancel_wake_up(r); /* before reading the next timer: it may be that one */
    const avr_cycle_timer_slot_t *next = r->avr->cycle_timers.timer;
    if (next == NULL || next->when <= own_end) return 0;
    doze_until_timer(r, next->when);
    return 1;
}

/* The window's end for a parked robot: it need not be run before the
 * window its next timer falls in (the others reach it by a timer, or
 * through lockstep_settle). */
static void doze_parked(robot *r, avr_cycle_count_t next_timer) {
    cancel_wake_up(r);
    doze_until_timer(r, next_timer);
}

/* Robot r at the head of a loop that repeats (loop_skip.h): the repeats
 * that end before its next timer and by end, skipped. 1 when it stays
 * parked there, short of end by less than a repeat (the next one ends
 * after end and before the timer); 0 when it runs on into the repeat in
 * which the timer fires, instruction by instruction. */
static int skip_ahead(robot *r, avr_cycle_count_t end) {
    loop_skip *s = r->skip;
    avr_cycle_count_t head = r->avr->cycle, period = s->period, next = loop_skip_next_timer(r);
    s->parked = 0;
    if (next <= head + period) return 0;
    uint64_t before_timer = (next - head - 1) / period, by_end = end > head ? (end - head) / period : 0;
    loop_skip_jump(r, before_timer < by_end ? before_timer : by_end);
    if (r->avr->cycle + period >= next) return 0;
    s->parked = 1;
    doze_parked(r, next);
    return 1;
}

static void unpark(robot *r) {
    r->skip->parked = 0;
    r->doze_until = 0;
}

/* Robot r up to end (or until it stops), instruction by instruction but
 * for the repeats of a loop it skips. */
static void run_until(robot *r, avr_cycle_count_t end, int may_park) {
    while (!robot_finished(r) && r->avr->cycle < end) {
        if (!pc_in_flash(r->avr)) {
            r->state = cpu_Crashed; /* main.c's report says where the PC went */
            break;
        }
        if (invalid_opcode_ahead(r->avr)) {
            invalid_opcode_stop(r->avr, r->avr->pc); /* before simavr reads past the flash */
            break;
        }
        if (r->skip_anchor == r->avr->pc && loop_skip_repeats(r) != 0) {
            if (skip_ahead(r, end)) {
                if (may_park) break;
                unpark(r);
            }
            if (r->avr->cycle >= end) break;
        }
        power_down_before_step(r);
        register_store_check(r);
        if (profiling)
            step_profiled(r);
        else
            r->state = avr_run(r->avr);
        interrupt_watch_step(r);
        stack_watch_step(r);
        handler_watch_step(r);
        power_down_after_step(r);
        if (robot_at_bootloader(r)) r->state = cpu_Done; /* nothing there to run */
    }
}

/* Robot r up to the window's end; 1 when it has stopped. With several
 * robots a sleeping one is woken at the window's end, so it never skips
 * past what the others do. */
static int run_robot(robot *r) {
    if (r->doze_until > window_end) return 0;
    avr_cycle_count_t end = own_cycles(r, window_end);
    if (n_robots > 1 && !robot_finished(r) && r->avr->cycle < end && dozing_through(r, end)) return 0;
    if (r->skip != NULL) {
        loop_skip_window_start(r);
        if (r->skip->parked && skip_ahead(r, end)) return 0;
    }
    if (n_robots > 1 && !robot_finished(r) && r->avr->cycle < end) {
        avr_cycle_timer_register(r->avr, end - r->avr->cycle, wake_up, NULL);
        r->wake_registered = 1;
    }
    run_until(r, end, 1);
    return robot_finished(r);
}

/* Thread t's share of the window; 1 when all its robots have stopped. */
static int run_share(int t) {
    int all_stopped = 1;
    for (int i = t; i < n_robots; i += n_threads) all_stopped &= run_robot(&robots[i]);
    return all_stopped;
}

/* A parked robot as if it had run to the last window's end (lockstep.h). */
void lockstep_settle(robot *r) {
    if (r->skip == NULL || !r->skip->parked) return;
    unpark(r);
    avr_cycle_count_t end = own_cycles(r, window_end);
    if (skip_ahead(r, end)) unpark(r);
    run_until(r, end, 0);
}

void lockstep_settle_all(void) {
    for (int i = 0; i < n_robots; i++) lockstep_settle(&robots[i]);
}

uint64_t lockstep_skipped_cycles(void) {
    uint64_t sum = 0;
    for (int i = 0; i < n_robots; i++)
        if (robots[i].skip != NULL) sum += robots[i].skip->skipped;
    return sum;
}

/* After everything that registers I/O callbacks (loop_skip_attach). */
static int skip_loops(void) {
    for (int i = 0; i < n_robots; i++) {
        robots[i].skip_anchor = LOOP_SKIP_NO_ANCHOR;
        if (skipping && loop_skip_attach(&robots[i], wake_up) != 0) {
            fprintf(stderr, "openswarm-sim: out of memory for the loop skip of %d robots: run with "
                            "--no-loop-skip, or fewer robots\n", n_robots);
            return -1;
        }
    }
    return 0;
}

int lockstep_begin(robot *all, int n, uint32_t hz, int threads, int profile, int skip) {
    robots = all;
    n_robots = n;
    nominal_hz = hz;
    profiling = profile;
    skipping = skip;
    if (skip_loops() != 0) return -1;
    /* The profile's tables are shared: one thread. */
    n_threads = profiling ? 1 : window_workers_count(threads, n, ROBOTS_PER_THREAD);
    window_workers_begin(n_threads, run_share);
    return 0;
}

int lockstep_window(avr_cycle_count_t end) {
    window_end = end;
    return window_workers_run();
}

void lockstep_end(void) {
    window_workers_end();
    for (int i = 0; i < n_robots; i++) loop_skip_detach(&robots[i]);
}
