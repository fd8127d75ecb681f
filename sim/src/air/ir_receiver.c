/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* One robot's IR receiver (ir_receiver.h). Edges to one receiver stay at
 * least EDGE_GAP cycles apart: simavr 1.6 updates the comparator a cycle
 * after its input changes, and a second change before that update
 * replaces the first: the pulse would vanish. */
#include "air/ir_receiver.h"

#include <avr_acomp.h>
#include <avr_adc.h>
#include <stdlib.h>
#include <sim_cycle_timers.h>
#include <sim_io.h>

#include "lockstep.h"

#define AIN1_MV 500 /* the comparator's threshold */
#define EDGE_GAP 8

void *ir_grow(void *items, int *room, int needed, size_t size) {
    if (needed <= *room) return items;
    int more = *room ? *room * 2 : 16;
    while (more < needed) more *= 2;
    void *bigger = realloc(items, (size_t)more * size);
    if (bigger == NULL) {
        fprintf(stderr, "openswarm-sim: out of memory for the IR channel\n");
        exit(EXIT_CRASH);
    }
    *room = more;
    return bigger;
}

static void apply(ir_receiver *s, const ir_edge *e) {
    if (e->level != 0 && (s->sensed_high != e->high_gain_mv || s->sensed_low != e->low_gain_mv)) {
        s->sensed_high = e->high_gain_mv;
        s->sensed_low = e->low_gain_mv;
        avr_raise_irq(s->high_gain, e->high_gain_mv);
        avr_raise_irq(s->low_gain, e->low_gain_mv);
    }
    avr_raise_irq(s->ain0, e->level);
}

/* The receiver's timer: every edge due by now, then wait for the next. */
static avr_cycle_count_t deliver(struct avr_t *avr, avr_cycle_count_t when, void *param) {
    (void)when;
    ir_receiver *s = param;
    while (s->head < s->tail && s->queue[s->head].at <= avr->cycle) apply(s, &s->queue[s->head++]);
    if (s->head == s->tail) {
        s->head = s->tail = 0;
        return 0;
    }
    return s->queue[s->head].at; /* the same timer, again then */
}

void ir_receiver_enqueue(ir_receiver *s, ir_edge e) {
    if (s->robot->off_until != 0) return; /* powered off (--faults brownout): deaf */
    lockstep_settle(s->robot); /* an edge due at once comes after the instruction it has reached */
    avr_t *avr = s->robot->avr;
    if (e.at <= avr->cycle) e.at = avr->cycle + 1;
    if (e.at < s->next_free) e.at = s->next_free;
    s->next_free = e.at + EDGE_GAP;
    int idle = s->head == s->tail;
    s->queue = ir_grow(s->queue, &s->queue_room, s->tail + 1, sizeof(ir_edge));
    s->queue[s->tail++] = e;
    if (idle) avr_cycle_timer_register(avr, e.at - avr->cycle, deliver, s);
    s->robot->doze_until = 0; /* a new timer: look at it again */
}

void ir_receiver_reset(ir_receiver *s) {
    if (s->head != s->tail) avr_cycle_timer_cancel(s->robot->avr, deliver, s);
    s->head = s->tail = 0;
    s->next_free = 0;
    s->sensed_high = s->sensed_low = 0;
}

void ir_receiver_attach(ir_receiver *s, robot *listener) {
    avr_t *avr = listener->avr;
    s->robot = listener;
    s->ain0 = avr_io_getirq(avr, AVR_IOCTL_ACOMP_GETIRQ, ACOMP_IRQ_AIN0);
    s->high_gain = avr_io_getirq(avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_ADC0);
    s->low_gain = avr_io_getirq(avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_ADC1);
    avr_raise_irq(avr_io_getirq(avr, AVR_IOCTL_ACOMP_GETIRQ, ACOMP_IRQ_AIN1), AIN1_MV);
    avr_raise_irq(s->ain0, 0);
}
