/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* IR faults on whole frames (native_frame_faults.h).
 *
 * The exact mode flips a slot at a receiver by losing the pulse in it or
 * adding one to it (air/ir_faults.c) and lets the firmware's decoder make
 * of the frame what it can. Not every flip loses the frame: a byte's start
 * bit only re-times the decoder, and the stop bits of all bytes but the
 * last are not read - a frame survives a lost pulse there unless the
 * silence it leaves ends the frame (docs/benchmarks.md measures the share
 * lost). So the frame is not lost with a formula's chance: its slots are
 * laid out as the sender sends them, the faults applied, and the pulses
 * left replayed through the same decoder the robot runs. */
#include "native/native_frame_faults.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "devices/ir_wire.h"
#include "faults/faults.h"
#include "world/world_random.h"

#define SLOTS IR_WIRE_SLOTS
#define MAX_ADDED 16 /* a frame's added pulses at one receiver, as air/ir_faults.h */

typedef struct frame_fault {
    double seconds; /* on the sender's clock */
    int robot, from, kind, slot;
    unsigned order; /* drawn at this receiver before those with a higher one */
} frame_fault;

typedef struct fault_list {
    frame_fault *all;
    unsigned n, room;
} fault_list;

static double flip, cut; /* chances, 0..1 */
static uint64_t *rng;    /* each receiver's */
static fault_list *lists, merged;
static int n_lists;

int native_frame_faults_start(double flip_pct, double cut_pct, uint64_t seed, int n_robots) {
    flip = flip_pct / 100.0;
    cut = cut_pct / 100.0;
    if (!native_frame_faults_on()) return 0;
    rng = malloc((size_t)n_robots * sizeof *rng);
    if (rng == NULL) return -1;
    for (int i = 0; i < n_robots; i++) rng[i] = world_random_stream(seed ^ 0xF7A3E5C1D2B4968Full, (uint64_t)i);
    return 0;
}

int native_frame_faults_on(void) { return flip > 0 || cut > 0; }

void native_frame_faults_threads(int n) {
    if (lists != NULL) return;
    lists = calloc((size_t)n, sizeof *lists);
    if (lists == NULL) exit(EXIT_CRASH);
    n_lists = n;
}

static void append(fault_list *l, frame_fault f) {
    if (l->n == l->room) {
        l->room = l->room ? 2 * l->room : 64;
        l->all = realloc(l->all, l->room * sizeof *l->all);
        if (l->all == NULL) exit(EXIT_CRASH);
    }
    l->all[l->n++] = f;
}

/* A fault drawn on a thread: one receiver's are all drawn on one thread,
 * so their order there is the order drawn. */
static void note(fault_list *l, frame_fault f) {
    f.order = l->n;
    append(l, f);
}

/* Which of a frame's slots hold a pulse, as the sender's send_slots lays
 * them out (ports/kilobot/src/devices/ir.c). */
static void lay_out(const uint8_t bytes[NATIVE_FRAME_BYTES], uint8_t one[SLOTS]) {
    for (unsigned slot = 0; slot < SLOTS; slot++) {
        if (slot < IR_WIRE_HEADER_SLOTS) {
            one[slot] = slot == 0u || slot == IR_WIRE_HEADER_SLOTS - 1u;
            continue;
        }
        unsigned s = slot - IR_WIRE_HEADER_SLOTS, bit = s % 10u;
        one[slot] = bit == 0u || bit == 9u || ((bytes[s / 10u] >> (bit - 1u)) & 1u);
    }
}

/* Slots to the next flipped one: geometric, one draw per flip. */
static unsigned slots_to_next_flip(uint64_t *r) {
    double gap = floor(log(1.0 - world_random_uniform(r)) / log(1.0 - flip)) + 1.0;
    return gap > SLOTS ? SLOTS + 1u : (unsigned)gap;
}

/* Draw the faults of one frame at receiver to into one, and note them;
 * the slots from cut_from on (SLOTS: not cut) hold nothing. */
static void draw(fault_list *l, int from, int to, double t0, double slot_s, uint8_t one[SLOTS]) {
    uint64_t *r = &rng[to];
    unsigned cut_from = SLOTS;
    if (cut > 0 && world_random_uniform(r) < cut) {
        cut_from = 1u + (unsigned)(world_random_uniform(r) * (SLOTS - 1));
        note(l, (frame_fault){t0, to, from, FAULT_FRAME_CUT, (int)cut_from, 0});
    }
    int added = 0;
    for (unsigned slot = flip > 0 ? slots_to_next_flip(r) - 1u : SLOTS; slot < cut_from;
         slot += slots_to_next_flip(r)) {
        int kind = one[slot] ? FAULT_PULSE_LOST : FAULT_PULSE_ADDED;
        if (kind == FAULT_PULSE_ADDED && added == MAX_ADDED) continue;
        added += kind == FAULT_PULSE_ADDED;
        one[slot] = !one[slot];
        note(l, (frame_fault){t0 + slot * slot_s, to, from, kind, (int)slot, 0});
    }
    memset(one + cut_from, 0, SLOTS - cut_from);
}

typedef enum replayed { GONE, WHOLE, COLLIDED, BROKEN } replayed;

/* The pulses left, through the receiver's decoder as ir.c's receive_frame
 * drives it: a silence longer than IR_WIRE_SILENCE ends the frame short.
 * first: the slot of the pulse it starts at. */
static replayed replay(const uint8_t one[SLOTS], uint8_t bytes[NATIVE_FRAME_BYTES], unsigned *first) {
    unsigned k = 0;
    while (k < SLOTS && !one[k]) k++;
    if (k == SLOTS) return GONE;
    *first = k;
    ir_wire_decoder d;
    memset(bytes, 0, NATIVE_FRAME_BYTES);
    ir_wire_decode_start(&d, (uint16_t)(k * IR_WIRE_BIT), bytes);
    for (unsigned last = k++; k < SLOTS; k++) {
        if (!one[k]) continue;
        if ((k - last) * IR_WIRE_BIT > IR_WIRE_SILENCE) return BROKEN;
        last = k;
        switch (ir_wire_decode_pulse(&d, (uint16_t)(k * IR_WIRE_BIT))) {
        case IR_WIRE_MORE:
        case IR_WIRE_HEADER_STOP: break;
        case IR_WIRE_WHOLE: return WHOLE;
        case IR_WIRE_COLLISION: return COLLIDED;
        case IR_WIRE_BROKEN: return BROKEN;
        }
    }
    return BROKEN; /* its last stop bit never came */
}

int native_frame_faults_apply(int thread, int from, int to, uint64_t at, uint32_t from_hz, uint32_t to_hz,
                              native_frame *f) {
    fault_list *l = &lists[thread];
    unsigned before = l->n, first = 0;
    uint8_t one[SLOTS];
    lay_out(f->bytes, one);
    draw(l, from, to, (double)at / from_hz, (double)IR_WIRE_BIT / from_hz, one);
    if (l->n == before) return 0; /* untouched */
    switch (replay(one, f->bytes, &first)) {
    case GONE: return -1;
    case WHOLE: break; /* its bytes as read: the receiver's CRC check judges them */
    case COLLIDED: f->damage = NATIVE_FRAME_COLLIDED; break;
    case BROKEN: f->damage = NATIVE_FRAME_BROKEN; break;
    }
    f->start += (uint64_t)first * IR_WIRE_BIT * to_hz / from_hz; /* its first pulse left */
    return 0;
}

static int by_time(const void *a, const void *b) {
    const frame_fault *x = a, *y = b;
    if (x->seconds != y->seconds) return x->seconds < y->seconds ? -1 : 1;
    if (x->robot != y->robot) return x->robot < y->robot ? -1 : 1;
    return (x->order > y->order) - (x->order < y->order);
}

void native_frame_faults_log(void) {
    merged.n = 0;
    for (int t = 0; t < n_lists; t++) {
        for (unsigned k = 0; k < lists[t].n; k++) append(&merged, lists[t].all[k]);
        lists[t].n = 0;
    }
    qsort(merged.all, merged.n, sizeof *merged.all, by_time);
    for (unsigned k = 0; k < merged.n; k++) {
        const frame_fault *f = &merged.all[k];
        fault_log(f->kind, f->seconds, f->robot, "from=%d slot=%d", f->from, f->slot);
    }
}
