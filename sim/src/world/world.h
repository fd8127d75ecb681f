/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The physical world robots move in: Box2D bodies for the arena's walls,
 * the obstacles, the movable objects and the robots, stepped between the
 * robots' lockstep windows. Motion comes from each robot's motor duties
 * (kilobot_motion.h); the firmware's duty changes are reported as they
 * happen, the physics reads them at each step. */
#ifndef OPENSWARM_WORLD_H
#define OPENSWARM_WORLD_H

#include <stdint.h>

#include "world/kilobot_motion.h"
#include "world/world_spec.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct world world;

#define WORLD_STEP_S 0.01 /* physics at 100 Hz: a Kilobot walks 0.1 mm a step */

/* The bodies of spec, each robot's motors drawn from the seed. */
world *world_create(const world_spec *spec);
void world_destroy(world *w);
const world_spec *world_spec_of(const world *w);
/* Robot i's own motors (its factory calibration comes from them). */
const kilobot_motors_model *world_robot_motors(const world *w, int i);
/* The firmware of robot i set a motor (0 left, 1 right) at time t (s). */
void world_motor_duty(world *w, int i, int side, uint8_t duty, double t);
/* An e-puck's steppers: robot i's wheels turn at these steps/s. */
void world_epuck_wheels(world *w, int i, int16_t left, int16_t right);
/* Advance the physics by one WORLD_STEP_S, ending at time t: the two
 * halves below, one after the other. */
void world_step(world *w, double t);
/* Each robot's twist slots: the steps under way beside the robots and the
 * one being prepared (world_stepper.h). */
#define WORLD_TWIST_SLOTS 3
/* The step's first half, for robots share, share + shares, ...: each
 * one's motors advanced to t and what its legs (or wheels) will walk it
 * at, its noise drawn, kept in its twist slot (below WORLD_TWIST_SLOTS).
 * It touches no Box2D body, so it may run while the steps before,
 * prepared in the other slots, are still taking their bodies
 * (world_stepper.c). */
void world_step_prepare(world *w, double t, unsigned slot, int share, int shares);
/* The second half: the bodies walked as prepared in slot, and Box2D's step. */
void world_step_bodies(world *w, unsigned slot);
void world_robot_pose(const world *w, int i, double *x_mm, double *y_mm, double *heading_deg);
void world_object_position(const world *w, int k, double *x_mm, double *y_mm);
/* 1 when a wall or an obstacle stands between two points (IR cannot pass:
 * they are taller than a Kilobot, whose IR travels by the floor). */
int world_blocks_ir(const world *w, double ax_mm, double ay_mm, double bx_mm, double by_mm);

/* What a ray meets first: a wall (or obstacle), a robot, an object. */
enum { WORLD_HIT_NONE = 0, WORLD_HIT_WALL, WORLD_HIT_ROBOT, WORLD_HIT_OBJECT };
typedef struct world_hit {
    int kind;           /* WORLD_HIT_* */
    int index;          /* the robot's or object's; -1 otherwise */
    double distance_mm; /* max_mm when nothing */
} world_hit;
/* The first body on the ray from (x, y) towards heading_deg, at most
 * max_mm away, robot self (-1: none) not counted: what a sensor of it sees. */
world_hit world_ray(const world *w, int self, double x_mm, double y_mm, double heading_deg,
                    double max_mm);

#ifdef __cplusplus
}
#endif

#endif
