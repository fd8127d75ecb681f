/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The physics stepped beside the robots: a step begun at time t (when the
 * robots reach it) runs while they go on, on a thread of its own or, with
 * one thread, at once - the same results either way, since nothing the
 * robots do meanwhile reaches it: their motor changes wait here and go in
 * before the next step. Up to WORLD_STEPS_AHEAD steps are under way at
 * once, so the robots sense where a step left them WORLD_STEPS_AHEAD
 * steps later (world_run.c): the robots' and the physics' threads each
 * run on while the other's step of the moment is slow, rather than both
 * meeting at every step. */
#ifndef OPENSWARM_WORLD_STEPPER_H
#define OPENSWARM_WORLD_STEPPER_H

#include <stdint.h>

#include "world/world.h"

/* Steps begun and not yet seen by the robots, at most. */
#define WORLD_STEPS_AHEAD 2

/* Where a step left the bodies. */
typedef struct world_pose {
    double x_mm, y_mm, heading_deg;
} world_pose;
typedef struct world_poses {
    world_pose *robots;
    world_point *objects;
} world_poses;

/* n robots and n_objects objects in physics; threaded: step on a thread
 * of its own. */
void world_stepper_start(world *physics, int n, int n_objects, int threaded);
/* Robot index set a motor (0 left, 1 right) at time t (s): kept for the
 * next step. From any thread, one robot's changes from one at a time. */
void world_stepper_motor(int index, int side, uint8_t duty, double t);
/* The motor changes kept go in, and the step ending at t is prepared
 * (world_step_prepare, shared over the robots' threads as their windows
 * are: call it between windows): while the steps begun before may still
 * run. */
void world_stepper_prepare(double t);
/* The step prepared begins, after those begun before it. */
void world_stepper_begin(void);
/* Steps begun and not yet taken by world_stepper_take. */
int world_stepper_pending(void);
/* Once the oldest of them is over: where it left the bodies (valid until
 * the next world_stepper_begin). */
const world_poses *world_stepper_take(void);
void world_stepper_stop(void);

#endif
