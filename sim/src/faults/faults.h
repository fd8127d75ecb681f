/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Fault injection (--faults SPEC): robots reset or brown out, IR pulses
 * are lost or appear in frames, frames are cut short, a robot's EEPROM
 * calibration is blank, a robot's clock runs fast or slow. Every fault drawn is logged, one line each, and
 * counted for the run's summary.
 *
 * fault_spec.c reads the spec; fault_plan.c fires the robots' resets and brown-outs
 * between windows, in either mode (a fault_robots says what they do to a
 * robot); air/ir_faults.c applies the IR faults as the exact mode's
 * channel hands edges over; board/power_cycle.c is what a reset and a
 * power cut do to one robot simulated cycle by cycle, native/native_faults.c
 * to a native one; fault_log.c writes and counts. */
#ifndef OPENSWARM_FAULTS_H
#define OPENSWARM_FAULTS_H

#include "sim.h"

#define MAX_FAULTS_AT 64 /* faults given a robot and a time, e.g. reset:3@5 */

enum fault_kind {
    FAULT_RESET,
    FAULT_BROWNOUT,
    FAULT_PULSE_LOST,
    FAULT_PULSE_ADDED,
    FAULT_FRAME_CUT,
    FAULT_BLANK_CALIBRATION,
    FAULT_CLOCK_DRIFT,
    FAULT_KINDS
};

/* A fault at a given time for a given robot. */
typedef struct fault_at {
    int kind; /* FAULT_RESET, FAULT_BROWNOUT; at 0 s FAULT_BLANK_CALIBRATION, FAULT_CLOCK_DRIFT */
    int robot;
    double seconds;
    double ppm; /* FAULT_CLOCK_DRIFT: how fast the clock runs (negative: slow) */
} fault_at;

typedef struct fault_spec {
    int enabled;               /* --faults was given */
    double resets_per_hour;    /* each robot's, on average (Poisson) */
    double brownouts_per_hour;
    double brownout_ms;        /* how long the power is off */
    double flip_pct;           /* each slot of a frame, at each receiver */
    double cut_pct;            /* each frame, at each receiver */
    int blank;                 /* robots drawn at random with blank calibration */
    double drift_pct;          /* each robot's clock drawn between -this and +this */
    uint64_t seed;
    fault_at at[MAX_FAULTS_AT];
    int n_at;
    /* Each item as given, to name it: once only (a second is refused). */
    char at_text[MAX_FAULTS_AT][40];
    unsigned keys_given;       /* bit k: the k-th key=value item was given */
    char key_text[8][40];
    const char *log_path;      /* --fault-log FILE; NULL: stderr */
} fault_spec;

/* fault_spec.c */
/* One --faults argument, added to spec; -1 after a message. */
int faults_parse(const char *text, fault_spec *spec);
/* The checks that need the robots' count and the run's length (a fault
 * at a time after it would never be injected); -1 after a message. */
int faults_check(const fault_spec *spec, int robots, double seconds);
/* fault_plan.c */
/* Draw the faults of n robots; open the log. -1 after a message. */
int faults_start(const fault_spec *spec, int n);
/* What a reset and a power cut do to the robots of a mode; cycles are of
 * the nominal clock. */
typedef struct fault_robots {
    int (*can_fault)(int index);                     /* running and powered */
    avr_cycle_count_t (*off_until)(int index);       /* when its power returns; 0: powered */
    void (*reset)(int index, avr_cycle_count_t now);
    void (*power_off)(int index, avr_cycle_count_t now, avr_cycle_count_t on);
    void (*power_on)(int index, avr_cycle_count_t on);
} fault_robots;

/* The robots are loaded: their resets and brown-outs can fire. */
void faults_attach(const fault_robots *robots, uint32_t nominal_hz);
/* Robot index has blank calibration (its EEPROM's 0xFF). */
int faults_blank_calibration(int index);
/* Robot index's clock rate, hz with its drift (0 if none), which is logged. */
uint32_t faults_clock_rate(int index, uint32_t hz);
/* Between two windows: the resets, brown-outs and power returns due by
 * cycle end of the nominal clock. */
void faults_after_window(avr_cycle_count_t end);
/* The run's counts on stderr; the log closed: -1 after a message if it
 * could not be written. */
int faults_finish(void);

/* fault_log.c: one line per fault, "fault t=SECONDS robot=INDEX kind=KIND ...". */
int fault_log_open(const char *path);
void fault_log(int kind, double seconds, int index, const char *detail_format, ...)
    __attribute__((format(printf, 4, 5)));
unsigned long fault_log_count(int kind);
const char *fault_kind_name(int kind);
/* -1 after a message if the log could not be written. */
int fault_log_close(void);

/* board/power_cycle.c: what a reset and a power cut do to the exact
 * mode's robots (a power cut lasts until r->off_until, and ends at the end
 * of the window that reaches it). */
const fault_robots *power_cycle_robots(robot *robots, uint32_t nominal_hz);

#endif
