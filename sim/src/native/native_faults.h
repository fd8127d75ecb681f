/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* --faults in the native mode: the exact mode's plan (faults/fault_plan.c:
 * the same spec and seed give the same faults at the same times), what a
 * reset and a power cut do to a native robot, and the IR faults drawn on
 * whole frames (native_frame_faults.h). A robot's blank calibration and
 * clock drift are set as native_run.c configures it. */
#ifndef OPENSWARM_NATIVE_FAULTS_H
#define OPENSWARM_NATIVE_FAULTS_H

#include <stdint.h>

#include "sim.h"

/* Before the robots are configured: draw the faults of o's robots (none
 * without --faults). -1 after a message. */
int native_faults_start(const options *o);
/* The robots have booted: their resets and brown-outs can fire. */
void native_faults_attach(uint32_t nominal_hz);
/* After a window whose frames were delivered, ending at cycle end of the
 * nominal clock: its frames' faults logged, then the resets, brown-outs
 * and power returns due. */
void native_faults_after_window(uint64_t end);

#endif
