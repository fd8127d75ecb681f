/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Where a world's e-puck controllers run, as the world's steps see them
 * (epuck_run.c): one host process each over a pipe (epuck_pipes.c: a
 * program, or QEMU running an e-puck2 image), or
 * all in the simulator's process in the native mode
 * (native/native_epuck.c). Either way a step is the same exchange: every
 * robot's inputs, the step run, every robot's answer. */
#ifndef OPENSWARM_EPUCK_CONTROLLERS_H
#define OPENSWARM_EPUCK_CONTROLLERS_H

#include <stdint.h>

#include "openswarm/epuck_world_link.h"
#include "sim.h"

typedef struct epuck_controllers {
    /* Start n controllers (o->robot_elf[i]), each's first answer in
     * first[i]; -1 after a message. */
    int (*start)(const options *o, int n, epuck_world_output *first);
    /* Robot i's inputs for the step at t_ms (pixels when in carries a frame). */
    int (*send)(int i, uint32_t t_ms, const epuck_world_input *in, const uint16_t *pixels);
    /* Every robot's answer to the step, once all were sent. */
    int (*receive)(int n, epuck_world_output *out);
    /* Stop them all: -1 if one failed to stop cleanly. Controllers that
     * send their kernels' losses as they end note them as warnings. */
    int (*stop)(void);
    /* Before stop: what their kernels lost or refused, noted as warnings;
     * how many. NULL: stop notes them (the controllers over pipes, other
     * processes, send them as they end). */
    int (*warnings)(void);
} epuck_controllers;

extern const epuck_controllers epuck_pipes;
/* The same, each controller an e-puck2 image run by QEMU ("fidelity": "qemu"). */
extern const epuck_controllers epuck_qemu;

#endif
