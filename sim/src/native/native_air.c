/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Frames between native robots (native_air.h). */
#include "native/native_air.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "world/world_random.h"
#include "world/world_run.h"

/* A frame on the wire: 130 slots of 269 cycles (ports/kilobot/src/devices/ir_wire.h). */
#define FRAME_CYCLES ((uint64_t)IR_FRAME_SLOTS * IR_BIT_CYCLES)

typedef struct delivery {
    int receiver, sender;
    native_frame frame;
} delivery;

static int n_robots;
static double range_mm, loss;
static uint32_t nominal;
static uint64_t latency;
static ir_distance_fn distance_of;
static void *distance_ctx;
static uint64_t *receiver_rng; /* each receiver's loss and noise draws */
static uint64_t *last_start;   /* each sender's last frame's start, nominal cycles; 0: none */
static delivery *pending;
static size_t n_pending, pending_room;
static uint64_t overflowed;

void native_air_start(int n, int range, double loss_pct, uint64_t seed, uint32_t nominal_hz, uint64_t lat) {
    n_robots = n;
    range_mm = range;
    loss = loss_pct / 100.0;
    nominal = nominal_hz;
    latency = lat;
    receiver_rng = malloc((size_t)n * sizeof *receiver_rng);
    last_start = calloc((size_t)n, sizeof *last_start);
    for (int i = 0; receiver_rng != NULL && i < n; i++) {
        receiver_rng[i] = seed ^ (0xD1B54A32D192ED03ull * (uint64_t)(i + 1));
        world_random_next(&receiver_rng[i]);
    }
}

void native_air_place(ir_distance_fn distance, void *ctx) {
    distance_of = distance;
    distance_ctx = ctx;
}

/* A receiver's comparator sees a frame's first pulse within a few
 * microseconds: two robots that start closer together both send. */
#define SENSE_CYCLES IR_LATENCY_CYCLES

int native_air_clear(int sender, uint64_t at) {
    uint64_t now = at * nominal / native_swarm_robot(sender)->hz;
    for (int j = 0; j < n_robots; j++) {
        uint64_t s = last_start[j];
        if (j == sender || s == 0 || s + SENSE_CYCLES > now || now >= s + FRAME_CYCLES) continue;
        if (distance_of(sender, j, distance_ctx) <= range_mm) return 0;
    }
    last_start[sender] = now;
    return 1;
}

int native_air_links(int sender, int *receivers, int room) {
    int n = 0;
    for (int j = 0; j < n_robots; j++) {
        if (j == sender || distance_of(sender, j, distance_ctx) > range_mm) continue;
        if (n < room) receivers[n] = j;
        n++;
    }
    return n < room ? n : room;
}

/* A reading as the receiver's ADC takes it: the model's, with its noise. */
static int16_t reading(int model, uint64_t *rng) {
    long r = lround(model + WORLD_ANALOG_NOISE_COUNTS * world_random_normal(rng));
    return (int16_t)(r < 0 ? 0 : r > 1023 ? 1023 : r);
}

static void deliver_to(int receiver, int sender, const native_sent *s, double mm) {
    uint64_t *rng = &receiver_rng[receiver];
    double chance = loss * (mm / range_mm) * (mm / range_mm);
    if (chance > 0 && world_random_uniform(rng) < chance) return;
    uint32_t from_hz = native_swarm_robot(sender)->hz, to_hz = native_swarm_robot(receiver)->hz;
    uint64_t start = s->at * nominal / from_hz + latency; /* nominal cycles */
    if (n_pending == pending_room) {
        pending_room = pending_room ? 2 * pending_room : 256;
        pending = realloc(pending, pending_room * sizeof *pending);
        if (pending == NULL) exit(EXIT_CRASH);
    }
    delivery *d = &pending[n_pending++];
    memset(d, 0, sizeof *d);
    d->receiver = receiver;
    d->sender = sender;
    d->frame.start = start * to_hz / nominal;
    d->frame.end = d->frame.start + FRAME_CYCLES * to_hz / from_hz;
    memcpy(d->frame.bytes, s->bytes, sizeof d->frame.bytes);
    int rounded = (int)lround(mm);
    d->frame.high_gain = reading(ir_high_gain_reading(rounded), rng);
    d->frame.low_gain = reading(ir_low_gain_reading(rounded), rng);
}

void native_air_send(int sender, const native_sent *frames, unsigned n) {
    for (unsigned k = 0; k < n; k++)
        for (int j = 0; j < n_robots; j++) {
            if (j == sender) continue;
            double mm = distance_of(sender, j, distance_ctx);
            if (mm <= range_mm) deliver_to(j, sender, &frames[k], mm);
        }
}

static int by_receiver_then_start(const void *a, const void *b) {
    const delivery *x = a, *y = b;
    if (x->receiver != y->receiver) return x->receiver < y->receiver ? -1 : 1;
    if (x->frame.start != y->frame.start) return x->frame.start < y->frame.start ? -1 : 1;
    return x->sender < y->sender ? -1 : x->sender > y->sender;
}

/* Into the receiver's inbox (kept by start: every frame handed over now
 * starts after those before it); frames that overlap there are broken,
 * both, as two senders' pulses interleave at the receiver. */
static void enqueue(native_io *io, native_frame f) {
    if (io->inbox_count == NATIVE_INBOX_ROOM) {
        io->frames_lost_inbox_full++;
        overflowed++;
        return;
    }
    for (unsigned k = 0; k < io->inbox_count; k++) {
        native_frame *g = &io->inbox[(io->inbox_head + k) % NATIVE_INBOX_ROOM];
        if (g->start < f.end && f.start < g->end) g->broken = f.broken = 1;
    }
    io->inbox[(io->inbox_head + io->inbox_count) % NATIVE_INBOX_ROOM] = f;
    io->inbox_count++;
}

void native_air_hand_over(void) {
    if (n_pending == 0) return;
    qsort(pending, n_pending, sizeof *pending, by_receiver_then_start);
    for (size_t k = 0; k < n_pending; k++)
        enqueue(native_swarm_robot(pending[k].receiver)->io, pending[k].frame);
    n_pending = 0;
}

uint64_t native_air_overflowed(void) { return overflowed; }
