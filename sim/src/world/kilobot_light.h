/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* What a Kilobot's ambient light sensor sees (docs/world.md, "Light"): the
 * room's ambient light plus each lamp's, less what the robot's own battery
 * shades. The phototransistor sits at the rim of the robot's top, beside
 * the coin cell; a lamp low enough and on the far side of the cell is
 * hidden behind it, so the reading changes as the robot turns - what the
 * classic move-to-light lab steers by. */
#ifndef OPENSWARM_KILOBOT_LIGHT_H
#define OPENSWARM_KILOBOT_LIGHT_H

#include "world/world_spec.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A lamp's height when the world file gives none (world.json
 * light.sources[].height_mm). */
#define KILOBOT_LIGHT_DEFAULT_HEIGHT_MM 150.0

/* The sensor's input in mV (before it clips at the supply) of a robot
 * whose body's centre is at (x, y), facing heading_deg. */
double kilobot_light_mv(const world_spec *spec, double x_mm, double y_mm, double heading_deg);

#ifdef __cplusplus
}
#endif

#endif
