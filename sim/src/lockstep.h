/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The robots advance together, window by window, on one thread or several.
 * Within a window every robot runs on its own (what one sends reaches the
 * others only in the next window, air/ir_channel.c), so the robots can be
 * shared among threads and the run is the same on any number of them. */
#ifndef OPENSWARM_LOCKSTEP_H
#define OPENSWARM_LOCKSTEP_H

#include "sim.h"

/* threads: 0 picks by the machine and the swarm; profiling runs on one.
 * skip_loops: loops that repeat exactly are fast-forwarded (loop_skip.h);
 * call it after everything that registers I/O callbacks. -1 after a
 * message when out of memory. */
int lockstep_begin(robot *robots, int n, uint32_t nominal_hz, int threads, int profiling, int skip_loops);
/* Run every robot up to the nominal clock's cycle end (or until it stops);
 * 1 when all have stopped. */
int lockstep_window(avr_cycle_count_t end);
void lockstep_end(void);
/* A robot fast-forwarding a loop may wait at the loop's head, up to a
 * repeat short of the last window's end, until a later window (parked):
 * nothing can tell until something acts on it from outside. Whatever
 * does so between windows (an IR edge handed over, a reset, --counters)
 * settles it first: it runs on to where it would have stopped. */
void lockstep_settle(robot *r);
void lockstep_settle_all(void);
/* The cycles all robots fast-forwarded so far. */
uint64_t lockstep_skipped_cycles(void);
int lockstep_threads(void);

int robot_finished(const robot *r);
/* A robot that jumped to its bootloader (a BOOT message asks for it). */
int robot_at_bootloader(const robot *r);

#endif
