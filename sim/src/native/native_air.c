/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Frames between native robots (native_air.h). */
#include "native/native_air.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "native/native_frame_faults.h"
#include "window_workers.h"
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
static uint64_t *frames_sent;  /* each sender's frames so far: the distance error's frame count */
/* Each receiver's frames from robots in range: in its inbox, or lost on
 * the way (the loss's draw, a full inbox); counted on its own thread. */
static uint64_t *heard, *lost_channel;
static ir_distance_error distance_error;
/* Each thread's: the frames on their way to its receivers, and those
 * that found an inbox full. */
typedef struct deliveries {
    delivery *pending;
    size_t n_pending, pending_room;
    uint64_t overflowed;
} deliveries;
static deliveries *by_thread;

void native_air_start(int n, int range, double loss_pct, uint64_t seed, uint32_t nominal_hz, uint64_t lat,
                      const ir_distance_error *distance) {
    n_robots = n;
    distance_error = distance != NULL ? *distance : (ir_distance_error){0, 0, 0};
    frames_sent = calloc((size_t)n, sizeof *frames_sent);
    heard = calloc((size_t)n, sizeof *heard);
    lost_channel = calloc((size_t)n, sizeof *lost_channel);
    range_mm = range;
    loss = loss_pct / 100.0;
    nominal = nominal_hz;
    latency = lat;
    receiver_rng = malloc((size_t)n * sizeof *receiver_rng);
    last_start = calloc((size_t)n, sizeof *last_start);
    for (int i = 0; receiver_rng != NULL && i < n; i++) receiver_rng[i] = world_random_stream(seed, (uint64_t)i);
}

/* Robots by cell of a grid range_mm wide (when their positions are
 * known): the robots in range of one are in its cell and the eight round
 * it. A counting sort: cell_first[c] .. cell_first[c + 1] index in_cell. */
static int grid_on, grid_cols, grid_rows;
static double grid_x0, grid_y0, grid_cell;
static const double *where; /* the positions the grid holds */
static double beyond_squared; /* past this square of a distance, out of range for sure */
static int *cell_first, *in_cell, *cell_of;
static int grid_room;

static int cell_at(double x, double y, int *cx, int *cy) {
    *cx = (int)((x - grid_x0) / grid_cell);
    *cy = (int)((y - grid_y0) / grid_cell);
    return *cy * grid_cols + *cx;
}

static void grid_build(const double *xy) {
    double x1 = xy[0], y1 = xy[1];
    grid_x0 = x1;
    grid_y0 = y1;
    for (int i = 1; i < n_robots; i++) {
        double x = xy[2 * i], y = xy[2 * i + 1];
        grid_x0 = x < grid_x0 ? x : grid_x0;
        grid_y0 = y < grid_y0 ? y : grid_y0;
        x1 = x > x1 ? x : x1;
        y1 = y > y1 ? y : y1;
    }
    grid_cell = range_mm;
    /* At most four cells a robot: a far-flung swarm gets larger cells. */
    while ((floor((x1 - grid_x0) / grid_cell) + 1) * (floor((y1 - grid_y0) / grid_cell) + 1) > 4.0 * n_robots + 16)
        grid_cell *= 2;
    grid_cols = (int)floor((x1 - grid_x0) / grid_cell) + 1;
    grid_rows = (int)floor((y1 - grid_y0) / grid_cell) + 1;
    int cells = grid_cols * grid_rows, cx, cy;
    if (cells + 1 > grid_room) {
        grid_room = 2 * (cells + 1);
        cell_first = realloc(cell_first, (size_t)grid_room * sizeof *cell_first);
        if (cell_first == NULL) exit(EXIT_CRASH);
    }
    memset(cell_first, 0, (size_t)(cells + 1) * sizeof *cell_first);
    for (int i = 0; i < n_robots; i++) cell_first[(cell_of[i] = cell_at(xy[2 * i], xy[2 * i + 1], &cx, &cy)) + 1]++;
    for (int c = 0; c < cells; c++) cell_first[c + 1] += cell_first[c];
    int *fill = malloc((size_t)cells * sizeof *fill);
    if (fill == NULL) exit(EXIT_CRASH);
    memcpy(fill, cell_first, (size_t)cells * sizeof *fill);
    for (int i = 0; i < n_robots; i++) in_cell[fill[cell_of[i]]++] = i; /* by index within a cell */
    free(fill);
}

void native_air_place(ir_distance_fn distance, void *ctx, const double *xy) {
    distance_of = distance;
    distance_ctx = ctx;
    grid_on = xy != NULL && n_robots > 0;
    if (!grid_on) return;
    where = xy;
    /* The world's distance is hypot's, exactly rounded: a margin far
     * above the sum of squares' rounding keeps every pair it puts in range. */
    beyond_squared = range_mm * range_mm * (1.0 + 1e-9);
    if (in_cell == NULL) {
        in_cell = malloc((size_t)n_robots * sizeof *in_cell);
        cell_of = malloc((size_t)n_robots * sizeof *cell_of);
        if (in_cell == NULL || cell_of == NULL) exit(EXIT_CRASH);
    }
    grid_build(xy);
}

/* each(j, mm, ctx) for every robot j in range of robot i (not i), in
 * index order within each cell. */
typedef void (*in_range_fn)(int j, double mm, void *ctx);

static void visit(int i, int j, in_range_fn each, void *ctx) {
    if (j == i) return;
    if (grid_on) { /* most of the cells round a robot are out of its range: no hypot for them */
        double dx = where[2 * i] - where[2 * j], dy = where[2 * i + 1] - where[2 * j + 1];
        if (dx * dx + dy * dy > beyond_squared) return;
    }
    double mm = distance_of(i, j, distance_ctx);
    if (mm <= range_mm) each(j, mm, ctx);
}

static void each_in_range(int i, in_range_fn each, void *ctx) {
    if (!grid_on) {
        for (int j = 0; j < n_robots; j++) visit(i, j, each, ctx);
        return;
    }
    int c = cell_of[i], cx = c % grid_cols, cy = c / grid_cols;
    for (int y = cy - 1; y <= cy + 1; y++)
        for (int x = cx - 1; x <= cx + 1; x++) {
            if (x < 0 || y < 0 || x >= grid_cols || y >= grid_rows) continue;
            int cell = y * grid_cols + x;
            for (int k = cell_first[cell]; k < cell_first[cell + 1]; k++) visit(i, in_cell[k], each, ctx);
        }
}

/* A receiver's comparator sees a frame's first pulse within a few
 * microseconds: two robots that start closer together both send. */
#define SENSE_CYCLES IR_LATENCY_CYCLES

typedef struct carrier {
    uint64_t now; /* nominal cycles */
    int busy;
} carrier;

/* A robot in range whose frame began before now, sensed, and is not over. */
static void sense(int j, double mm, void *ctx) {
    (void)mm;
    carrier *c = ctx;
    uint64_t s = last_start[j];
    if (s != 0 && s + SENSE_CYCLES <= c->now && c->now < s + FRAME_CYCLES) c->busy = 1;
}

int native_air_clear(int sender, uint64_t at) {
    carrier c = {at * nominal / native_swarm_robot(sender)->hz, 0};
    each_in_range(sender, sense, &c);
    if (c.busy) return 0;
    last_start[sender] = c.now;
    return 1;
}

typedef struct link_list {
    int *receivers;
    int room, n;
} link_list;

static void add_link(int j, double mm, void *ctx) {
    (void)mm;
    link_list *l = ctx;
    if (l->n < l->room) l->receivers[l->n] = j;
    l->n++;
}

static int by_index(const void *a, const void *b) { return *(const int *)a - *(const int *)b; }

int native_air_links(int sender, int *receivers, int room) {
    link_list l = {receivers, room, 0};
    each_in_range(sender, add_link, &l);
    int n = l.n < room ? l.n : room;
    qsort(receivers, (size_t)n, sizeof *receivers, by_index);
    return n;
}

/* A reading as the receiver's ADC takes it: the model's, with its noise. */
static int16_t reading(int model, uint64_t *rng) {
    long r = lround(model + WORLD_ANALOG_NOISE_COUNTS * world_random_normal(rng));
    return (int16_t)(r < 0 ? 0 : r > 1023 ? 1023 : r);
}

static void deliver_to(int t, int receiver, int sender, uint64_t frame, const native_sent *s, double mm) {
    deliveries *out = &by_thread[t];
    uint64_t *rng = &receiver_rng[receiver];
    double chance = loss * (mm / range_mm) * (mm / range_mm);
    if (chance > 0 && world_random_uniform(rng) < chance) {
        lost_channel[receiver]++;
        return;
    }
    uint32_t from_hz = native_swarm_robot(sender)->hz, to_hz = native_swarm_robot(receiver)->hz;
    uint64_t start = s->at * nominal / from_hz + latency; /* nominal cycles */
    if (out->n_pending == out->pending_room) {
        out->pending_room = out->pending_room ? 2 * out->pending_room : 256;
        out->pending = realloc(out->pending, out->pending_room * sizeof *out->pending);
        if (out->pending == NULL) exit(EXIT_CRASH);
    }
    delivery *d = &out->pending[out->n_pending++];
    memset(d, 0, sizeof *d);
    d->receiver = receiver;
    d->sender = sender;
    d->frame.start = start * to_hz / nominal;
    d->frame.end = d->frame.start + FRAME_CYCLES * to_hz / from_hz;
    memcpy(d->frame.bytes, s->bytes, sizeof d->frame.bytes);
    int sensed = ir_distance_sensed(&distance_error, sender, receiver, frame, mm);
    d->frame.high_gain = reading(ir_high_gain_reading(sensed), rng);
    d->frame.low_gain = reading(ir_low_gain_reading(sensed), rng);
    if (native_frame_faults_on() &&
        native_frame_faults_apply(t, sender, receiver, s->at, from_hz, to_hz, &d->frame) != 0)
        out->n_pending--; /* --faults left nothing of it */
}

static int by_receiver_then_start(const void *a, const void *b) {
    const delivery *x = a, *y = b;
    if (x->receiver != y->receiver) return x->receiver < y->receiver ? -1 : 1;
    if (x->frame.start != y->frame.start) return x->frame.start < y->frame.start ? -1 : 1;
    return x->sender < y->sender ? -1 : x->sender > y->sender;
}

/* Into the receiver's inbox, kept by start (a robot's frame handed over
 * now starts after those before it; the overhead controller's may come
 * between); frames that overlap there are broken, both, as two senders'
 * pulses interleave at the receiver. 0: no room, the frame lost. */
static int enqueue(deliveries *out, native_io *io, native_frame f) {
    if (io->inbox_count == NATIVE_INBOX_ROOM) {
        io->frames_lost_inbox_full++;
        out->overflowed++;
        return 0;
    }
    unsigned at = io->inbox_count;
    for (unsigned k = 0; k < io->inbox_count; k++) {
        native_frame *g = &io->inbox[(io->inbox_head + k) % NATIVE_INBOX_ROOM];
        if (g->start < f.end && f.start < g->end) g->damage = f.damage = NATIVE_FRAME_COLLIDED;
        if (g->start > f.start && at == io->inbox_count) at = k;
    }
    for (unsigned k = io->inbox_count; k > at; k--)
        io->inbox[(io->inbox_head + k) % NATIVE_INBOX_ROOM] = io->inbox[(io->inbox_head + k - 1) % NATIVE_INBOX_ROOM];
    io->inbox[(io->inbox_head + at) % NATIVE_INBOX_ROOM] = f;
    io->inbox_count++;
    return 1;
}

/* Frames from outside the swarm: their overflows. */
static deliveries from_outside;

void native_air_hand_over(int receiver, const native_frame *f) {
    (void)enqueue(&from_outside, native_swarm_robot(receiver)->io, *f); /* not a robot's: uncounted */
    native_swarm_woken(receiver);
}

/* The window's senders (index order) and whom each reaches: found on
 * every thread, senders t, t + T, ...; each sender's reach is the same
 * for all its frames (nobody moves between windows' ends). */
typedef struct reach {
    int receiver;
    double mm;
} reach;
typedef struct reach_list {
    reach *all;
    unsigned n, room;
} reach_list;
static const int *senders;
static unsigned n_senders;
static reach_list *reach_by_thread;
static unsigned *reach_first, *reach_count, senders_room; /* per sender, in its thread's list */

static void add_reach(int j, double mm, void *ctx) {
    reach_list *l = ctx;
    if (l->n == l->room) {
        l->room = l->room ? 2 * l->room : 1024;
        l->all = realloc(l->all, l->room * sizeof *l->all);
        if (l->all == NULL) exit(EXIT_CRASH);
    }
    l->all[l->n++] = (reach){j, mm};
}

static int find_reach(int t) {
    int threads = window_workers_threads();
    reach_list *l = &reach_by_thread[t];
    l->n = 0;
    for (unsigned p = (unsigned)t; p < n_senders; p += (unsigned)threads) {
        reach_first[p] = l->n;
        each_in_range(senders[p], add_reach, l);
        reach_count[p] = l->n - reach_first[p];
    }
    return 1;
}

/* Thread t's receivers (index mod T = t), those with power: each one's
 * draws in the order the frames were sent (sender, then frame), as on one
 * thread; then into their inboxes by start. */
static int deliver_share(int t) {
    int threads = window_workers_threads();
    deliveries *out = &by_thread[t];
    for (unsigned p = 0; p < n_senders; p++) {
        const native_log *log = &native_swarm_robot(senders[p])->log;
        const reach *r = reach_by_thread[p % (unsigned)threads].all + reach_first[p];
        for (unsigned k = 0; k < log->n_sent; k++)
            for (unsigned q = 0; q < reach_count[p]; q++)
                if (r[q].receiver % threads == t && native_swarm_powered(r[q].receiver))
                    deliver_to(t, r[q].receiver, senders[p], frames_sent[senders[p]] + k + 1, &log->sent[k], r[q].mm);
    }
    qsort(out->pending, out->n_pending, sizeof *out->pending, by_receiver_then_start);
    for (size_t k = 0; k < out->n_pending; k++) {
        int receiver = out->pending[k].receiver;
        if (enqueue(out, native_swarm_robot(receiver)->io, out->pending[k].frame))
            heard[receiver]++;
        else
            lost_channel[receiver]++;
        native_swarm_woken(receiver);
    }
    out->n_pending = 0;
    return 1;
}

void native_air_deliver(const int *sent_by, unsigned n) {
    if (n == 0) return;
    if (n > senders_room) {
        senders_room = 2 * n;
        reach_first = realloc(reach_first, senders_room * sizeof *reach_first);
        reach_count = realloc(reach_count, senders_room * sizeof *reach_count);
        if (reach_first == NULL || reach_count == NULL) exit(EXIT_CRASH);
    }
    if (by_thread == NULL) { /* the threads are known once the robots have booted */
        by_thread = calloc((size_t)window_workers_threads(), sizeof *by_thread);
        reach_by_thread = calloc((size_t)window_workers_threads(), sizeof *reach_by_thread);
        if (by_thread == NULL || reach_by_thread == NULL) exit(EXIT_CRASH);
        native_frame_faults_threads(window_workers_threads());
    }
    senders = sent_by;
    n_senders = n;
    window_workers_run_job(find_reach);
    window_workers_run_job(deliver_share);
    for (unsigned p = 0; p < n; p++) frames_sent[sent_by[p]] += native_swarm_robot(sent_by[p])->log.n_sent;
}

uint64_t native_air_overflowed(void) {
    uint64_t n = from_outside.overflowed;
    for (int t = 0; by_thread != NULL && t < window_workers_threads(); t++) n += by_thread[t].overflowed;
    return n;
}

void native_air_counts(int receiver, uint64_t *heard_by, uint64_t *lost_to) {
    *heard_by = heard != NULL ? heard[receiver] : 0;
    *lost_to = lost_channel != NULL ? lost_channel[receiver] : 0;
}
