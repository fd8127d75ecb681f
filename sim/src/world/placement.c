/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Where the robots stand: every pair at one distance (--distance), on a
 * line (--line) or where a file says (--positions), and how far apart two
 * of them are. Positions are checked once, before anything runs, so the
 * lockstep loop never meets a robot inside another. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sim.h"

/* A Kilobot is a disc 33 mm across: two centres closer than that would
 * put one robot inside the other. */
#define BODY_MM 33.0
#define FAR_MM 100000.0 /* 100 m: beyond any arena, a sign of a typo */

void placement_all_at(placement *p, int distance_mm) {
    memset(p, 0, sizeof *p);
    p->distance_mm = distance_mm;
}

/* Room for robots positions, zeroed; -1 when memory runs out. */
static int positions_for(placement *p, int robots) {
    memset(p, 0, sizeof *p);
    p->has_positions = 1;
    p->x_mm = calloc((size_t)robots, sizeof(double));
    p->y_mm = calloc((size_t)robots, sizeof(double));
    if (p->x_mm != NULL && p->y_mm != NULL) return 0;
    fprintf(stderr, "openswarm-sim: out of memory for %d robots' positions\n", robots);
    return -1;
}

int placement_line(placement *p, int robots, const char *spacing_text) {
    char *end;
    double spacing = strtod(spacing_text, &end);
    if (end == spacing_text || *end != '\0' || !(spacing >= BODY_MM && spacing <= FAR_MM)) {
        fprintf(stderr, "openswarm-sim: --line '%s': expected millimetres between neighbours, "
                        "at least %.0f (a Kilobot is %.0f mm across), e.g. --line 80\n",
                spacing_text, BODY_MM, BODY_MM);
        return -1;
    }
    if (positions_for(p, robots) != 0) return -1;
    for (int i = 0; i < robots; i++) p->x_mm[i] = spacing * i;
    return 0;
}

double placement_distance(const placement *p, int a, int b) {
    if (!p->has_positions) return p->distance_mm;
    return hypot(p->x_mm[a] - p->x_mm[b], p->y_mm[a] - p->y_mm[b]);
}

double placement_distance_of(int a, int b, void *ctx) { return placement_distance(ctx, a, b); }

/* Reads "x y" from one line of the file; 0 for a blank or comment line,
 * 1 for a position, -1 for anything else. */
static int read_position(char *text, double *x, double *y) {
    char *comment = strchr(text, '#');
    if (comment != NULL) *comment = '\0';
    char *end;
    *x = strtod(text, &end);
    if (end == text) return strspn(text, " \t\r\n") == strlen(text) ? 0 : -1;
    char *rest = end;
    *y = strtod(rest, &end);
    if (end == rest || strspn(end, " \t\r\n") != strlen(end)) return -1;
    return isfinite(*x) && isfinite(*y) && fabs(*x) <= FAR_MM && fabs(*y) <= FAR_MM ? 1 : -1;
}

static void trim_end(char *text) {
    size_t n = strlen(text);
    while (n > 0 && strchr(" \t\r\n", text[n - 1]) != NULL) n--;
    text[n] = '\0';
}

/* Robot k (on line_of[k] of path) must not overlap any robot before it. */
static int check_overlap(const placement *p, const char *path, const int *line_of, int k) {
    for (int i = 0; i < k; i++) {
        double d = placement_distance(p, i, k);
        if (d < BODY_MM) {
            fprintf(stderr, "%s:%d: this robot is %.1f mm from the one on line %d; Kilobots are "
                            "%.0f mm across: move them at least %.0f mm apart\n",
                    path, line_of[k], d, line_of[i], BODY_MM, BODY_MM);
            return -1;
        }
    }
    return 0;
}

static int read_positions(placement *p, const char *path, FILE *f, int *count, int *line_of) {
    char text[256];
    *count = 0;
    for (int n = 1; fgets(text, sizeof text, f) != NULL; n++) {
        if (strchr(text, '\n') == NULL && !feof(f)) {
            fprintf(stderr, "%s:%d: line longer than %d characters; write \"x y\" only\n", path,
                    n, (int)sizeof text - 2);
            return -1;
        }
        double x, y;
        int got = read_position(text, &x, &y);
        if (got == 0) continue;
        if (got < 0) {
            trim_end(text);
            fprintf(stderr, "%s:%d: '%s': expected a robot's position \"x y\" in millimetres "
                            "(each within +-%.0f), e.g. \"80 0\"; a '#' starts a comment\n",
                    path, n, text, FAR_MM);
            return -1;
        }
        if (*count == MAX_ROBOTS) {
            fprintf(stderr, "%s:%d: more than %d robots; openswarm-sim runs at most %d\n", path,
                    n, MAX_ROBOTS, MAX_ROBOTS);
            return -1;
        }
        p->x_mm[*count] = x;
        p->y_mm[*count] = y;
        line_of[*count] = n;
        if (check_overlap(p, path, line_of, (*count)++) != 0) return -1;
    }
    if (ferror(f)) {
        fprintf(stderr, "openswarm-sim: --positions %s: %s; give a text file with one \"x y\" "
                        "line per robot\n", path, strerror(errno));
        return -1;
    }
    return 0;
}

int placement_file(placement *p, const char *path, int *robots, int robots_given) {
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        fprintf(stderr, "openswarm-sim: --positions %s: %s; give a file with one \"x y\" line "
                        "(millimetres) per robot\n", path, strerror(errno));
        return -1;
    }
    int count, *line_of = calloc(MAX_ROBOTS, sizeof(int)), status = -1;
    if (line_of != NULL && positions_for(p, MAX_ROBOTS) == 0)
        status = read_positions(p, path, f, &count, line_of);
    free(line_of);
    fclose(f);
    if (status != 0) return -1;
    if (count == 0) {
        fprintf(stderr, "%s: no positions; write one \"x y\" line (millimetres) per robot\n",
                path);
        return -1;
    }
    if (robots_given && count != *robots) {
        fprintf(stderr, "%s: %d position%s for --robots %d: give one \"x y\" line per robot, or "
                        "drop --robots to run one robot per line\n",
                path, count, count == 1 ? "" : "s", *robots);
        return -1;
    }
    *robots = count;
    return 0;
}
