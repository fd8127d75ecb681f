/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* What an e-puck's sensors read in the world: its eight IR proximity
 * sensors and its camera, from rays cast in the physics (world_ray). The
 * figures and their sources are in docs/world.md. */
#ifndef OPENSWARM_EPUCK_SENSORS_H
#define OPENSWARM_EPUCK_SENSORS_H

#include <stdint.h>

#include "world/world.h"

#ifdef __cplusplus
extern "C" {
#endif

#define EPUCK_SENSOR_COUNT 8
#define EPUCK_FRAME_WIDTH 40
#define EPUCK_FRAME_HEIGHT 30

/* The ADC's two samples of each sensor (epuck_proximity_samples): with
 * the emitters off and at the end of their pulse; rng: the robot's noise. */
void epuck_proximity_read(const world *w, int robot, uint16_t off[EPUCK_SENSOR_COUNT],
                          uint16_t pulsed[EPUCK_SENSOR_COUNT], uint64_t *rng);
/* The reflected counts at distance_mm from the sensor, the model's mean,
 * less what it reads with nothing near (as calibrated readings are). */
double epuck_reflection_counts(double distance_mm);
/* A frame as the camera takes it: RGB565, row after row. Robots show
 * green, objects red, walls white (as in the experiment the paper
 * reproduces); each column is the colour of the first body its ray meets.
 * rng: the robot's camera stream (epuck_camera_stream), which the world's
 * camera noise draws from; without noise nothing is drawn. */
void epuck_camera_render(const world *w, int robot,
                         uint16_t pixels[EPUCK_FRAME_WIDTH * EPUCK_FRAME_HEIGHT], uint64_t *rng);

#ifdef __cplusplus
}
#endif

#endif
