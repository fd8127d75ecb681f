/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A world of e-pucks (world.json "robot": "epuck"): each robot's
 * controller runs as a process of its own on the host port
 * (ports/epuck/host), or natively in this process (native/native_epuck.c),
 * in lockstep with the physics: every 10 ms step the
 * world hands each its sensors, lets it run the step, and moves its wheels
 * as it set them. Not cycle-exact: docs/world.md says what this mode shows
 * and what it cannot. */
#ifndef OPENSWARM_EPUCK_RUN_H
#define OPENSWARM_EPUCK_RUN_H

#include "sim.h"
#include "world/epuck_controllers.h"
#include "world/world.h"

/* Run the world for o->seconds with controllers o->robot_elf[i], run
 * where says (epuck_pipes, native_epucks); the exit
 * status (0, EXIT_CRASH when a controller died, EXIT_FAULT on a kernel
 * fault, EXIT_USAGE when the outputs could not be written). */
int epuck_world_run(const options *o, const world_spec *spec, world *physics, const epuck_controllers *where);

#endif
