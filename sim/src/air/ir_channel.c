/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The IR channel between robots: a robot hears every other within range.
 *
 * A flash of a robot's IR LED (PB0 high) drives the analog comparator of
 * every other robot within --ir-range (AIN0 above AIN1) at the same cycle;
 * robots farther away see nothing, so they neither receive the frame nor
 * sense it as carrier, and frames collide only where both senders reach.
 * The pairs in range are listed once, when the robots are placed: a flash
 * costs one step per receiver in range, nothing per cycle. If the receiver is
 * behind in its lockstep window the edge is scheduled at that cycle,
 * otherwise as soon as it can be (at most a window late, a quarter bit).
 * Edges to one receiver stay at least EDGE_GAP cycles apart: simavr 1.6
 * updates the comparator a cycle after its input changes, and a second
 * change before that update (two edges closer than the instruction being
 * executed) replaces the first: the pulse would vanish.
 * The distance sensors (ADC0 high gain, ADC1 low gain) read what the
 * sender of the last flash would give at its distance: the firmware samples
 * them during a frame (after its start and stop pulses, ports/kilobot/src/
 * devices/ir.c), so they show the robot whose frame is being received.
 * Before the first flash they read 0 V, as in the dark. */
#include <avr_acomp.h>
#include <avr_adc.h>
#include <avr_ioport.h>
#include <math.h>
#include <string.h>
#include <sim_cycle_timers.h>
#include <sim_io.h>

#include "sim.h"

#define AIN1_MV 500 /* the comparator's threshold */
#define EDGE_GAP 8

typedef struct ir_link ir_link;

/* One edge on its way from a sender to a receiver; rises and falls have
 * their own, so a pending rise is never replaced by its fall. */
typedef struct ir_edge {
    ir_link *link;
    uint32_t level; /* AIN0 millivolts to apply */
} ir_edge;

/* A sender and one receiver in its range. */
struct ir_link {
    robot *to;
    uint32_t high_gain_mv, low_gain_mv; /* the receiver's distance sensors, from this sender */
    ir_edge edge[2];                    /* [0] fall, [1] rise */
    avr_cycle_count_t next_free;        /* earliest receiver cycle for the next edge */
    double loss;                        /* chance that a frame does not reach it (--ir-loss) */
    avr_cycle_count_t lost_until;       /* sender cycle: the current frame's edges are lost */
};

/* links[s][0 .. n_links[s] - 1]: the receivers sender s reaches. */
static ir_link links[MAX_ROBOTS][MAX_ROBOTS - 1];
static int n_links[MAX_ROBOTS];
/* The same, as text for --ir-log: "1, 2"; and for the frame on the air,
 * with the receivers --ir-loss took it from: "1, 2; lost at 2". */
static char in_range[MAX_ROBOTS][MAX_ROBOTS * 4];
static char frame_reach[MAX_ROBOTS][MAX_ROBOTS * 8 + 16];
/* Until about this cycle a frame may be on the air (a flash plus two frame
 * times: the sender's cycles are within a few percent of the others'). */
static avr_cycle_count_t busy_until;
#define FRAME_CYCLES ((IR_FRAME_SLOTS + 1) * IR_BIT_CYCLES)
/* A sender's flash this long after its last starts a new frame (within a
 * frame, pulses are at most 9 slots apart). */
#define FRAME_GAP_CYCLES (12 * IR_BIT_CYCLES)
static avr_cycle_count_t last_flash[MAX_ROBOTS];
static uint32_t loss_random = 0x2545F491u; /* fixed: every run loses the same frames */

avr_cycle_count_t ir_channel_busy_until(void) { return busy_until; }
/* The link each robot's distance sensors read now, NULL before any. */
static const ir_link *sensed[MAX_ROBOTS];

static void set_input(avr_t *avr, uint32_t ioctl, int irq, uint32_t millivolts) {
    avr_raise_irq(avr_io_getirq(avr, ioctl, irq), millivolts);
}

static void sense(const ir_link *l) {
    if (sensed[l->to->index] == l) return;
    sensed[l->to->index] = l;
    avr_t *avr = l->to->avr;
    set_input(avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_ADC0, l->high_gain_mv);
    set_input(avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_ADC1, l->low_gain_mv);
}

static avr_cycle_count_t deliver(struct avr_t *avr, avr_cycle_count_t when, void *param) {
    (void)avr;
    (void)when;
    ir_edge *e = param;
    if (e->level != 0) sense(e->link);
    set_input(e->link->to->avr, AVR_IOCTL_ACOMP_GETIRQ, ACOMP_IRQ_AIN0, e->level);
    return 0;
}

/* A number in [0, 1) from a fixed xorshift sequence. */
static double next_random(void) {
    loss_random ^= loss_random << 13;
    loss_random ^= loss_random >> 17;
    loss_random ^= loss_random << 5;
    return loss_random / 4294967296.0;
}

/* At a frame's start pulse, each receiver in range loses the whole frame
 * or none of it. */
static void draw_losses(robot *from, avr_cycle_count_t sent) {
    int starts = last_flash[from->index] == 0 || sent - last_flash[from->index] > FRAME_GAP_CYCLES;
    last_flash[from->index] = sent;
    if (!starts) return;
    char *lost = frame_reach[from->index];
    strcpy(lost, in_range[from->index]);
    const char *sep = "; lost at ";
    for (int k = 0; k < n_links[from->index]; k++) {
        ir_link *l = &links[from->index][k];
        l->lost_until = l->loss > 0 && next_random() < l->loss ? sent + FRAME_CYCLES : 0;
        if (l->lost_until == 0) continue;
        size_t used = strlen(lost);
        snprintf(lost + used, sizeof frame_reach[0] - used, "%s%d", sep, l->to->index);
        sep = ", ";
    }
}

/* Cycle c of robot from's clock on robot to's (--clock-spread). */
static avr_cycle_count_t on_clock_of(const robot *to, const robot *from, avr_cycle_count_t c) {
    uint32_t f_to = to->avr->frequency, f_from = from->avr->frequency;
    return f_to == f_from ? c : c * f_to / f_from;
}

static void tx_pin(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    robot *from = param;
    avr_cycle_count_t sent = from->avr->cycle;
    if (value) {
        ir_log_flash(from, sent, frame_reach[from->index]); /* ends a frame, or starts one */
        draw_losses(from, sent);
    }
    if (n_links[from->index] != 0 && sent + 2 * FRAME_CYCLES > busy_until)
        busy_until = sent + 2 * FRAME_CYCLES;
    for (int k = 0; k < n_links[from->index]; k++) {
        ir_link *l = &links[from->index][k];
        if (sent < l->lost_until) continue; /* neither heard nor sensed as carrier */
        ir_edge *e = &l->edge[value ? 1 : 0];
        robot *to = l->to;
        avr_cycle_count_t now = to->avr->cycle;
        avr_cycle_count_t heard = on_clock_of(to, from, sent);
        avr_cycle_count_t at = heard > now ? heard : now;
        if (at < l->next_free) at = l->next_free;
        l->next_free = at + EDGE_GAP;
        avr_cycle_timer_register(to->avr, at - now + 1, deliver, e);
    }
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

static uint32_t millivolts_of(const robot *r, int reading) {
    return (uint32_t)reading * r->avr->avcc / 1024u;
}

/* List the receivers sender s reaches, with what their sensors read. */
static void link_sender(robot *all, int n, int s, const placement *p, int range_mm, double loss_pct) {
    for (int j = 0; j < n; j++) {
        double mm = placement_distance(p, s, j);
        if (j == s || mm > range_mm) continue;
        ir_link *l = &links[s][n_links[s]++];
        l->to = &all[j];
        l->edge[0] = (ir_edge){l, 0};
        l->edge[1] = (ir_edge){l, IR_LIT_MV};
        l->high_gain_mv = millivolts_of(l->to, ir_high_gain_reading((int)lround(mm)));
        l->low_gain_mv = millivolts_of(l->to, ir_low_gain_reading((int)lround(mm)));
        l->loss = loss_pct / 100.0 * (mm / range_mm) * (mm / range_mm);
        size_t used = strlen(in_range[s]);
        snprintf(in_range[s] + used, sizeof in_range[s] - used, "%s%d", used ? ", " : "", j);
    }
}

void ir_channel_attach(robot *all, int n, const placement *p, int range_mm, double loss_pct) {
    for (int i = 0; i < n; i++) {
        robot *r = &all[i];
        avr_irq_register_notify(avr_io_getirq(r->avr, AVR_IOCTL_IOPORT_GETIRQ('B'), IOPORT_IRQ_PIN0),
                                tx_pin, r);
        set_input(r->avr, AVR_IOCTL_ACOMP_GETIRQ, ACOMP_IRQ_AIN1, AIN1_MV);
        set_input(r->avr, AVR_IOCTL_ACOMP_GETIRQ, ACOMP_IRQ_AIN0, 0);
        link_sender(all, n, i, p, range_mm, loss_pct);
    }
}
