/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Loops that change nothing, fast-forwarded (on unless --no-loop-skip).
 *
 * A classic kilolib loop() with nothing to do comes back to the same
 * instruction with the same registers, flags, stack and RAM every time
 * round, and until something outside the CPU acts - a cycle timer (the
 * tick, a peripheral's event, an IR edge) or an I/O register simavr does
 * something at - every further round is an exact repeat. At one
 * instruction, the anchor, the robot's state is kept and compared with the
 * state at its next visit: the same, with no such I/O register read or
 * written between (each one is wrapped to tell), no timer fired, added or
 * moved, no interrupt pending, and the loop repeats every (cycles between
 * the visits). lockstep.c then adds whole repeats to the cycle count, never
 * past the next timer, whose event therefore comes at the very instruction
 * it would have: the run is the same, cycle for cycle, only sooner. */
#ifndef OPENSWARM_LOOP_SKIP_H
#define OPENSWARM_LOOP_SKIP_H

#include <sim_cycle_timers.h>

#include "sim.h"

#define LOOP_SKIP_NO_ANCHOR UINT32_MAX
/* Longer repeats are not looked for: a repeat's masked stretch must stay
 * shorter than --mask-limit's smallest (1 ms), and keeping the state costs
 * as much as a few hundred instructions, so long loops gain little. */
#define LOOP_SKIP_MAX_PERIOD 4096
#define LOOP_SKIP_MAX_TIMERS 16

/* An I/O register's simavr callbacks, which its wrappers call. */
typedef struct io_tap {
    avr_io_read_t read;
    void *read_param;
    avr_io_write_t write;
    void *write_param;
} io_tap;

/* A cycle timer as it stood (what the loop must leave as it found). */
typedef struct timer_seen {
    avr_cycle_timer_t fn;
    void *param;
    avr_cycle_count_t when;
} timer_seen;

typedef struct loop_skip {
    avr_cycle_timer_t window_timer; /* the lockstep's own, which changes nothing: left out */
    io_tap taps[MAX_IOs];
    int touched; /* an I/O register with callbacks read or written since the anchor's visit */
    /* The state at the anchor's last visit. */
    avr_cycle_count_t since, quiet_until; /* its cycle; no timer due before quiet_until */
    uint8_t sreg[8];
    int8_t interrupt_state;
    uint8_t running_ptr;
    timer_seen timers[LOOP_SKIP_MAX_TIMERS];
    int n_timers;
    uint8_t *data; /* registers, I/O and RAM: data[0..ramend] */
    size_t data_size;
    /* Visits in a row that found no repeat, and the wait before anchoring again. */
    int misses;
    avr_cycle_count_t backoff, rearm_at;
    /* The repeat found; parked: the robot waits at the loop's head, at most
     * a repeat short of the window's end, until a later window. */
    avr_cycle_count_t period;
    int parked;
    uint64_t skipped; /* cycles fast-forwarded */
} loop_skip;

/* Robot r's loops watched: every I/O register simavr acts at is wrapped,
 * so call it after everything has registered its callbacks (a read
 * callback registered later makes simavr 1.6 abort). window_timer: a
 * timer the lockstep sets and moves every window, which is left out. -1
 * when out of memory. */
int loop_skip_attach(robot *r, avr_cycle_timer_t window_timer);
void loop_skip_detach(robot *r);
/* At the start of each window the robot runs in. */
void loop_skip_window_start(robot *r);
/* At the anchor (r->skip_anchor == PC): the cycles after which the loop
 * repeats, 0 if it does not (or not yet). */
avr_cycle_count_t loop_skip_repeats(robot *r);
/* The next timer's cycle but the window's own; UINT64_MAX: none. */
avr_cycle_count_t loop_skip_next_timer(const robot *r);
/* periods whole repeats of the loop found, in no time. */
void loop_skip_jump(robot *r, uint64_t periods);
/* After a reset: nothing kept holds. */
void loop_skip_forget(robot *r);

#endif
