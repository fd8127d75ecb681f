/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The physics stepped beside the robots: a step begun at time t (when the
 * robots reach it) runs while they go on to the next step's time, on a
 * thread of its own or, with one thread, at once - the same results
 * either way, since nothing the robots do meanwhile reaches it: their
 * motor changes wait here and go in before the next step, as they did
 * when the physics stepped between their windows. The robots see where
 * the step left them one step later (world_run.c). */
#ifndef OPENSWARM_WORLD_STEPPER_H
#define OPENSWARM_WORLD_STEPPER_H

#include <stdint.h>

#include "world/world.h"

/* n robots in physics; threaded: step on a thread of its own. */
void world_stepper_start(world *physics, int n, int threaded);
/* Robot index set a motor (0 left, 1 right) at time t (s): kept for the
 * next step. From any thread, one robot's changes from one at a time. */
void world_stepper_motor(int index, int side, uint8_t duty, double t);
/* The motor changes kept go in, and the step ending at t is prepared
 * (world_step_prepare, shared over the robots' threads as their windows
 * are: call it between windows): while the step begun before may still
 * run. */
void world_stepper_prepare(double t);
/* The step prepared begins, once the one before it is over. */
void world_stepper_begin(void);
/* Until the step begun is over (nothing to wait for when none is). */
void world_stepper_wait(void);
void world_stepper_stop(void);

#endif
