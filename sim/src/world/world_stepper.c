/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The physics beside the robots (world_stepper.h). A step of a thousand
 * packed robots costs about as much as the robots' own work between two
 * steps, and each varies from step to step: with one step under way at a
 * time, each thread waited at every step for the other's slower part
 * (a fifth of each thread's time, perf sched, 1000 robots); with two
 * steps under way, the physics' thread works through a queue and the
 * robots wait only when it is two steps behind. Handing a step over is
 * rare (100 times a simulated second): a mutex and a condition, and the
 * thread sleeps while the queue is empty. The motors' part of a step
 * (world_step_prepare: the motion model and its noise) is the robots'
 * threads', shared as their windows are (window_workers) and done while
 * the steps before still run there, so the physics' thread does only
 * Box2D's part and notes where it left the bodies. */
#include "world/world_stepper.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>

#include "sim.h"
#include "window_workers.h"

_Static_assert(WORLD_TWIST_SLOTS == WORLD_STEPS_AHEAD + 1, "a twist slot for each step under way and the next");

typedef struct motor_change {
    double t;
    uint8_t side, duty;
} motor_change;

typedef struct motor_changes {
    motor_change *at;
    unsigned n, room;
} motor_changes;

static world *physics;
static int n_robots, n_objects;
static motor_changes *kept; /* by robot: each robot's own thread appends */
/* Where each step under way left the bodies: step k's in seen[k % 2]
 * (the physics' thread writes the newer while the main one reads the
 * older). */
static world_poses seen[WORLD_STEPS_AHEAD];
static int threaded;
static pthread_t thread;
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t turn = PTHREAD_COND_INITIALIZER;
static int stopping;
static unsigned steps_begun, steps_done, steps_taken;
static double prepare_end; /* the step being prepared ends then */

/* Step k: its bodies walked and Box2D's step, then where it left them. */
static void take_step(unsigned k) {
    world_step_bodies(physics, k % WORLD_TWIST_SLOTS);
    const world_poses *p = &seen[k % WORLD_STEPS_AHEAD];
    for (int i = 0; i < n_robots; i++)
        world_robot_pose(physics, i, &p->robots[i].x_mm, &p->robots[i].y_mm, &p->robots[i].heading_deg);
    for (int o = 0; o < n_objects; o++) world_object_position(physics, o, &p->objects[o].x, &p->objects[o].y);
}

static void *step_on_thread(void *unused) {
    (void)unused;
    pthread_mutex_lock(&lock);
    for (;;) {
        while (steps_done == steps_begun && !stopping) pthread_cond_wait(&turn, &lock);
        if (steps_done == steps_begun) break;
        unsigned k = steps_done;
        pthread_mutex_unlock(&lock);
        take_step(k);
        pthread_mutex_lock(&lock);
        steps_done++;
        pthread_cond_broadcast(&turn);
    }
    pthread_mutex_unlock(&lock);
    return NULL;
}

static void *allocate(size_t n, size_t size) {
    void *p = calloc(n > 0 ? n : 1, size);
    if (p == NULL) {
        fprintf(stderr, "openswarm-sim: out of memory for %d robots' physics\n", n_robots);
        exit(EXIT_CRASH);
    }
    return p;
}

void world_stepper_start(world *w, int n, int objects, int on_thread) {
    physics = w;
    n_robots = n;
    n_objects = objects;
    kept = allocate((size_t)n, sizeof *kept);
    for (int s = 0; s < WORLD_STEPS_AHEAD; s++) {
        seen[s].robots = allocate((size_t)n, sizeof *seen[s].robots);
        seen[s].objects = allocate((size_t)objects, sizeof *seen[s].objects);
    }
    threaded = on_thread;
    stopping = 0;
    steps_begun = steps_done = steps_taken = 0;
    if (threaded && pthread_create(&thread, NULL, step_on_thread, NULL) != 0) {
        fprintf(stderr, "openswarm-sim: cannot start the physics' thread; give --threads 1\n");
        exit(EXIT_CRASH);
    }
}

void world_stepper_motor(int index, int side, uint8_t duty, double t) {
    motor_changes *c = &kept[index];
    if (c->n == c->room) {
        c->room = c->room ? 2 * c->room : 8;
        c->at = realloc(c->at, c->room * sizeof *c->at);
        if (c->at == NULL) {
            fprintf(stderr, "openswarm-sim: out of memory for robot %d's motors\n", index);
            exit(EXIT_CRASH);
        }
    }
    c->at[c->n++] = (motor_change){t, (uint8_t)side, duty};
}

/* Thread share's robots (share, share + shares, ...), as the windows
 * share them: each robot's motors are touched by no other thread, and the
 * steps running meanwhile walk the bodies by their own slots (world.h). */
static int prepare_share(int share) {
    int shares = window_workers_threads();
    for (int i = share; i < n_robots; i += shares) {
        motor_changes *c = &kept[i];
        for (unsigned k = 0; k < c->n; k++) world_motor_duty(physics, i, c->at[k].side, c->at[k].duty, c->at[k].t);
        c->n = 0;
    }
    world_step_prepare(physics, prepare_end, steps_begun % WORLD_TWIST_SLOTS, share, shares);
    return 1;
}

void world_stepper_prepare(double t) {
    prepare_end = t;
    window_workers_run_job(prepare_share);
}

void world_stepper_begin(void) {
    if (world_stepper_pending() >= WORLD_STEPS_AHEAD) {
        fprintf(stderr, "openswarm-sim: internal error: a step begun with %d under way\n", WORLD_STEPS_AHEAD);
        exit(EXIT_CRASH);
    }
    if (!threaded) {
        take_step(steps_begun++);
        steps_done = steps_begun;
        return;
    }
    pthread_mutex_lock(&lock);
    steps_begun++;
    pthread_cond_broadcast(&turn);
    pthread_mutex_unlock(&lock);
}

int world_stepper_pending(void) { return (int)(steps_begun - steps_taken); }

const world_poses *world_stepper_take(void) {
    unsigned k = steps_taken++;
    if (threaded) {
        pthread_mutex_lock(&lock);
        while (steps_done <= k) pthread_cond_wait(&turn, &lock);
        pthread_mutex_unlock(&lock);
    }
    return &seen[k % WORLD_STEPS_AHEAD];
}

void world_stepper_stop(void) {
    if (threaded) {
        pthread_mutex_lock(&lock);
        stopping = 1;
        pthread_cond_broadcast(&turn);
        pthread_mutex_unlock(&lock);
        pthread_join(thread, NULL);
        threaded = 0;
    }
    for (int i = 0; i < n_robots; i++) free(kept[i].at);
    free(kept);
    kept = NULL;
    for (int s = 0; s < WORLD_STEPS_AHEAD; s++) {
        free(seen[s].robots);
        free(seen[s].objects);
    }
}
