/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A run's progress: one status line on stderr, rewritten in place
 * (simulated time, real-time factor, robots), and the summary line. */
#ifndef OPENSWARM_PROGRESS_H
#define OPENSWARM_PROGRESS_H

#include <stdint.h>

#include <sim_avr.h>

/* show: 1 always, 0 never, -1 when stderr is a terminal. */
void progress_start(int show, int robots, uint32_t nominal_hz);
void progress_update(avr_cycle_count_t cycle);
void progress_end(void);
/* "ran 10.000 s of simulated time (3 robots) in 2.1 s, 4.8x real time",
 * and the share of the robots' cycles fast-forwarded over loops
 * (loop_skip.h) when some were (skipped_share > 0). */
void progress_summary(double seconds, int robots, double skipped_share);

#endif
