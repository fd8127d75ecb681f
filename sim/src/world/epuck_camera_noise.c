/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The e-puck camera's noise (epuck_camera_noise.h). */
#include "world/epuck_camera_noise.h"

#include <math.h>

#include "world/world_random.h"

/* Mixed into the world's seed so the camera's streams are not the other
 * per-robot streams drawn from the same seed (the wheels', the IR's). */
#define CAMERA_STREAM_SALT 0xCA3E7A5EEDull

uint64_t epuck_camera_stream(uint32_t seed, int index) {
    return world_random_stream((uint64_t)seed ^ CAMERA_STREAM_SALT, (uint64_t)index);
}

int epuck_camera_misread(double distance_mm, double pct_per_m, uint64_t *rng) {
    if (pct_per_m <= 0) return 0;
    return world_random_uniform(rng) < pct_per_m / 100.0 * distance_mm / 1000.0;
}

/* One channel's value, `max` its top count, moved by sd counts. */
static unsigned noisy(unsigned value, unsigned max, double sd, uint64_t *rng) {
    long v = (long)value + lround(sd * world_random_normal(rng));
    return v < 0 ? 0u : v > (long)max ? max : (unsigned)v;
}

void epuck_camera_pixel_noise(uint16_t *pixels, size_t n, double sd_counts, uint64_t *rng) {
    if (sd_counts <= 0) return;
    for (size_t k = 0; k < n; k++) {
        unsigned p = pixels[k];
        unsigned r = noisy(p >> 11, 0x1Fu, sd_counts, rng);
        unsigned g = noisy((p >> 5) & 0x3Fu, 0x3Fu, 2 * sd_counts, rng);
        unsigned b = noisy(p & 0x1Fu, 0x1Fu, sd_counts, rng);
        pixels[k] = (uint16_t)(r << 11 | g << 5 | b);
    }
}
