/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Seeded random numbers (world_random.h). */
#include "world/world_random.h"

#include <math.h>

#define PI 3.14159265358979323846

uint64_t world_random_next(uint64_t *state) {
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

uint64_t world_random_stream(uint64_t seed, uint64_t index) {
    uint64_t state = seed;
    uint64_t mixed_seed = world_random_next(&state);
    state = mixed_seed ^ index;
    return world_random_next(&state);
}

double world_random_uniform(uint64_t *state) {
    return (double)(world_random_next(state) >> 11) / 9007199254740992.0;
}

double world_random_normal(uint64_t *state) {
    double u = world_random_uniform(state), v = world_random_uniform(state);
    return sqrt(-2.0 * log(1.0 - u)) * cos(2.0 * PI * v);
}
