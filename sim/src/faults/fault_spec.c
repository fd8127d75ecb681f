/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* --faults SPEC: reading the spec into a fault_spec, and the checks that
 * need the run's robots and length (faults.h). What is drawn from it, and
 * when it fires, is fault_plan.c's. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "faults/faults.h"

#define MAX_PER_HOUR 36000.0  /* ten a second: more is surely a typo */
#define MAX_FLIP_PCT 10.0
#define MAX_BROWNOUT_MS 60000.0
#define DEFAULT_BROWNOUT_MS 50.0
#define MAX_DRIFT_PCT 10.0

static void spec_usage(const char *text, const char *what) {
    fprintf(stderr,
            "openswarm-sim: --faults '%s': %s; expected a comma-separated list of reset=PER_HOUR "
            "(0..36000), brownout=PER_HOUR (0..36000), brownout-ms=MS (0.01..60000), flip=PCT "
            "(0..10), cut=PCT (0..100), blank=ROBOTS, drift=PCT (0..10), seed=N, "
            "reset:ROBOT@SECONDS, brownout:ROBOT@SECONDS, blank:ROBOT, drift:ROBOT=PCT "
            "(-10..10) or drift:ROBOT=PPMppm; e.g. --faults "
            "reset=2,flip=0.1,cut=1,seed=7 (docs/world.md, \"Fault injection\")\n",
            text, what);
}

/* A finite number in [lo, hi] from the whole of text. */
static int number_in(const char *text, double lo, double hi, double *out) {
    char *end;
    errno = 0;
    double v = strtod(text, &end);
    if (end == text || *end != '\0' || errno != 0 || !(v >= lo && v <= hi)) return -1;
    *out = v;
    return 0;
}

static int robot_and_time(const char *text, int kind, fault_spec *s) {
    if (s->n_at == MAX_FAULTS_AT) return -1;
    fault_at *f = &s->at[s->n_at];
    char *end;
    errno = 0;
    long index = strtol(text, &end, 10);
    if (end == text || errno != 0 || index < 0 || index >= MAX_ROBOTS) return -1;
    double seconds = 0;
    if (kind == FAULT_BLANK_CALIBRATION) {
        if (*end != '\0') return -1;
    } else if (*end != '@' || number_in(end + 1, 0, 1e6, &seconds) != 0) {
        return -1;
    }
    *f = (fault_at){kind, (int)index, seconds, 0.0};
    s->n_at++;
    return 0;
}

/* drift:ROBOT=PCT or drift:ROBOT=PPMppm: that robot's clock, from the start. */
static int robot_and_drift(const char *text, fault_spec *s) {
    if (s->n_at == MAX_FAULTS_AT) return -1;
    char *end;
    errno = 0;
    long index = strtol(text, &end, 10);
    if (end == text || errno != 0 || index < 0 || index >= MAX_ROBOTS || *end != '=') return -1;
    const char *value = end + 1;
    size_t n = strlen(value);
    int ppm = n > 3 && strcmp(value + n - 3, "ppm") == 0;
    char number[32];
    size_t digits = n - (ppm ? 3 : 0);
    if (digits >= sizeof number) return -1;
    memcpy(number, value, digits);
    number[digits] = '\0';
    double v, limit = ppm ? MAX_DRIFT_PCT * 1e4 : MAX_DRIFT_PCT;
    if (number_in(number, -limit, limit, &v) != 0) return -1;
    s->at[s->n_at++] = (fault_at){FAULT_CLOCK_DRIFT, (int)index, 0.0, ppm ? v : v * 1e4};
    return 0;
}

static const char *item_name(int kind);
static int parse_value(const char *item, size_t n, const char *value, fault_spec *s);

/* The fault at[n_at - 1], just added as item: -2 with why if the same
 * fault was given before (the same robot's drift or blank; the same
 * robot's reset or brown-out at the same time), else 0 with its text kept. */
static int new_at(const char *item, fault_spec *s, char *why, size_t room) {
    const fault_at *f = &s->at[s->n_at - 1];
    for (int k = 0; k < s->n_at - 1; k++) {
        const fault_at *e = &s->at[k];
        if (e->kind != f->kind || e->robot != f->robot) continue;
        if ((f->kind == FAULT_RESET || f->kind == FAULT_BROWNOUT) && e->seconds != f->seconds) continue;
        char name[48];
        if (f->kind == FAULT_RESET || f->kind == FAULT_BROWNOUT)
            snprintf(name, sizeof name, "%s:%d@%g", item_name(f->kind), f->robot, f->seconds);
        else
            snprintf(name, sizeof name, "%s:%d", item_name(f->kind), f->robot);
        snprintf(why, room, "%s is given twice (%s and %.39s): keep one", name, s->at_text[k], item);
        s->n_at--;
        return -2;
    }
    snprintf(s->at_text[s->n_at - 1], sizeof s->at_text[0], "%s", item);
    return 0;
}

/* One item of the list: "key=value" or "kind:robot[@seconds]" or
 * "drift:robot=value". -1: unknown or out of range; -2: why says. */
static int parse_item(const char *item, fault_spec *s, char *why, size_t room) {
    const char *eq = strchr(item, '='), *colon = strchr(item, ':');
    if (colon != NULL && (eq == NULL || colon < eq)) {
        size_t n = (size_t)(colon - item);
        int rc = -1;
        if (n == 5 && strncmp(item, "reset", n) == 0) rc = robot_and_time(colon + 1, FAULT_RESET, s);
        else if (n == 8 && strncmp(item, "brownout", n) == 0) rc = robot_and_time(colon + 1, FAULT_BROWNOUT, s);
        else if (n == 5 && strncmp(item, "blank", n) == 0) rc = robot_and_time(colon + 1, FAULT_BLANK_CALIBRATION, s);
        else if (n == 5 && strncmp(item, "drift", n) == 0) rc = robot_and_drift(colon + 1, s);
        return rc == 0 ? new_at(item, s, why, room) : rc;
    }
    if (eq == NULL) return -1;
    size_t n = (size_t)(eq - item);
    static const char *const keys[] = {"reset", "brownout", "brownout-ms", "flip", "cut", "drift", "blank", "seed"};
    for (int k = 0; k < (int)(sizeof keys / sizeof keys[0]); k++) {
        if (strlen(keys[k]) != n || strncmp(item, keys[k], n) != 0) continue;
        if (s->keys_given & (1u << k)) {
            snprintf(why, room, "%s= is given twice (%s and %.39s): keep one", keys[k], s->key_text[k], item);
            return -2;
        }
        int rc = parse_value(item, n, eq + 1, s);
        if (rc == 0) {
            s->keys_given |= 1u << k;
            snprintf(s->key_text[k], sizeof s->key_text[0], "%s", item);
        }
        return rc;
    }
    return -1;
}

/* key=value's value, for the key item's first n bytes name. */
static int parse_value(const char *item, size_t n, const char *value, fault_spec *s) {
    double v;
#define KEY(name) (n == sizeof name - 1 && strncmp(item, name, n) == 0)
    if (KEY("reset")) return number_in(value, 0, MAX_PER_HOUR, &s->resets_per_hour);
    if (KEY("brownout")) return number_in(value, 0, MAX_PER_HOUR, &s->brownouts_per_hour);
    if (KEY("brownout-ms")) return number_in(value, 0.01, MAX_BROWNOUT_MS, &s->brownout_ms);
    if (KEY("flip")) return number_in(value, 0, MAX_FLIP_PCT, &s->flip_pct);
    if (KEY("cut")) return number_in(value, 0, 100, &s->cut_pct);
    if (KEY("drift")) return number_in(value, 0, MAX_DRIFT_PCT, &s->drift_pct);
    if (KEY("blank")) {
        if (number_in(value, 0, MAX_ROBOTS, &v) != 0 || v != floor(v)) return -1;
        s->blank = (int)v;
        return 0;
    }
    if (KEY("seed")) {
        char *end;
        errno = 0;
        unsigned long long seed = strtoull(value, &end, 0);
        if (end == value || *end != '\0' || errno != 0 || value[0] == '-') return -1;
        s->seed = seed;
        return 0;
    }
#undef KEY
    return -1;
}

int faults_parse(const char *text, fault_spec *s) {
    if (text[0] == '\0') {
        spec_usage(text, "an empty list");
        return -1;
    }
    if (!s->enabled) {
        s->enabled = 1;
        s->brownout_ms = DEFAULT_BROWNOUT_MS;
        s->seed = 1;
    }
    size_t length = strlen(text);
    char *copy = malloc(length + 1);
    if (copy == NULL) return -1;
    memcpy(copy, text, length + 1);
    int status = 0;
    for (char *item = copy, *next; status == 0 && item != NULL; item = next) {
        next = strchr(item, ',');
        if (next != NULL) *next++ = '\0';
        char why[200];
        int rc = parse_item(item, s, why, sizeof why);
        if (rc == -2) {
            fprintf(stderr, "openswarm-sim: --faults '%s': %s\n", text, why);
            status = -1;
        } else if (rc != 0) {
            char what[96];
            if (s->n_at == MAX_FAULTS_AT)
                snprintf(what, sizeof what, "too many faults at given times (64 at most)");
            else if (item[0] == '\0')
                snprintf(what, sizeof what, "an empty item");
            else
                snprintf(what, sizeof what, "'%.60s' is unknown or out of its range", item);
            spec_usage(text, what);
            status = -1;
        }
    }
    free(copy);
    return status;
}

/* A fault at a given robot as the spec names it (reset:, blank:, drift:). */
static const char *item_name(int kind) {
    switch (kind) {
    case FAULT_BLANK_CALIBRATION: return "blank";
    case FAULT_CLOCK_DRIFT: return "drift";
    default: return fault_kind_name(kind);
    }
}

int faults_check(const fault_spec *s, int robots_in_run, double seconds) {
    if (!s->enabled) return 0;
    if (s->blank > robots_in_run) {
        fprintf(stderr, "openswarm-sim: --faults blank=%d: the run has %d robots; give at most %d\n",
                s->blank, robots_in_run, robots_in_run);
        return -1;
    }
    for (int i = 0; i < s->n_at; i++) {
        if (s->at[i].robot < robots_in_run) continue;
        fprintf(stderr, "openswarm-sim: --faults %s:%d: the run's robots are 0..%d (the index, as in "
                        "\"[robot N]\", not the uid)\n",
                item_name(s->at[i].kind), s->at[i].robot, robots_in_run - 1);
        return -1;
    }
    for (int i = 0; i < s->n_at; i++) {
        const fault_at *f = &s->at[i];
        if ((f->kind != FAULT_RESET && f->kind != FAULT_BROWNOUT) || f->seconds <= seconds) continue;
        fprintf(stderr, "openswarm-sim: --faults %s: at %g s, after the end of the run (%g s): give a "
                        "time within it, or a longer --time\n",
                s->at_text[i], f->seconds, seconds);
        return -1;
    }
    return 0;
}
