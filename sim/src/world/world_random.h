/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Seeded random numbers (splitmix64) for everything drawn in a world: the
 * placement, the motors, the motion and analog noise. The standard
 * library's distributions differ between implementations; these do not,
 * so the same seed gives the same run on every machine. */
#ifndef OPENSWARM_WORLD_RANDOM_H
#define OPENSWARM_WORLD_RANDOM_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

uint64_t world_random_next(uint64_t *state);
/* The state that starts stream `index` of `seed`. The two are mixed, not
 * added: starting states spaced by the generator's own increment would
 * make stream i+k stream i shifted by k draws (robot i+4 walked robot i's
 * path one 4-draw step later until this was used). */
uint64_t world_random_stream(uint64_t seed, uint64_t index);
double world_random_uniform(uint64_t *state); /* [0, 1) */
double world_random_normal(uint64_t *state);  /* mean 0, sd 1 */

#ifdef __cplusplus
}
#endif

#endif
