/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* One robot's IR receiver, as the IR channel (ir_channel.c) feeds it: the
 * edges on their way to its comparator, in time order, each applied at
 * its exact cycle by one cycle timer of the receiver's MCU (simavr 1.6 has
 * a pool of 64 timers per MCU: one per sender and edge ran out in swarms
 * of 64), and its distance sensors (ADC0 high gain, ADC1 low gain) set to
 * what the edge's sender gives at its distance. */
#ifndef OPENSWARM_IR_RECEIVER_H
#define OPENSWARM_IR_RECEIVER_H

#include <stdint.h>

#include "sim.h"

/* An edge on its way to a receiver, at a cycle of the receiver's clock. */
typedef struct ir_edge {
    avr_cycle_count_t at;
    uint32_t level; /* AIN0 millivolts */
    uint32_t high_gain_mv, low_gain_mv;
    int from, to;
} ir_edge;

typedef struct ir_receiver {
    robot *robot;
    avr_irq_t *ain0, *high_gain, *low_gain; /* its comparator and distance inputs */
    ir_edge *queue; /* edges due, in time order, from head on */
    int head, tail, queue_room;
    avr_cycle_count_t next_free;
    uint32_t sensed_high, sensed_low; /* last applied to ADC0 / ADC1 */
} ir_receiver;

/* The robot's comparator and distance inputs, in the dark. */
void ir_receiver_attach(ir_receiver *r, robot *listener);
/* Queue an edge for its cycle (a powered-off robot hears nothing). */
void ir_receiver_enqueue(ir_receiver *r, ir_edge e);
/* The robot reset or powered off: what it was hearing is gone. */
void ir_receiver_reset(ir_receiver *r);

/* items with room for at least needed of size bytes each (the channel's
 * lists grow by doubling, never per step); exits if memory runs out. */
void *ir_grow(void *items, int *room, int needed, size_t size);

#endif
