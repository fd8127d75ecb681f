/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* IR between native robots, at message level: a frame a robot sent in a
 * window reaches every robot in range one window later (the latency), in
 * each receiver's own clock, with the two gain readings its distance gives
 * (the exact mode's model: air/ir_channel.c, air/ir_distance_error.h), lost with the same chance
 * (--ir-loss), and broken where two frames overlap at a receiver. */
#ifndef OPENSWARM_NATIVE_AIR_H
#define OPENSWARM_NATIVE_AIR_H

#include <stdint.h>

#include "sim.h"
#include "native/native_swarm.h"

/* seed: the loss and noise draws', each receiver its own stream of it;
 * latency: nominal cycles from a frame's start to its first pulse at the
 * receivers (at least a window: it must reach them in their future);
 * distance: the error of the distance they read (NULL: none), the exact
 * mode's model (air/ir_distance_error.h). */
void native_air_start(int n, int range_mm, double loss_pct, uint64_t seed, uint32_t nominal_hz,
                      uint64_t latency, const ir_distance_error *distance);
/* Where the robots are now (ir_channel_place's contract), and their
 * positions (x, y in mm, index order) when known: a grid then finds who is
 * in range of whom; NULL: every pair is asked. */
void native_air_place(ir_distance_fn distance, void *ctx, const double *xy);
/* Carrier sense (native_carrier_fn): clear unless a robot in range began
 * a frame before at (sender's own cycles) that is not over; a clear
 * channel's frame is on the air from then. */
int native_air_clear(int sender, uint64_t at);
/* The receivers sender reaches (up to room of them), and their count. */
int native_air_links(int sender, int *receivers, int room);
/* After a window: what the robots sent in it (senders in index order,
 * n of them, their frames in their logs) into the receivers' inboxes, on
 * every thread (window_workers). */
void native_air_deliver(const int *senders, unsigned n);
/* A frame from outside the swarm (the overhead controller's) into the
 * receiver's inbox, between windows, starting in its future. */
void native_air_hand_over(int receiver, const native_frame *f);
/* Frames from robots in range since the start that reached receiver's
 * inbox (heard_by; overlapping ones are broken there) and those lost on
 * the way (lost_to: --ir-loss, a full inbox), as ir_channel_counts. */
void native_air_counts(int receiver, uint64_t *heard_by, uint64_t *lost_to);
/* Frames lost because a receiver's inbox had no room (0 in any sane swarm). */
uint64_t native_air_overflowed(void);

#endif
