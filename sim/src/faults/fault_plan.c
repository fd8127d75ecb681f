/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* --faults SPEC: what to inject, and when (faults.h); fault_spec.c reads
 * the spec.
 *
 * Random faults come from the spec's seed alone: each robot draws its
 * resets and brown-outs from its own sequence (a Poisson process at the
 * rate given: exponential gaps), so the same spec gives the same faults at
 * the same times on any number of threads, and adding robots leaves the
 * first ones' faults where they were. Resets and brown-outs happen between
 * two windows, when no robot runs: the exact mode's lockstep windows (8 us
 * apart) or the native mode's (1 ms), the same plan in both. A robot that has
 * stopped (its firmware exited or crashed) is not revived: its faults are
 * skipped. */
#include <math.h>
#include <stdlib.h>

#include "air/ir_faults.h"
#include "faults/faults.h"
#include "world/world_random.h"

typedef struct robot_faults {
    uint64_t rng;
    double next_reset_s, next_brownout_s; /* INFINITY: none */
    int blank;
    double drift_ppm;
} robot_faults;

static fault_spec spec;
static robot_faults *plans;
static const fault_robots *robots;
static int n_robots;
static uint32_t nominal_hz;
static avr_cycle_count_t next_due; /* no reset, brown-out or power return before this */
static int next_at;                /* spec.at[], sorted by time: the next to fire */

static double exponential_s(uint64_t *rng, double per_hour) {
    if (per_hour <= 0) return INFINITY;
    return -log(1.0 - world_random_uniform(rng)) * 3600.0 / per_hour;
}

static int by_time(const void *a, const void *b) {
    const fault_at *x = a, *y = b;
    return (x->seconds > y->seconds) - (x->seconds < y->seconds);
}

/* blank robots at random: the first draws of a shuffle of the indices. */
static void draw_blank(int n) {
    int *order = malloc((size_t)n * sizeof *order);
    if (order == NULL) exit(EXIT_CRASH);
    for (int i = 0; i < n; i++) order[i] = i;
    uint64_t rng = spec.seed ^ 0xB1A4C0FFEEull;
    for (int k = 0; k < spec.blank; k++) {
        int j = k + (int)(world_random_uniform(&rng) * (n - k));
        int t = order[k];
        order[k] = order[j];
        order[j] = t;
        plans[order[k]].blank = 1;
    }
    free(order);
}

/* drift=PCT: each robot's clock error evenly between -PCT and +PCT, from a
 * sequence of its own (the resets' and brown-outs' times stay as they were
 * without it). */
static void draw_drifts(int n) {
    if (spec.drift_pct <= 0) return;
    for (int i = 0; i < n; i++) {
        uint64_t rng = spec.seed * 0x9E3779B97F4A7C15ull ^ ((uint64_t)i << 32 | 0xD81F7u);
        world_random_next(&rng);
        plans[i].drift_ppm = (2.0 * world_random_uniform(&rng) - 1.0) * spec.drift_pct * 1e4;
    }
}

int faults_start(const fault_spec *s, int n) {
    spec = *s;
    n_robots = n;
    plans = calloc((size_t)n, sizeof *plans);
    if (plans == NULL || fault_log_open(spec.log_path) != 0) return -1;
    for (int i = 0; i < n; i++) {
        robot_faults *p = &plans[i];
        p->rng = spec.seed * 0x9E3779B97F4A7C15ull ^ ((uint64_t)i << 32 | 0x5EEDu);
        world_random_next(&p->rng);
        p->next_reset_s = exponential_s(&p->rng, spec.resets_per_hour);
        p->next_brownout_s = exponential_s(&p->rng, spec.brownouts_per_hour);
    }
    draw_blank(n);
    draw_drifts(n);
    for (int i = 0; i < spec.n_at; i++) {
        if (spec.at[i].kind == FAULT_BLANK_CALIBRATION) plans[spec.at[i].robot].blank = 1;
        if (spec.at[i].kind == FAULT_CLOCK_DRIFT) plans[spec.at[i].robot].drift_ppm = spec.at[i].ppm;
    }
    qsort(spec.at, (size_t)spec.n_at, sizeof spec.at[0], by_time);
    ir_faults_configure(spec.flip_pct, spec.cut_pct, spec.seed);
    return 0;
}

int faults_blank_calibration(int index) {
    if (plans == NULL || !plans[index].blank) return 0;
    fault_log(FAULT_BLANK_CALIBRATION, 0.0, index, NULL);
    return 1;
}

uint32_t faults_clock_rate(int index, uint32_t hz) {
    if (plans == NULL || plans[index].drift_ppm == 0) return hz;
    uint32_t drifted = (uint32_t)lround(hz * (1.0 + plans[index].drift_ppm * 1e-6));
    fault_log(FAULT_CLOCK_DRIFT, 0.0, index, "ppm=%+.0f hz=%u", plans[index].drift_ppm, (unsigned)drifted);
    return drifted;
}

static avr_cycle_count_t cycle_of(double seconds) {
    double c = seconds * nominal_hz;
    return c >= 1e18 ? (avr_cycle_count_t)1e18 : (avr_cycle_count_t)c;
}

/* The earliest cycle anything is due at. */
static void find_next_due(void) {
    double t = INFINITY;
    avr_cycle_count_t due = (avr_cycle_count_t)1e18;
    for (int i = 0; i < n_robots; i++) {
        t = fmin(t, fmin(plans[i].next_reset_s, plans[i].next_brownout_s));
        avr_cycle_count_t on = robots->off_until(i);
        if (on != 0 && on < due) due = on;
    }
    for (int k = next_at; k < spec.n_at; k++)
        if (spec.at[k].kind == FAULT_RESET || spec.at[k].kind == FAULT_BROWNOUT) {
            t = fmin(t, spec.at[k].seconds);
            break;
        }
    avr_cycle_count_t c = cycle_of(t);
    next_due = c < due ? c : due;
}

void faults_attach(const fault_robots *all, uint32_t hz) {
    if (plans == NULL) return;
    robots = all;
    nominal_hz = hz;
    find_next_due();
}

/* Robot i's fault of this kind, at the nominal time now; skipped by a
 * robot that has stopped or is without power. */
static void inject(int kind, int i, avr_cycle_count_t now) {
    if (!robots->can_fault(i)) return;
    double t = (double)now / nominal_hz;
    if (kind == FAULT_RESET) {
        fault_log(FAULT_RESET, t, i, NULL);
        robots->reset(i, now);
    } else {
        fault_log(FAULT_BROWNOUT, t, i, "off_ms=%g", spec.brownout_ms);
        robots->power_off(i, now, now + cycle_of(spec.brownout_ms / 1000.0));
    }
}

void faults_after_window(avr_cycle_count_t end) {
    if (plans == NULL || end < next_due) return;
    double t = (double)end / nominal_hz;
    for (int i = 0; i < n_robots; i++) {
        robot_faults *p = &plans[i];
        avr_cycle_count_t on = robots->off_until(i);
        if (on != 0 && on <= end) robots->power_on(i, end);
        for (; p->next_reset_s <= t; p->next_reset_s += exponential_s(&p->rng, spec.resets_per_hour))
            inject(FAULT_RESET, i, end);
        for (; p->next_brownout_s <= t;
             p->next_brownout_s += exponential_s(&p->rng, spec.brownouts_per_hour))
            inject(FAULT_BROWNOUT, i, end);
    }
    for (; next_at < spec.n_at && spec.at[next_at].seconds <= t; next_at++)
        if (spec.at[next_at].kind == FAULT_RESET || spec.at[next_at].kind == FAULT_BROWNOUT)
            inject(spec.at[next_at].kind, spec.at[next_at].robot, end);
    find_next_due();
}

int faults_finish(void) {
    if (plans == NULL) return 0;
    fprintf(stderr, "openswarm-sim: faults injected:");
    for (int k = 0; k < FAULT_KINDS; k++)
        fprintf(stderr, "%s %lu %s", k ? "," : "", fault_log_count(k), fault_kind_name(k));
    if (spec.log_path != NULL) fprintf(stderr, " (one a line in %s)", spec.log_path);
    fprintf(stderr, "\n");
    return fault_log_close();
}
