/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The IR channel between robots: a robot hears every other within range.
 *
 * A flash of a robot's IR LED (PB0 high) drives the analog comparator of
 * every other robot within --ir-range (AIN0 above AIN1); robots farther
 * away see nothing, so they neither receive the frame nor sense it as
 * carrier, and frames collide only where both senders reach.
 *
 * Every edge reaches its receivers exactly IR_LATENCY_CYCLES after it left
 * (on the receiver's clock): the robots run in lockstep windows that long,
 * so an edge sent in one window is handed over between the windows and
 * lands in the next, at its exact cycle, whatever order the robots ran in
 * (or on which thread). The 8 us delay is far below anything the wire
 * format times (a bit is 33 us) and the same for every edge, so bit
 * timing is exact.
 *
 * Each receiver keeps its own queue of edges, served by one cycle timer
 * (air/ir_receiver.h).
 *
 * The distance sensors (ADC0 high gain, ADC1 low gain) read what the
 * sender of the last flash gives at its distance: the firmware samples
 * them during a frame (ports/kilobot/src/devices/ir.c), so they show the
 * robot whose frame is being received. Before the first flash they read
 * 0 V, as in the dark. The distance they read is off as a real robot's
 * is (air/ir_distance_error.h): by the pair's own error, and by each
 * frame's, drawn again at every frame's start pulse.
 *
 * Who reaches whom is worked out again whenever the robots move
 * (ir_channel_place, after every physics step in a world), into a spare
 * list swapped in: no allocation per step. A flash costs one step per
 * receiver in range. */
#include <avr_ioport.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sim_io.h>

#include "sim.h"
#include "air/ir_distance_error.h"
#include "air/ir_faults.h"
#include "air/ir_receiver.h"
#include "lockstep.h"
#include "world/world_random.h"

/* A sender and one receiver in its range. */
typedef struct ir_link {
    int to;
    double mm;                          /* how far apart the two are */
    uint32_t high_gain_mv, low_gain_mv; /* the receiver's distance sensors, from this sender */
    double loss;                        /* chance that a frame does not reach it (--ir-loss) */
    avr_cycle_count_t lost_until;       /* sender cycle: the current frame is lost here */
    ir_link_faults faults;              /* --faults: pulses lost or added, the frame cut */
} ir_link;

/* A flash or its end, as the sender's LED did it. */
typedef struct ir_sent {
    avr_cycle_count_t cycle;
    int lit;
    int starts_frame; /* the rise of a frame's start pulse */
} ir_sent;

typedef struct ir_station {
    robot *robot;
    /* As sender: the receivers in range, by index, and this window's edges. */
    ir_link *links, *spare;
    int n_links, links_room, spare_room;
    ir_sent *outbox;
    int n_out, out_room;
    avr_cycle_count_t last_flash;
    uint64_t frames;      /* frames it started, counting the one on the air */
    uint64_t loss_random; /* its own stream of the loss seed: runs lose the same frames on any thread */
    char *frame_reach;    /* with --ir-log: "1, 2; lost at 2" for the frame on the air */
    int reach_room;
    /* With IR faults: the rises of the frame on the air, and whether a
     * link still has added pulses to send. */
    avr_cycle_count_t *rises;
    int n_rises, rises_room;
    int added_pending;
    /* As receiver. */
    ir_receiver receiver;
    uint64_t heard, lost_channel;     /* frames from robots in range: reached it, or lost on the way */
} ir_station;

static ir_station *stations;
static int n_stations;
static int range_mm;
static double loss_pct;
static ir_distance_error distance_error;

#define FRAME_CYCLES ((IR_FRAME_SLOTS + 1) * IR_BIT_CYCLES)
/* A sender's flash this long after its last starts a new frame (within a
 * frame, pulses are at most 9 slots apart). */
#define FRAME_GAP_CYCLES (12 * IR_BIT_CYCLES)

/* For --ir-log: "1, 2; lost at 2", the receivers the frame starting now
 * reaches and those it is lost at. */
static void describe_reach(ir_station *from) {
    /* "; lost at ", then up to 7 characters a receiver in each list */
    from->frame_reach = ir_grow(from->frame_reach, &from->reach_room, 16 * from->n_links + 16, 1);
    int used = 0;
    from->frame_reach[0] = '\0';
    for (int k = 0; k < from->n_links; k++)
        used += sprintf(from->frame_reach + used, "%s%d", k ? ", " : "", from->links[k].to);
    const char *sep = "; lost at ";
    for (int k = 0; k < from->n_links; k++) {
        if (from->links[k].lost_until == 0) continue;
        used += sprintf(from->frame_reach + used, "%s%d", sep, from->links[k].to);
        sep = ", ";
    }
}

static uint32_t millivolts_of(const robot *r, int reading) {
    return (uint32_t)reading * r->avr->avcc / 1024u;
}

/* What the link's receiver's distance sensors read during the sender's
 * current frame. */
static void sense_distance(const ir_station *from, ir_link *l) {
    const robot *to = stations[l->to].robot;
    int mm = ir_distance_sensed(&distance_error, (int)(from - stations), l->to, from->frames, l->mm);
    l->high_gain_mv = millivolts_of(to, ir_high_gain_reading(mm));
    l->low_gain_mv = millivolts_of(to, ir_low_gain_reading(mm));
}

/* At a frame's start pulse, each receiver in range loses the whole frame
 * or none of it, and reads the frame's own distance error. */
static int draw_losses(ir_station *from, avr_cycle_count_t sent) {
    int starts = from->last_flash == 0 || sent - from->last_flash > FRAME_GAP_CYCLES;
    from->last_flash = sent;
    if (!starts) return 0;
    from->frames++;
    for (int k = 0; k < from->n_links; k++) {
        ir_link *l = &from->links[k];
        l->lost_until = l->loss > 0 && world_random_uniform(&from->loss_random) < l->loss ? sent + FRAME_CYCLES : 0;
        if (distance_error.noise_mm > 0) sense_distance(from, l);
    }
    if (ir_log_enabled()) describe_reach(from);
    return 1;
}

/* The LED's pin: noted in the sender's outbox, handed over after the window. */
static void tx_pin(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    ir_station *from = param;
    avr_cycle_count_t sent = from->robot->avr->cycle;
    int starts = 0;
    if (value) {
        ir_log_flash(from->robot, sent, from->frame_reach); /* ends a frame, or starts one */
        starts = draw_losses(from, sent);
    }
    if (from->n_links == 0) return;
    from->outbox = ir_grow(from->outbox, &from->out_room, from->n_out + 1, sizeof(ir_sent));
    from->outbox[from->n_out++] = (ir_sent){sent, value != 0, starts};
}

/* Cycle c of robot from's clock on robot to's (--clock-spread). */
static avr_cycle_count_t on_clock_of(const robot *to, const robot *from, avr_cycle_count_t c) {
    uint32_t f_to = to->avr->frequency, f_from = from->avr->frequency;
    return f_to == f_from ? c : c * f_to / f_from;
}

static ir_edge *window_edges;
static int n_window_edges, window_edges_room;

static int by_receiver_then_time(const void *a, const void *b) {
    const ir_edge *x = a, *y = b;
    if (x->to != y->to) return x->to < y->to ? -1 : 1;
    if (x->at != y->at) return x->at < y->at ? -1 : 1;
    return x->from < y->from ? -1 : x->from > y->from;
}

static void add_edge(const ir_station *from, const ir_link *l, avr_cycle_count_t cycle, int lit,
                     uint32_t latency) {
    const robot *to = stations[l->to].robot;
    window_edges = ir_grow(window_edges, &window_edges_room, n_window_edges + 1, sizeof(ir_edge));
    window_edges[n_window_edges++] = (ir_edge){
        on_clock_of(to, from->robot, cycle) + on_clock_of(to, stations[0].robot, latency),
        lit ? IR_LIT_MV : 0, l->high_gain_mv, l->low_gain_mv, (int)(from - stations), l->to};
}

/* --faults: the sender's frame rises, kept to tell a real pulse from an
 * added one in the same slot. */
static void note_rise(ir_station *from, const ir_sent *sent) {
    if (!sent->lit) return;
    if (sent->starts_frame) from->n_rises = 0;
    from->rises = ir_grow(from->rises, &from->rises_room, from->n_rises + 1, sizeof(avr_cycle_count_t));
    from->rises[from->n_rises++] = sent->cycle;
}

/* --faults: does this edge reach the link's receiver? A powered-off
 * receiver draws no faults: it hears nothing anyway. */
static int passes_faults(ir_station *from, ir_link *l, const ir_sent *sent) {
    if (stations[l->to].robot->off_until != 0) return 0;
    if (sent->starts_frame) {
        ir_faults_frame(&l->faults, from->robot, l->to, sent->cycle);
        if (l->faults.n_added != 0) from->added_pending = 1;
    }
    return ir_faults_pass(&l->faults, from->robot, l->to, sent->cycle, sent->lit);
}

/* --faults: the added pulses whose time the sender has passed. */
static void add_due_pulses(ir_station *from, uint32_t latency) {
    lockstep_settle(from->robot); /* its clock says which are due */
    int pending = 0;
    for (int k = 0; k < from->n_links; k++) {
        ir_link *l = &from->links[k];
        avr_cycle_count_t at;
        while ((at = ir_faults_added_due(&l->faults, from->robot, l->to, from->robot->avr->cycle,
                                         from->rises, from->n_rises)) != 0) {
            add_edge(from, l, at, 1, latency);
            add_edge(from, l, at + IR_ADDED_FLASH_CYCLES, 0, latency);
        }
        pending |= l->faults.next_added < l->faults.n_added;
    }
    from->added_pending = pending;
}

/* A frame starting: each receiver in range counts it heard or lost
 * (ir.csv). A powered-off receiver counts neither: it was not there. */
static void count_frame(const ir_station *from, avr_cycle_count_t start) {
    for (int k = 0; k < from->n_links; k++) {
        ir_station *to = &stations[from->links[k].to];
        if (to->robot->off_until != 0) continue;
        if (start < from->links[k].lost_until)
            to->lost_channel++;
        else
            to->heard++;
    }
}

static void collect(ir_station *from, uint32_t latency) {
    int faults = ir_faults_active();
    for (int e = 0; e < from->n_out; e++) {
        const ir_sent *sent = &from->outbox[e];
        if (sent->starts_frame) count_frame(from, sent->cycle);
        if (faults) note_rise(from, sent);
        for (int k = 0; k < from->n_links; k++) {
            ir_link *l = &from->links[k];
            if (sent->cycle < l->lost_until) continue; /* neither heard nor sensed as carrier */
            if (faults && !passes_faults(from, l, sent)) continue;
            add_edge(from, l, sent->cycle, sent->lit, latency);
        }
    }
    from->n_out = 0;
    if (faults && from->added_pending) add_due_pulses(from, latency);
}

void ir_channel_hand_over(uint32_t latency_cycles) {
    n_window_edges = 0;
    for (int i = 0; i < n_stations; i++)
        if (stations[i].n_out != 0 || stations[i].added_pending) collect(&stations[i], latency_cycles);
    if (n_window_edges == 0) return;
    qsort(window_edges, (size_t)n_window_edges, sizeof(ir_edge), by_receiver_then_time);
    for (int e = 0; e < n_window_edges; e++) ir_receiver_enqueue(&stations[window_edges[e].to].receiver, window_edges[e]);
}

/* ADC readings (0..1023) a receiver gets from a sender d mm away: the high
 * gain amplifier saturates close by, the low gain one reaches further. */
int ir_high_gain_reading(int mm) {
    int v = 1023 * 40 / (mm > 0 ? mm : 1);
    return v > 1023 ? 1023 : v;
}
int ir_low_gain_reading(int mm) {
    int v = 1023 * 15 / (mm > 0 ? mm : 1);
    return v > 1023 ? 1023 : v;
}

/* The receivers sender s reaches now, built in the spare list and swapped
 * in. A receiver still in range keeps the loss drawn for the frame on the air. */
static void link_sender(int s, ir_distance_fn distance, void *ctx) {
    ir_station *from = &stations[s];
    const ir_link *old = from->links;
    int n_old = from->n_links, o = 0, n = 0;
    for (int j = 0; j < n_stations; j++) {
        if (j == s) continue;
        double mm = distance(s, j, ctx);
        if (mm > range_mm) continue;
        from->spare = ir_grow(from->spare, &from->spare_room, n + 1, sizeof(ir_link));
        ir_link *l = &from->spare[n++];
        l->to = j;
        l->mm = mm;
        sense_distance(from, l);
        l->loss = loss_pct / 100.0 * (mm / range_mm) * (mm / range_mm);
        while (o < n_old && old[o].to < j) o++;
        int kept = o < n_old && old[o].to == j;
        l->lost_until = kept ? old[o].lost_until : 0;
        if (kept)
            l->faults = old[o].faults;
        else
            memset(&l->faults, 0, sizeof l->faults);
    }
    ir_link *was = from->links;
    int was_room = from->links_room;
    from->links = from->spare;
    from->links_room = from->spare_room;
    from->n_links = n;
    from->spare = was;
    from->spare_room = was_room;
}

void ir_channel_place(ir_distance_fn distance, void *ctx) {
    for (int s = 0; s < n_stations; s++) link_sender(s, distance, ctx);
}

/* A robot reset or powered off: what it was hearing is gone, and what it
 * was sending stops where it was (its links' added pulses too). */
void ir_channel_robot_reset(int index) {
    ir_station *s = &stations[index];
    ir_receiver_reset(&s->receiver);
    s->added_pending = 0;
    for (int k = 0; k < s->n_links; k++) s->links[k].faults.next_added = s->links[k].faults.n_added;
}

void ir_channel_counts(int receiver, uint64_t *heard, uint64_t *lost_channel) {
    *heard = stations[receiver].heard;
    *lost_channel = stations[receiver].lost_channel;
}

int ir_channel_links(int sender, int *receivers, int room) {
    const ir_station *from = &stations[sender];
    int n = from->n_links < room ? from->n_links : room;
    for (int k = 0; k < n; k++) receivers[k] = from->links[k].to;
    return from->n_links;
}

void ir_channel_attach(robot *all, int n, int range, double loss, uint64_t loss_seed,
                       const ir_distance_error *distance) {
    stations = calloc((size_t)n, sizeof *stations);
    if (stations == NULL) {
        fprintf(stderr, "openswarm-sim: out of memory for %d robots\n", n);
        exit(EXIT_CRASH);
    }
    n_stations = n;
    range_mm = range;
    loss_pct = loss;
    distance_error = distance != NULL ? *distance : (ir_distance_error){0, 0, 0};
    for (int i = 0; i < n; i++) {
        ir_station *s = &stations[i];
        s->robot = &all[i];
        s->loss_random = world_random_stream(loss_seed, (uint64_t)i);
        avr_irq_register_notify(avr_io_getirq(all[i].avr, AVR_IOCTL_IOPORT_GETIRQ('B'), IOPORT_IRQ_PIN0),
                                tx_pin, s);
        ir_receiver_attach(&s->receiver, &all[i]);
    }
}
