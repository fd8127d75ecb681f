/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The run kept so far, sample by sample: final.png draws trails from it and
 * viewer.html embeds all of it, both written at the end. */
#include <stdlib.h>
#include <string.h>

#include "output/output_parts.h"

void history_init(output_history *h, const world_spec *w)
{
    memset(h, 0, sizeof *h);
    h->world = w;
}

/* Grows *p to hold at least `need` items of `size` bytes; capacities double. */
static int grow(void **p, int *capacity, int need, size_t size)
{
    if (need <= *capacity)
        return 0;
    int c = *capacity ? *capacity : 64;
    while (c < need)
        c *= 2;
    void *q = realloc(*p, (size_t)c * size);
    if (!q)
        return -1;
    *p = q;
    *capacity = c;
    return 0;
}

int history_add(output_history *h, const output_sample *s)
{
    const int nr = h->world->n_robots, no = h->world->n_objects;
    if (h->n + 1 > h->capacity) {
        int c = h->capacity ? h->capacity * 2 : 256;
        double *t = realloc(h->time_s, (size_t)c * sizeof *t);
        if (t)
            h->time_s = t;
        output_robot *r = realloc(h->robots, (size_t)c * (size_t)(nr ? nr : 1) * sizeof *r);
        if (r)
            h->robots = r;
        world_point *o = realloc(h->objects, (size_t)c * (size_t)(no ? no : 1) * sizeof *o);
        if (o)
            h->objects = o;
        int *ls = realloc(h->link_start, (size_t)(c + 1) * sizeof *ls);
        if (ls)
            h->link_start = ls;
        if (!t || !r || !o || !ls)
            return -1;
        h->capacity = c;
    }
    if (grow((void **)&h->links, &h->links_capacity, h->n_links + s->n_links, sizeof *h->links))
        return -1;
    const int k = h->n;
    h->time_s[k] = s->time_s;
    if (nr)
        memcpy(h->robots + (size_t)k * (size_t)nr, s->robots, (size_t)nr * sizeof *s->robots);
    if (no)
        memcpy(h->objects + (size_t)k * (size_t)no, s->objects, (size_t)no * sizeof *s->objects);
    h->link_start[k] = h->n_links;
    if (s->n_links)
        memcpy(h->links + h->n_links, s->links, (size_t)s->n_links * sizeof *s->links);
    h->n_links += s->n_links;
    h->link_start[k + 1] = h->n_links;
    h->n++;
    return 0;
}

void history_free(output_history *h)
{
    free(h->time_s);
    free(h->robots);
    free(h->objects);
    free(h->link_start);
    free(h->links);
    memset(h, 0, sizeof *h);
}
