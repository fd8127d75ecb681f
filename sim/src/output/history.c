/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The run kept so far, sample by sample: final.png draws trails from it and
 * viewer.html embeds it, both written at the end. Past its budget it thins
 * itself to every other sample (output_parts.h). */
#include <stdlib.h>
#include <string.h>

#include "output/output_parts.h"

void history_init(output_history *h, const world_spec *w, size_t budget)
{
    memset(h, 0, sizeof *h);
    h->world = w;
    h->budget = budget ? budget : HISTORY_BUDGET_BYTES;
    h->stride = 1;
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

static size_t held_bytes(const output_history *h)
{
    const size_t per_sample = (size_t)h->world->n_robots * sizeof *h->robots +
                              (size_t)h->world->n_objects * sizeof *h->objects +
                              sizeof *h->time_s + sizeof *h->number + sizeof *h->link_start;
    return (size_t)h->n * per_sample + (size_t)h->n_links * sizeof *h->links;
}

/* Sample `from` moved to place `to` (to <= from); its links start at `at`. */
static void move_sample(output_history *h, int from, int to, int at)
{
    const size_t nr = (size_t)h->world->n_robots, no = (size_t)h->world->n_objects;
    const int first = h->link_start[from], count = h->link_start[from + 1] - first;
    h->number[to] = h->number[from];
    h->time_s[to] = h->time_s[from];
    memmove(h->robots + (size_t)to * nr, h->robots + (size_t)from * nr, nr * sizeof *h->robots);
    memmove(h->objects + (size_t)to * no, h->objects + (size_t)from * no, no * sizeof *h->objects);
    memmove(h->links + at, h->links + first, (size_t)count * sizeof *h->links);
    h->link_start[to] = at;
    h->link_start[to + 1] = at + count;
}

/* Keeps the samples on a stride twice as long, and the newest. */
static void thin(output_history *h)
{
    h->stride *= 2;
    int kept = 0;
    for (int k = 0; k < h->n; k++) {
        if (h->number[k] % h->stride != 0 && k != h->n - 1)
            continue;
        move_sample(h, k, kept, kept ? h->link_start[kept] : 0);
        kept++;
    }
    h->n = kept;
    h->n_links = h->link_start[kept];
}

static int make_room(output_history *h, int nr, int no)
{
    if (h->n + 1 <= h->capacity)
        return 0;
    int c = h->capacity ? h->capacity * 2 : 256;
    long *number = realloc(h->number, (size_t)c * sizeof *number);
    if (number)
        h->number = number;
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
    if (!number || !t || !r || !o || !ls)
        return -1;
    h->capacity = c;
    return 0;
}

int history_add(output_history *h, const output_sample *s)
{
    const int nr = h->world->n_robots, no = h->world->n_objects;
    /* The newest was kept for being the newest: a newer one replaces it. */
    if (h->n > 0 && h->number[h->n - 1] % h->stride != 0) {
        h->n--;
        h->n_links = h->link_start[h->n];
    }
    if (make_room(h, nr, no))
        return -1;
    if (grow((void **)&h->links, &h->links_capacity, h->n_links + s->n_links, sizeof *h->links))
        return -1;
    const int k = h->n;
    h->number[k] = h->added++;
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
    while (h->n > 2 && held_bytes(h) > h->budget)
        thin(h);
    return 0;
}

void history_forget_before(output_history *h, double t)
{
    int stale = 0;
    while (stale < h->n - 1 && h->time_s[stale] < t)
        stale++;
    /* Moved only once half is stale: each sample moves about once. */
    if (stale == 0 || stale < h->n / 2)
        return;
    for (int k = stale; k < h->n; k++)
        move_sample(h, k, k - stale, k > stale ? h->link_start[k - stale] : 0);
    h->n -= stale;
    h->n_links = h->link_start[h->n];
}

void history_free(output_history *h)
{
    free(h->number);
    free(h->time_s);
    free(h->robots);
    free(h->objects);
    free(h->link_start);
    free(h->links);
    memset(h, 0, sizeof *h);
}
