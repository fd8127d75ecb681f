/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* trajectories.csv (one row per robot per sample) and objects.csv (one row
 * per object per sample), written as the samples come so that a long run
 * can be followed with `tail -f` (as NAME.csv.part: renamed to NAME.csv
 * when the run ends, so a NAME.csv is always whole) and a crash loses
 * nothing before it. The
 * formats are fixed (time to the millisecond, positions to 0.01 mm,
 * headings to 0.1 degree): the same run gives the same bytes. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "output/output_parts.h"

int tables_open(output_tables *t, const char *robots_path, const char *objects_path)
{
    memset(t, 0, sizeof *t);
    t->robots_path = strdup(robots_path);
    t->objects_path = strdup(objects_path);
    t->robots = part_table_open(robots_path, "time_s,robot,x_mm,y_mm,heading_deg,led_r,led_g,led_b");
    if (t->robots)
        t->objects = part_table_open(objects_path, "time_s,object,x_mm,y_mm");
    if (!t->robots_path || !t->objects_path || !t->robots || !t->objects) {
        tables_close(t, 0);
        return -1;
    }
    return 0;
}

/* -0.00 would differ from 0.00 between two runs that differ by rounding
 * noise only; print both as 0.00. */
static double no_negative_zero(double v, double half_unit)
{
    return (v < 0 && v > -half_unit) ? 0.0 : v;
}

/* Headings in [0, 360), whatever the physics keeps. */
static double heading_0_360(double deg)
{
    double h = deg - 360.0 * (double)(long long)(deg / 360.0);
    if (h < 0)
        h += 360.0;
    if (h >= 359.95)
        h = 0.0;
    return h;
}

int tables_add(output_tables *t, const world_spec *w, const output_sample *s)
{
    for (int i = 0; i < w->n_robots; i++) {
        const output_robot *r = &s->robots[i];
        fprintf(t->robots, "%.3f,%d,%.2f,%.2f,%.1f,%d,%d,%d\n", s->time_s, i,
                no_negative_zero(r->x_mm, 0.005), no_negative_zero(r->y_mm, 0.005),
                heading_0_360(r->heading_deg), r->led_r, r->led_g, r->led_b);
    }
    for (int i = 0; i < w->n_objects; i++)
        fprintf(t->objects, "%.3f,%d,%.2f,%.2f\n", s->time_s, i,
                no_negative_zero(s->objects[i].x, 0.005), no_negative_zero(s->objects[i].y, 0.005));
    if (ferror(t->robots) || ferror(t->objects)) {
        const char *path = ferror(t->robots) ? t->robots_path : t->objects_path;
        fprintf(stderr, "openswarm-sim: cannot write %s: %s; is the disk full?\n", path,
                strerror(errno));
        return -1;
    }
    return 0;
}

int tables_close(output_tables *t, int keep)
{
    int rc = 0;
    if (part_table_close(t->robots, t->robots_path, keep))
        rc = -1;
    if (part_table_close(t->objects, t->objects_path, keep))
        rc = -1;
    free(t->robots_path);
    free(t->objects_path);
    memset(t, 0, sizeof *t);
    return rc;
}
