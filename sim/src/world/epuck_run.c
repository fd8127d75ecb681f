/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
#include "world/epuck_run.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "interrupt.h"
#include "output/output.h"
#include "world/epuck_camera_noise.h"
#include "world/epuck_link.h"
#include "world/epuck_sensors.h"
#include "world/world_random.h"

#define STEP_MS 10 /* = WORLD_STEP_S: one exchange per physics step */
#define FRAME_PIXELS (EPUCK_FRAME_WIDTH * EPUCK_FRAME_HEIGHT)

typedef struct epuck_robot {
    uint64_t rng;        /* its proximity sensors' noise */
    uint64_t camera_rng; /* its camera's noise */
    uint16_t *frames;    /* the frames taken and not yet delivered, camera_depth of them */
} epuck_robot;

static const epuck_controllers *controllers;
static epuck_robot *robots;
static epuck_world_output *answers; /* each robot's last */
static int n_robots;
static output_robot *poses;
static world_point *object_centres;
static const uint16_t no_frame[1]; /* the pixels a step without a frame passes */
static int camera_period_ms, camera_lag_ms;
static int camera_depth; /* frames in flight a robot: the lag's periods and one */

static void *allocate(size_t n, size_t size) {
    void *p = calloc(n ? n : 1, size);
    if (p == NULL) {
        fprintf(stderr, "openswarm-sim: out of memory for %zu e-pucks\n", n);
        exit(EXIT_CRASH);
    }
    return p;
}

static int start_controllers(const options *o, const world_spec *spec) {
    camera_period_ms = world_camera_period_ms(spec);
    camera_lag_ms = spec->camera_lag_ms;
    camera_depth = camera_lag_ms / camera_period_ms + 1;
    for (int i = 0; i < n_robots; i++) {
        epuck_robot *r = &robots[i];
        r->rng = (uint64_t)spec->seed * 0x9E3779B97F4A7C15ull ^ ((uint64_t)i << 32 | 0xE9u);
        world_random_next(&r->rng);
        r->camera_rng = epuck_camera_stream(spec->seed, i);
        r->frames = allocate((size_t)camera_depth * FRAME_PIXELS, sizeof *r->frames);
    }
    return controllers->start(o, n_robots, answers);
}

/* Robot i's frame for this step, if one arrives: taken camera_lag_ms ago
 * (the sensor's readout and the transfer), kept in its ring until then.
 * Without a lag the ring holds one frame, taken and delivered in the same
 * step. */
static const uint16_t *camera_frame(const world *physics, int i, uint32_t t_ms) {
    epuck_robot *r = &robots[i];
    if (t_ms % (uint32_t)camera_period_ms == 0)
        epuck_camera_render(physics, i, r->frames + (t_ms / camera_period_ms % camera_depth) * FRAME_PIXELS,
                            &r->camera_rng);
    if (t_ms < (uint32_t)camera_lag_ms || (t_ms - camera_lag_ms) % (uint32_t)camera_period_ms != 0) return NULL;
    return r->frames + ((t_ms - camera_lag_ms) / camera_period_ms % camera_depth) * FRAME_PIXELS;
}

/* One step's exchange with every controller: all inputs first, then
 * every answer. */
static int exchange(const world *physics, uint32_t t_ms) {
    for (int i = 0; i < n_robots; i++) {
        epuck_robot *r = &robots[i];
        epuck_world_input in = {EPUCK_LINK_MAGIC, STEP_MS, EPUCK_LINK_PROXIMITY, 0, {0}, {0}, 0, 0};
        epuck_proximity_read(physics, i, in.proximity_off, in.proximity_pulsed, &r->rng);
        const uint16_t *taken = camera_frame(physics, i, t_ms);
        if (taken != NULL) {
            in.frame_width = EPUCK_FRAME_WIDTH;
            in.frame_height = EPUCK_FRAME_HEIGHT;
        }
        if (controllers->send(i, t_ms, &in, taken != NULL ? taken : no_frame) != 0) return -1;
    }
    return controllers->receive(n_robots, answers);
}

static unsigned faults_now(void) {
    unsigned n = 0;
    for (int i = 0; i < n_robots; i++) n += answers[i].faults;
    return n;
}

static void observe(const world *physics, const world_spec *spec) {
    for (int i = 0; i < n_robots; i++) {
        output_robot *p = &poses[i];
        world_robot_pose(physics, i, &p->x_mm, &p->y_mm, &p->heading_deg);
        uint8_t rgb = answers[i].rgb_leds; /* EPUCK_RGB: 2 bits a channel */
        p->led_r = rgb & 3;
        p->led_g = (rgb >> 2) & 3;
        p->led_b = (rgb >> 4) & 3;
    }
    for (int k = 0; k < spec->n_objects; k++)
        world_object_position(physics, k, &object_centres[k].x, &object_centres[k].y);
}

static int record(double t) {
    output_sample s = {t, poses, object_centres, NULL, 0, NULL};
    return output_sample_add(&s);
}

/* The video's frames at its own times, before the run's end. */
static int record_frame(double t, double end_s) {
    if (t >= end_s - 1e-9 || t + 1e-9 < output_next_frame_s()) return 0;
    output_sample s = {t, poses, object_centres, NULL, 0, NULL};
    return output_frame_add(&s);
}

/* The run proper: steps until the time is up or a controller fails. */
static int run_steps(const options *o, const world_spec *spec, world *physics, int recording) {
    uint32_t steps = (uint32_t)llround(o->seconds * 1000.0 / STEP_MS);
    double next_sample = spec->sample_period_s;
    unsigned faults = 0;
    for (uint32_t k = 0; k < steps; k++) {
        uint32_t t_ms = k * STEP_MS;
        if (interrupt_stop_here(t_ms / 1000.0)) break;
        if (exchange(physics, t_ms) != 0) return EXIT_CRASH;
        if (faults_now() != faults) {
            faults = faults_now();
            fprintf(stderr, "openswarm-sim: a controller reported a kernel fault by %.2f s (its "
                            "message is above)\n", (t_ms + STEP_MS) / 1000.0);
        }
        for (int i = 0; i < n_robots; i++)
            world_epuck_wheels(physics, i, answers[i].wheel_left, answers[i].wheel_right);
        double t = (t_ms + STEP_MS) / 1000.0;
        world_step(physics, t);
        observe(physics, spec);
        if (recording && t + 1e-9 >= next_sample) {
            if (record(t) != 0) return EXIT_USAGE;
            next_sample += spec->sample_period_s;
        }
        if (recording && o->video && record_frame(t, o->seconds) != 0) return EXIT_USAGE;
    }
    return faults && !o->allow_faults ? EXIT_FAULT : 0;
}

int epuck_world_run(const options *o, const world_spec *spec, world *physics, const epuck_controllers *where) {
    if (epuck_link_wait_from_environment() != 0) return EXIT_USAGE;
    controllers = where;
    n_robots = spec->n_robots;
    robots = allocate((size_t)n_robots, sizeof *robots);
    answers = allocate((size_t)n_robots, sizeof *answers);
    poses = allocate((size_t)n_robots, sizeof *poses);
    object_centres = allocate((size_t)spec->n_objects, sizeof *object_centres);
    struct timespec began;
    clock_gettime(CLOCK_MONOTONIC, &began);
    int status = start_controllers(o, spec) != 0 ? EXIT_CRASH : 0;
    int recording = 0;
    if (status == 0 && o->out_dir != NULL) {
        output_options out = {.dir = o->out_dir, .video = o->video, .quiet = o->quiet,
                              .ids = o->ids, .video_fps = o->video_fps, .video_speed = o->video_speed};
        observe(physics, spec);
        if (output_open(&out, spec) != 0 || record(0.0) != 0 || (o->video && record_frame(0.0, o->seconds) != 0))
            status = EXIT_USAGE;
        else recording = 1;
    }
    if (status == 0) status = run_steps(o, spec, physics, recording);
    if (status == 0 && controllers->warnings != NULL) controllers->warnings();
    if (controllers->stop() != 0 && status == 0) status = EXIT_CRASH;
    int warned = warnings_print();
    if (status == 0 && warnings_fail_run(warned, o)) status = EXIT_WARNINGS;
    if (interrupt_caught()) output_quieten(); /* interrupt_finish names the files */
    if (recording && output_close() != 0 && status == 0) status = EXIT_USAGE;
    if (interrupt_caught() && status == 0) return interrupt_finish(recording ? output_written() : NULL);
    struct timespec ended;
    clock_gettime(CLOCK_MONOTONIC, &ended);
    double wall = (double)(ended.tv_sec - began.tv_sec) + (ended.tv_nsec - began.tv_nsec) / 1e9;
    if (status == 0 && !o->quiet)
        fprintf(stderr, "openswarm-sim: ran %.3f s of simulated time (%d e-puck%s) in %.1f s, "
                        "%.1fx real time\n",
                o->seconds, n_robots, n_robots == 1 ? "" : "s", wall, o->seconds / (wall > 0 ? wall : 1e-9));
    return status;
}
