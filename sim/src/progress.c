/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The status line and the summary (progress.h). The line is rewritten at
 * most five times a second and only after the first two seconds of wall
 * time, so short runs print nothing but their summary. */
#include "progress.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

#define FIRST_AFTER_S 2.0
#define EVERY_S 0.2

static int shown, robot_count;
static uint32_t hz;
static double started, last_shown;
static avr_cycle_count_t last_cycle;

static double wall_now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + t.tv_nsec / 1e9;
}

void progress_start(int show, int robots, uint32_t nominal_hz) {
    shown = show < 0 ? isatty(2) : show;
    robot_count = robots;
    hz = nominal_hz;
    started = last_shown = wall_now();
}

static double factor(double simulated, double wall) { return wall > 0 ? simulated / wall : 0.0; }

void progress_update(avr_cycle_count_t cycle) {
    last_cycle = cycle;
    if (!shown || (cycle & 0xFFFF) >= 64) return; /* look at the clock now and then only */
    double now = wall_now();
    if (now - started < FIRST_AFTER_S || now - last_shown < EVERY_S) return;
    last_shown = now;
    double simulated = (double)cycle / hz;
    fprintf(stderr, "\ropenswarm-sim: %9.1f s simulated, %6.1fx real time, %d robot%s ", simulated,
            factor(simulated, now - started), robot_count, robot_count > 1 ? "s" : "");
    fflush(stderr);
}

void progress_end(void) {
    if (shown && wall_now() - started >= FIRST_AFTER_S) fprintf(stderr, "\r\033[K");
}

void progress_summary(double seconds, int robots, double skipped_share) {
    double wall = wall_now() - started;
    fprintf(stderr, "openswarm-sim: ran %.3f s of simulated time (%d robot%s) in %.1f s, %.1fx real "
                    "time", seconds, robots, robots > 1 ? "s" : "", wall, factor(seconds, wall));
    if (skipped_share > 0)
        fprintf(stderr, "; %.0f%% of the cycles fast-forwarded over loops that repeat", 100 * skipped_share);
    fprintf(stderr, "\n");
}
