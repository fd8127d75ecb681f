/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The overhead controller in the native mode (--ohc): each message
 * reaches every robot as a whole frame in its inbox, its first pulse at
 * the cycle of the robot's own clock where the exact mode's first flash
 * falls (air/overhead_controller.c), whatever the robot's position. */
#ifndef OPENSWARM_NATIVE_OHC_H
#define OPENSWARM_NATIVE_OHC_H

#include <stdint.h>

#include "sim.h"

/* The messages o asks for, to n robots, windows cut by a nominal_hz clock. */
void native_ohc_start(const options *o, int n, uint32_t nominal_hz);
/* Between windows: the messages whose first pulse comes before until
 * (nominal cycles: the next window's end) into every robot's inbox. */
void native_ohc_deliver(uint64_t until);

#endif
