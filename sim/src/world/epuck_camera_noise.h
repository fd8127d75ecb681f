/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The e-puck camera's noise (the world file's "camera": "pixel_noise",
 * "misread_pct_per_m"; docs/world.md, "camera noise"): both off unless
 * given, and then drawn from the robot's own camera stream. A setting of
 * 0 draws nothing, so a world without noise gets exactly the frames it
 * got before the model. */
#ifndef OPENSWARM_EPUCK_CAMERA_NOISE_H
#define OPENSWARM_EPUCK_CAMERA_NOISE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The state that starts robot `index`'s camera stream for a world's seed:
 * a stream of its own, apart from its proximity sensors' and wheels'. */
uint64_t epuck_camera_stream(uint32_t seed, int index);
/* Whether a robot's or an object's column, distance_mm from the robot's
 * centre, shows the wall behind it instead: with pct_per_m percent chance
 * per metre (at most always). */
int epuck_camera_misread(double distance_mm, double pct_per_m, uint64_t *rng);
/* Each RGB565 channel of each of the n pixels moved by a gaussian draw of
 * its own, rounded to a count and kept within the channel: red and blue
 * (5 bits) with standard deviation sd_counts, green (6 bits) with twice
 * that, the same share of its range. */
void epuck_camera_pixel_noise(uint16_t *pixels, size_t n, double sd_counts, uint64_t *rng);

#ifdef __cplusplus
}
#endif

#endif
