/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The native e-pucks (native_epuck.h). A world step is one window of the
 * robots' clocks: the step's inputs are set in each robot's
 * native_epuck_io and reach it as its board's interrupt as the window
 * begins (ports/native/epuck), and its answer is what it shows when the
 * window ends - as the pipe mode's controller answers once it has run the
 * step. The time and faults of the answer are the simulator's to know.
 *
 * The pipe mode's controller runs the step's last tick and everything it
 * wakes before it answers (ports/epuck/host/src/world_link_main.c,
 * settle). Here the window runs half a tick past the step's end for that:
 * the work a tick starts takes microseconds of the robot's cycles, and no
 * tick comes in between, so the kernel's time at the next inputs is the
 * pipe mode's too. */
#include "native/native_epuck.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "native/native_handlers.h"
#include "native/native_swarm.h"
#include "openswarm/native_epuck.h"

static native_epuck_io *boards;
static uint32_t *faults; /* each robot's, so far */
static int n_robots;
static uint32_t hz;
static uint64_t step_end; /* the window the sent inputs are for, in cycles */
static const char *controller;
static int booted;

static int same_controller(const options *o, int n) {
    for (int i = 1; i < n; i++) {
        if (strcmp(o->robot_elf[i], o->robot_elf[0]) == 0) continue;
        fprintf(stderr, "openswarm-sim: robot %d runs %s, robot 0 %s: the native mode runs one "
                        "controller on every e-puck of a world so far; give one, or run the world "
                        "with the controllers built for the pipe mode (without --native)\n",
                i, o->robot_elf[i], o->robot_elf[0]);
        return -1;
    }
    return 0;
}

static int no_carrier(int index, uint64_t at) {
    (void)index;
    (void)at;
    return 1; /* e-pucks send no IR frames */
}

static int receive(int n, epuck_world_output *out);

static int start(const options *o, int n, epuck_world_output *first) {
    if (same_controller(o, n) != 0) return -1;
    controller = o->robot_elf[0];
    n_robots = n;
    int threads = native_swarm_threads_for(o->threads, n);
    native_copy *copies = calloc((size_t)threads, sizeof *copies);
    boards = calloc(n ? (size_t)n : 1, sizeof *boards);
    faults = calloc(n ? (size_t)n : 1, sizeof *faults);
    if (copies == NULL || boards == NULL || faults == NULL || native_load(controller, threads, copies) != 0 ||
        native_swarm_create(copies, 1, threads, NULL, n) != 0)
        return -1;
    hz = copies[0].entry.cpu_hz;
    for (int i = 0; i < n; i++) {
        native_robot *r = native_swarm_robot(i);
        r->hz = hz;
        r->io->board = &boards[i];
        r->io->noise = 0x5DEECE66Dull * (uint64_t)(i + 1) | 1u;
        boards[i].robot_id = (uint16_t)i;
    }
    native_swarm_boot();
    booted = 1;
    return receive(n, first); /* the first answer: main has started the robot */
}

static int send(int i, uint32_t t_ms, const epuck_world_input *in, const uint16_t *pixels) {
    native_epuck_io *b = &boards[i];
    size_t n_pixels = (size_t)in->frame_width * in->frame_height;
    if (n_pixels > NATIVE_EPUCK_MAX_PIXELS) {
        fprintf(stderr, "openswarm-sim: a %u x %u frame is larger than a native e-puck takes (%u pixels)\n",
                in->frame_width, in->frame_height, NATIVE_EPUCK_MAX_PIXELS);
        return -1;
    }
    b->input = *in;
    memcpy(b->pixels, pixels, n_pixels * sizeof *pixels);
    native_swarm_robot(i)->io->board_inputs = 1;
    native_swarm_woken(i);
    step_end = (uint64_t)(t_ms + in->advance_ms) * hz / 1000u;
    return 0;
}


/* What a robot that ran said: its faults, counted and printed. */
static void read_log(int i) {
    native_robot *r = native_swarm_robot(i);
    for (unsigned k = 0; k < r->log.n_faults; k++) {
        const native_fault *f = &r->log.faults[k];
        fprintf(stderr, "openswarm-sim: robot %d: kernel fault: %s in thread %u at %.6f s\n", i,
                kernel_fault_name(f->fault), f->pid, (double)f->at / hz);
        faults[i]++;
    }
    native_log_clear(&r->log);
}

static int receive(int n, epuck_world_output *out) {
    native_swarm_window(step_end + hz / 2000u, hz, no_carrier);
    unsigned n_ran;
    const int *ran = native_swarm_ran(&n_ran);
    for (unsigned k = 0; k < n_ran; k++) read_log(ran[k]);
    for (int i = 0; i < n; i++) {
        const native_io *io = native_swarm_robot(i)->io;
        if (io->state != NATIVE_RUNNING) {
            fprintf(stderr, "openswarm-sim: robot %d's controller %s stopped at %.3f s (its main "
                            "returned %d): a controller runs as long as the world; let main end in "
                            "the system thread (Sys_Run_SystemThread) or a loop\n",
                    i, controller, (double)io->now / hz, io->status);
            return -1;
        }
        out[i] = boards[i].shown;
        out[i].time_ms = (uint32_t)(io->now * 1000u / hz);
        out[i].faults = faults[i];
    }
    return 0;
}

static int warnings(void) {
    int n = 0;
    for (int i = 0; i < n_robots; i++) {
        const uint16_t *counters = native_swarm_robot_stats(i);
        if (counters != NULL) n += kernel_loss_warnings(i, ROBOT_EPUCK, counters);
        n += native_handlers_report(i, i, ROBOT_EPUCK, controller, (double)step_end / hz);
    }
    return n;
}

static int stop(void) {
    if (booted) native_swarm_end();
    return 0;
}

const epuck_controllers native_epucks = {start, send, receive, stop, warnings};
