/* A controller without the OS - one loop that waits for a camera frame
 * and sets the wheels, as a hardware-near program on the bare robot does
 * with its camera and motor drivers - run as an e-puck of the world
 * simulator. The baseline the case study compares the OpenSwarm
 * controller with (templates/object-clustering/plain/). No kernel: no
 * threads, no events, no processors; the wheels take the speeds as they
 * are (no safety processor limiting their change). */
#ifndef OPENSWARM_EPUCK_PLAIN_H
#define OPENSWARM_EPUCK_PLAIN_H

#include <stdint.h>

#include "openswarm/epuck.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Connect to the world (once, first). */
void epuck_plain_start(void);
/* The next camera frame; the world's time runs (the wheels turning as
 * last set) until it comes. Ends the process when the world stops. */
const epuck_camera_frame *epuck_plain_wait_frame(void);
/* Steps/s, + forward, each clamped to +-EPUCK_MAX_STEPS_PER_S. */
void epuck_plain_set_wheels(int16_t left, int16_t right);

/* The clamp set_wheels applies (each board's, the pipe's and the native one). */
static inline int16_t epuck_plain_limit(int16_t v) {
    return v > EPUCK_MAX_STEPS_PER_S ? EPUCK_MAX_STEPS_PER_S
                                     : v < -EPUCK_MAX_STEPS_PER_S ? -EPUCK_MAX_STEPS_PER_S : v;
}

#ifdef __cplusplus
}
#endif

#endif
