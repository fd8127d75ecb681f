/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* --faults flip=PCT and cut=PCT in the native mode, where a frame travels
 * whole: the exact mode's faults drawn on the frame's 130 slots (each
 * slot flips with flip's chance at each receiver, a frame is cut short
 * from a slot drawn at random with cut's), logged as the exact mode logs
 * them (pulse-lost, pulse-added, frame-cut), and the frame they leave
 * decoded by the firmware's own decoder (ports/kilobot/src/devices/ir_wire.h):
 * whole, with the bytes it read (a flipped data bit fails the CRC at the
 * receiver, as on the robot), or broken, or collided, or nothing at all.
 * Draws come from each receiver's own stream of the faults' seed, in the
 * order its frames are delivered: the same on any number of threads. */
#ifndef OPENSWARM_NATIVE_FRAME_FAULTS_H
#define OPENSWARM_NATIVE_FRAME_FAULTS_H

#include <stdint.h>

#include "openswarm/native_robot.h"

/* The chances in percent (both 0: nothing to do), the faults' seed, the
 * robots. -1 if out of memory. */
int native_frame_faults_start(double flip_pct, double cut_pct, uint64_t seed, int n_robots);
int native_frame_faults_on(void);
/* The threads that deliver frames (each calls apply with its own number). */
void native_frame_faults_threads(int n);
/* The frame the sender sent at its cycle at (its clock from_hz), as
 * receiver to (clock to_hz) gets it: f is changed to what the faults
 * leave of it. 0: it arrives; -1: no pulse of it is left. */
int native_frame_faults_apply(int thread, int from, int to, uint64_t at, uint32_t from_hz, uint32_t to_hz,
                              native_frame *f);
/* The window's faults into the fault log, by time, receiver and order
 * drawn (main thread). */
void native_frame_faults_log(void);

#endif
