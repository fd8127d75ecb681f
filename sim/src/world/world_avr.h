/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The exact mode's simulated MCUs as the robots of a world. */
#ifndef OPENSWARM_WORLD_AVR_H
#define OPENSWARM_WORLD_AVR_H

#include "sim.h"

/* Robot index's analog inputs carry its own noise (before they are set). */
void world_avr_robot_noise(robot *r, int index);
/* The robots are loaded: follow their motors, place them on the IR
 * channel, open the outputs; -1 after a message. */
int world_avr_start(robot *robots, int n, const options *o, uint32_t nominal_hz);

#endif
