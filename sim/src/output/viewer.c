/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* viewer.html: the player (viewer_page.html, built into the simulator as
 * output_viewer_page) with the run put in place of its RUN marker, as
 * compact JSON: per sample [time, [x, y, heading, led, ...], [object x, y,
 * ...], [a, b, ...]], positions to 0.1 mm, headings to the degree, the LED
 * as r * 16 + g * 4 + b, and each pair of robots linked by IR (one way or
 * both: the viewer draws a line) once, lower index first. 100 robots for
 * 1200 samples make 2 to 6 MB, the more the denser the swarm. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "output/output_parts.h"

extern const char output_viewer_page[]; /* generated from viewer_page.html */

static const char marker[] = "/*OPENSWARM_RUN*/";

/* A number to `decimals` places, without a sign on zero. */
static void number(FILE *f, double v, int decimals)
{
    const double half = 0.5 * pow(10, -decimals);
    if (!isfinite(v))
        v = 0;
    if (v < 0 && v > -half)
        v = 0;
    fprintf(f, "%.*f", decimals, v);
}

/* "[x,y,value]", after a comma unless it is the list's first (index 0). */
static void place(FILE *f, int index, world_point at, double value, int value_decimals)
{
    fputs(index ? ",[" : "[", f);
    number(f, at.x, 1);
    fputc(',', f);
    number(f, at.y, 1);
    fputc(',', f);
    number(f, value, value_decimals);
    fputc(']', f);
}

static void write_world(FILE *f, const world_spec *w)
{
    fputs("{\"arena\":[", f);
    number(f, w->width_mm, 1);
    fputc(',', f);
    number(f, w->height_mm, 1);
    fputs("],\"radius\":", f);
    number(f, world_robot_radius(w), 1);
    fputs(",\"obstacles\":[", f);
    for (int i = 0; i < w->n_obstacles; i++) {
        fputs(i ? ",[" : "[", f);
        for (int k = 0; k < w->obstacles[i].n; k++) {
            if (k)
                fputc(',', f);
            number(f, w->obstacles[i].v[k].x, 1);
            fputc(',', f);
            number(f, w->obstacles[i].v[k].y, 1);
        }
        fputc(']', f);
    }
    fputs("],\"objects\":[", f);
    for (int i = 0; i < w->n_objects; i++)
        place(f, i, w->objects[i].at, w->objects[i].radius_mm, 1);
    fputs("],\"lights\":[", f);
    for (int i = 0; i < w->n_lights; i++)
        place(f, i, w->lights[i].at, w->lights[i].intensity_mv, 1);
    fprintf(f, "],\"robots\":%d,\"start\":[", w->n_robots);
    for (int i = 0; i < w->n_robots; i++)
        place(f, i, w->robots[i].at, w->robots[i].heading_deg, 0);
    fputc(']', f);
}

static int by_pair(const void *a, const void *b)
{
    const output_link *x = a, *y = b;
    return x->sender != y->sender ? x->sender - y->sender : x->receiver - y->receiver;
}

/* Sample k's links as sorted pairs a < b, each once. */
static void write_link_pairs(FILE *f, const output_history *h, int k, output_link *pairs)
{
    int n = 0;
    for (int l = h->link_start[k]; l < h->link_start[k + 1]; l++) {
        const output_link *x = &h->links[l];
        if (x->sender == x->receiver)
            continue;
        pairs[n].sender = x->sender < x->receiver ? x->sender : x->receiver;
        pairs[n].receiver = x->sender < x->receiver ? x->receiver : x->sender;
        n++;
    }
    qsort(pairs, (size_t)n, sizeof *pairs, by_pair);
    for (int i = 0; i < n; i++)
        if (i == 0 || by_pair(&pairs[i], &pairs[i - 1]))
            fprintf(f, "%s%d,%d", i ? "," : "", pairs[i].sender, pairs[i].receiver);
}

static int write_samples(FILE *f, const output_history *h)
{
    int most = 1;
    for (int k = 0; k < h->n; k++)
        if (h->link_start[k + 1] - h->link_start[k] > most)
            most = h->link_start[k + 1] - h->link_start[k];
    output_link *pairs = malloc((size_t)most * sizeof *pairs);
    if (!pairs)
        return -1;
    const world_spec *w = h->world;
    fputs(",\"samples\":[", f);
    for (int k = 0; k < h->n; k++) {
        fputs(k ? ",\n[" : "\n[", f);
        number(f, h->time_s[k], 3);
        fputs(",[", f);
        const output_robot *r = history_robots(h, k);
        for (int i = 0; i < w->n_robots; i++) {
            if (i)
                fputc(',', f);
            number(f, r[i].x_mm, 1);
            fputc(',', f);
            number(f, r[i].y_mm, 1);
            fputc(',', f);
            number(f, r[i].heading_deg, 0);
            fprintf(f, ",%d", (r[i].led_r & 3) * 16 + (r[i].led_g & 3) * 4 + (r[i].led_b & 3));
        }
        fputs("],[", f);
        const world_point *o = history_objects(h, k);
        for (int i = 0; i < w->n_objects; i++) {
            if (i)
                fputc(',', f);
            number(f, o[i].x, 1);
            fputc(',', f);
            number(f, o[i].y, 1);
        }
        fputs("],[", f);
        write_link_pairs(f, h, k, pairs);
        fputs("]]", f);
    }
    fputs("]}", f);
    free(pairs);
    return 0;
}

int viewer_write(const char *path, const output_history *h)
{
    const char *at = strstr(output_viewer_page, marker);
    if (!at) {
        fprintf(stderr, "openswarm-sim: the viewer page built in has no %s marker (a bug)\n",
                marker);
        return -1;
    }
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "openswarm-sim: cannot write %s: %s; choose another --out folder\n", path,
                strerror(errno));
        return -1;
    }
    fwrite(output_viewer_page, 1, (size_t)(at - output_viewer_page), f);
    write_world(f, h->world);
    int bad = write_samples(f, h);
    fputs(at + strlen(marker), f);
    bad |= ferror(f);
    if (fclose(f) != 0 || bad) {
        fprintf(stderr, "openswarm-sim: cannot write %s: %s; is the disk full?\n", path,
                strerror(errno));
        return -1;
    }
    return 0;
}
