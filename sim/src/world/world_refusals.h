/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The options a run in a world refuses, each with a message naming the
 * option and what to do instead; world_options_check (world_run.c) asks
 * them before the run starts. Each returns 0, or -1 after its message. */
#ifndef OPENSWARM_WORLD_REFUSALS_H
#define OPENSWARM_WORLD_REFUSALS_H

#include "sim.h"
#include "world/world_spec.h"

/* Options the world file sets itself (--robots, --uid, --light...). */
int world_refuse_owned_options(const options *o);
/* Options that watch or drive a Kilobot's MCU, in a world of e-pucks. */
int world_refuse_kilobot_only(const options *o);
/* A run whose samples would write more rows than an output file holds. */
int world_sample_count_check(const options *o, const world_spec *spec);

#endif
