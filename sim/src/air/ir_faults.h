/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* IR faults on one link (a sender and one receiver in its range): pulses
 * of a frame lost, pulses added in its empty slots (each slot flips with
 * --faults flip=PCT), and frames cut short (cut=PCT). The channel
 * (ir_channel.c) asks, edge by edge as it hands them over, whether each
 * passes, and which added pulses are due; everything is drawn there, on
 * the main thread, in a fixed order, so a run is the same on any number
 * of threads. */
#ifndef OPENSWARM_IR_FAULTS_H
#define OPENSWARM_IR_FAULTS_H

#include "sim.h"

#define IR_MAX_ADDED_PULSES 16 /* a frame's added pulses at one receiver, at most */
#define IR_ADDED_FLASH_CYCLES 12 /* an added pulse is as long as a sender's flash */

typedef struct ir_link_faults {
    avr_cycle_count_t start;    /* the frame's start pulse, sender's cycles; 0: none */
    avr_cycle_count_t cut_from; /* the frame's pulses from here on are lost; 0: not cut */
    avr_cycle_count_t added[IR_MAX_ADDED_PULSES]; /* added pulses, sender's cycles, in order */
    int n_added, next_added;
    int rise_passed; /* the last rising edge reached the receiver: so does its fall */
} ir_link_faults;

/* The chances, in percent, and the seed; both 0: no IR faults. */
void ir_faults_configure(double flip_pct, double cut_pct, uint64_t seed);
int ir_faults_active(void);
/* A frame from robot `from` starts at its cycle `start` on the link to `to`:
 * draw whether it is cut and which empty slots get a pulse. */
void ir_faults_frame(ir_link_faults *f, const robot *from, int to, avr_cycle_count_t start);
/* Does this edge of the sender's (at its cycle, rising or falling) reach
 * the receiver? */
int ir_faults_pass(ir_link_faults *f, const robot *from, int to, avr_cycle_count_t cycle, int lit);
/* The next added pulse the sender's clock has passed by now (its cycle),
 * or 0. rises: the frame's real pulses so far; an added pulse on one of
 * them flips nothing and is dropped unlogged. */
avr_cycle_count_t ir_faults_added_due(ir_link_faults *f, const robot *from, int to,
                                      avr_cycle_count_t now, const avr_cycle_count_t *rises,
                                      int n_rises);

#endif
