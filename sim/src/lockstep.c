/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The robots in lockstep windows (lockstep.h).
 *
 * With several threads (window_workers.c), thread t runs robots t, t + T,
 * t + 2T, ... (robots next to each other by index are often alike, so
 * interleaving spreads the busy ones). */
#include "lockstep.h"

#include <sim_cycle_timers.h>

#include "board/invalid_opcode.h"
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
        if (invalid_opcode_ahead(r->avr)) {
            invalid_opcode_stop(r->avr, r->avr->pc); /* before simavr reads past the flash */
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
        handler_watch_step(r);
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

void lockstep_begin(robot *all, int n, uint32_t hz, int threads, int profile) {
    robots = all;
    n_robots = n;
    nominal_hz = hz;
    profiling = profile;
    /* The profile's tables are shared: one thread. */
    n_threads = profiling ? 1 : window_workers_count(threads, n, ROBOTS_PER_THREAD);
    window_workers_begin(n_threads, run_share);
}

int lockstep_window(avr_cycle_count_t end) {
    window_end = end;
    return window_workers_run();
}

void lockstep_end(void) { window_workers_end(); }
