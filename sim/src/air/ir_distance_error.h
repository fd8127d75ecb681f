/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* How far off a Kilobot's distance estimate is, as the real robots were
 * measured: "sensing accuracy of +-2 mm, and precision under 1 mm"
 * (Rubenstein, Ahler, Nagpal, Kilobot, Harvard TR-06-11 / ICRA 2012;
 * docs/world.md, "IR between robots"). Two parts:
 *
 * - accuracy: a fixed error of each ordered pair (sender, receiver), from
 *   the manufacturing spread of emitters and receivers that one shared
 *   calibration table cannot take out; uniform within +-bias_mm;
 * - precision: each message's own error, gaussian with sd noise_mm.
 *
 * Both are functions of the seed, the pair and the sender's frame count,
 * never of the order robots run in: the exact mode (ir_channel.c) and the
 * native one (native_air.c) draw the same error for the same frame, on
 * any number of threads. */
#ifndef OPENSWARM_IR_DISTANCE_ERROR_H
#define OPENSWARM_IR_DISTANCE_ERROR_H

#include <stdint.h>

/* A world's defaults (world.json's "ir"): the published figures. */
#define IR_DISTANCE_BIAS_MM 2.0
#define IR_DISTANCE_NOISE_MM 0.5

typedef struct ir_distance_error {
    double bias_mm;  /* each ordered pair's fixed error lies within +-bias_mm; 0: none */
    double noise_mm; /* each message's own error's sd; 0: none */
    uint64_t seed;   /* the world's, for these draws alone */
} ir_distance_error;

#ifdef __cplusplus
extern "C" {
#endif

/* The distance, whole mm, that receiver's distance sensors read for the
 * frame-th frame of sender (counted from 1), the two being mm apart. With
 * no error (e NULL or both parts 0) it is mm rounded, as before the model. */
int ir_distance_sensed(const ir_distance_error *e, int sender, int receiver, uint64_t frame, double mm);

#ifdef __cplusplus
}
#endif

#endif
