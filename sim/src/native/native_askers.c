/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The askers' heap (native_askers.h). (at, index) is unique - a robot
 * asks once at a time - so the order is total and the same on any
 * number of threads. */
#include "native/native_askers.h"

#include <stdio.h>
#include <stdlib.h>

typedef struct asker {
    uint64_t at;
    int index;
} asker;

static asker *heap;
static unsigned n, room;

static int before(const asker *a, const asker *b) { return a->at < b->at || (a->at == b->at && a->index < b->index); }

static void swap(unsigned a, unsigned b) {
    asker t = heap[a];
    heap[a] = heap[b];
    heap[b] = t;
}

void native_askers_push(uint64_t at, int index) {
    if (n == room) {
        room = room ? 2 * room : 64;
        heap = realloc(heap, room * sizeof *heap);
        if (heap == NULL) {
            fprintf(stderr, "openswarm-sim: out of memory for the robots asking to transmit\n");
            exit(EXIT_FAILURE);
        }
    }
    unsigned k = n++;
    heap[k] = (asker){at, index};
    for (; k > 0 && before(&heap[k], &heap[(k - 1) / 2]); k = (k - 1) / 2) swap(k, (k - 1) / 2);
}

int native_askers_pop(void) {
    if (n == 0) return -1;
    int first = heap[0].index;
    heap[0] = heap[--n];
    for (unsigned k = 0;;) {
        unsigned least = k, l = 2 * k + 1, r = l + 1;
        if (l < n && before(&heap[l], &heap[least])) least = l;
        if (r < n && before(&heap[r], &heap[least])) least = r;
        if (least == k) break;
        swap(k, least);
        k = least;
    }
    return first;
}
