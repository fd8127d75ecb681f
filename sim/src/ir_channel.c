/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The IR channel between robots: every robot hears every other.
 *
 * A flash of a robot's IR LED (PB0 high) drives the analog comparator of
 * every other robot (AIN0 above AIN1) at the same cycle: if the receiver is
 * behind in its lockstep window the edge is scheduled at that cycle,
 * otherwise as soon as it can be (at most a window late, a quarter bit).
 * Edges to one receiver stay at least EDGE_GAP cycles apart: simavr 1.6
 * updates the comparator a cycle after its input changes, and a second
 * change before that update (two edges closer than the instruction being
 * executed) replaces the first: the pulse would vanish.
 * The distance sensors (ADC0 high gain, ADC1 low gain) read what a robot
 * at --distance millimetres would. */
#include <avr_acomp.h>
#include <avr_adc.h>
#include <avr_ioport.h>
#include <sim_cycle_timers.h>
#include <sim_io.h>

#include "sim.h"

#define AIN1_MV 500 /* the comparator's threshold */
#define LIT_MV 1000
#define EDGE_GAP 8

/* One edge on its way from a sender to a receiver; rises and falls have
 * their own, so a pending rise is never replaced by its fall. */
typedef struct ir_edge {
    robot *to;
    uint32_t level; /* AIN0 millivolts to apply */
} ir_edge;

typedef struct ir_link {
    ir_edge edge[2]; /* [0] fall, [1] rise */
    avr_cycle_count_t next_free; /* earliest receiver cycle for the next edge */
} ir_link;

static robot *robots_of;
static int n_robots;
static ir_link links[MAX_ROBOTS * MAX_ROBOTS];

static void apply(robot *to, uint32_t millivolts) {
    avr_raise_irq(avr_io_getirq(to->avr, AVR_IOCTL_ACOMP_GETIRQ, ACOMP_IRQ_AIN0), millivolts);
}

static avr_cycle_count_t deliver(struct avr_t *avr, avr_cycle_count_t when, void *param) {
    (void)avr;
    (void)when;
    ir_edge *e = param;
    apply(e->to, e->level);
    return 0;
}

static void tx_pin(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    robot *from = param;
    avr_cycle_count_t sent = from->avr->cycle;
    for (int j = 0; j < n_robots; j++) {
        robot *to = &robots_of[j];
        if (to == from) continue;
        ir_link *l = &links[from->index * MAX_ROBOTS + j];
        ir_edge *e = &l->edge[value ? 1 : 0];
        e->to = to;
        e->level = value ? LIT_MV : 0;
        avr_cycle_count_t now = to->avr->cycle;
        avr_cycle_count_t at = sent > now ? sent : now;
        if (at < l->next_free) at = l->next_free;
        l->next_free = at + EDGE_GAP;
        avr_cycle_timer_register(to->avr, at - now + 1, deliver, e);
    }
}

/* ADC readings (0..1023) a receiver gets from a sender d mm away: the high
 * gain amplifier saturates close by, the low gain one reaches further. */
int ir_high_gain_reading(int mm);
int ir_low_gain_reading(int mm);
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

void ir_channel_attach(robot *all, int n, int distance_mm) {
    robots_of = all;
    n_robots = n;
    for (int i = 0; i < n; i++) {
        robot *r = &all[i];
        avr_irq_register_notify(avr_io_getirq(r->avr, AVR_IOCTL_IOPORT_GETIRQ('B'), IOPORT_IRQ_PIN0),
                                tx_pin, r);
        avr_raise_irq(avr_io_getirq(r->avr, AVR_IOCTL_ACOMP_GETIRQ, ACOMP_IRQ_AIN1), AIN1_MV);
        avr_raise_irq(avr_io_getirq(r->avr, AVR_IOCTL_ACOMP_GETIRQ, ACOMP_IRQ_AIN0), 0);
        avr_raise_irq(avr_io_getirq(r->avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_ADC0),
                      millivolts_of(r, ir_high_gain_reading(distance_mm)));
        avr_raise_irq(avr_io_getirq(r->avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_ADC1),
                      millivolts_of(r, ir_low_gain_reading(distance_mm)));
    }
}
