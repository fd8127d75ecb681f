/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The world's end of the link to one e-puck controller process
 * (ports/epuck/host/include/openswarm/epuck_world_link.h). */
#ifndef OPENSWARM_EPUCK_LINK_H
#define OPENSWARM_EPUCK_LINK_H

#include <stdint.h>
#include <sys/types.h>

#include "openswarm/epuck_world_link.h"

typedef struct epuck_link {
    pid_t pid;
    int to, from; /* its standard input and output */
    int index;    /* the robot's */
    const char *controller;
    int32_t t_ms; /* the step being exchanged, -1 before the first; for messages */
    int stopping; /* the exchange is the request to stop */
    epuck_world_losses losses; /* its kernel's, sent after its last answer */
    int has_losses;            /* 0: none came (a controller without a kernel) */
} epuck_link;

/* How long, in wall time, the world waits for a controller to take its
 * inputs or answer them, unless OPENSWARM_LINK_TIMEOUT_S says otherwise;
 * then it kills the controller and the run stops (exit 3). */
#define EPUCK_LINK_WAIT_S 60

/* OPENSWARM_LINK_TIMEOUT_S, when set: -1 after a message if it is not a
 * number of seconds in (0, 86400]. */
int epuck_link_wait_from_environment(void);

/* Whether the file is an e-puck2 image (a 32-bit ARM ELF), which runs
 * under QEMU, not as a program of the host's. */
int epuck_link_is_epuck2_image(const char *path);
/* Start the controller for robot index (under_qemu: the e-puck2 image
 * controller in QEMU) and read its first answer; -1 after a message
 * naming the controller and what went wrong. */
int epuck_link_start(epuck_link *l, const char *controller, int under_qemu, int index, epuck_world_output *first);
/* One exchange's halves: the input (and pixels when it carries a frame),
 * then the answer. -1 after a message (the process ended, said nonsense
 * or did not move within the wait: then it is killed). */
int epuck_link_send(epuck_link *l, const epuck_world_input *in, const uint16_t *pixels);
int epuck_link_receive(epuck_link *l, epuck_world_output *out);
/* Tell it to stop, wait for it; its exit status (-1 if it had to be
 * killed). Its kernel's losses, when it sends them, are kept in l. */
int epuck_link_stop(epuck_link *l);

#endif
