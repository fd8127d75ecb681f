/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A world's e-pucks in the native mode: their controller (an e-puck app,
 * or a plain loop, built with `openswarm build --native`) loaded into this
 * process and run step by step beside the physics, each robot its own RAM
 * image (native_swarm.h), instead of one process each over a pipe. */
#ifndef OPENSWARM_NATIVE_EPUCK_RUN_H
#define OPENSWARM_NATIVE_EPUCK_RUN_H

#include "world/epuck_controllers.h"

extern const epuck_controllers native_epucks;

#endif
