/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The distance-estimate error (ir_distance_error.h). */
#include "air/ir_distance_error.h"

#include <math.h>
#include <stddef.h>

#include "world/world_random.h"

int ir_distance_sensed(const ir_distance_error *e, int sender, int receiver, uint64_t frame, double mm) {
    if (e != NULL && (e->bias_mm > 0 || e->noise_mm > 0)) {
        /* A stream per ordered pair: its first draw is the pair's bias, and
         * it seeds each frame's own stream, so no draw depends on another
         * pair's or on the order frames are handed over in. */
        uint64_t pair = world_random_stream(e->seed, (uint64_t)(uint32_t)sender << 32 | (uint32_t)receiver);
        uint64_t bias_draw = pair;
        mm += e->bias_mm * (2.0 * world_random_uniform(&bias_draw) - 1.0);
        if (e->noise_mm > 0) {
            uint64_t message = world_random_stream(pair, frame);
            mm += e->noise_mm * world_random_normal(&message);
        }
    }
    return (int)lround(mm);
}
