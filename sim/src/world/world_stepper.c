/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The physics beside the robots (world_stepper.h). A step of a thousand
 * packed robots costs about as much as the robots' own work between two
 * steps: on a thread of its own it costs the run nothing it waits for.
 * Handing a step over is rare (100 times a simulated second): a mutex and
 * a condition, and the thread sleeps between steps. The motors' part of a
 * step (world_step_prepare: the motion model and its noise, a tenth of a
 * step at a thousand robots) is the robots' threads', shared as their
 * windows are (window_workers) and done while the step before still runs
 * there, so the physics' thread - the busier at a thousand robots - does
 * only Box2D's part. */
#include "world/world_stepper.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>

#include "sim.h"
#include "window_workers.h"

typedef struct motor_change {
    double t;
    uint8_t side, duty;
} motor_change;

typedef struct motor_changes {
    motor_change *at;
    unsigned n, room;
} motor_changes;

static world *physics;
static int n_robots;
static motor_changes *kept; /* by robot: each robot's own thread appends */
static int threaded;
static pthread_t thread;
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t turn = PTHREAD_COND_INITIALIZER;
static int stepping; /* a step is begun and not over */
static int stopping;
static unsigned steps_begun; /* a step's twists are in slot steps_begun % 2 */
static unsigned step_slot;   /* the one begun's, for the physics' thread */
static double prepare_end;   /* the step being prepared ends then */

static void *step_on_thread(void *unused) {
    (void)unused;
    pthread_mutex_lock(&lock);
    for (;;) {
        while (!stepping && !stopping) pthread_cond_wait(&turn, &lock);
        if (!stepping) break;
        unsigned slot = step_slot;
        pthread_mutex_unlock(&lock);
        world_step_bodies(physics, slot);
        pthread_mutex_lock(&lock);
        stepping = 0;
        pthread_cond_broadcast(&turn);
    }
    pthread_mutex_unlock(&lock);
    return NULL;
}

void world_stepper_start(world *w, int n, int on_thread) {
    physics = w;
    n_robots = n;
    kept = calloc(n > 0 ? (size_t)n : 1, sizeof *kept);
    if (kept == NULL) {
        fprintf(stderr, "openswarm-sim: out of memory for %d robots' motors\n", n);
        exit(EXIT_CRASH);
    }
    threaded = on_thread;
    stepping = stopping = 0;
    steps_begun = 0;
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
 * step running meanwhile walks the bodies by the other slot (world.h). */
static int prepare_share(int share) {
    int shares = window_workers_threads();
    for (int i = share; i < n_robots; i += shares) {
        motor_changes *c = &kept[i];
        for (unsigned k = 0; k < c->n; k++) world_motor_duty(physics, i, c->at[k].side, c->at[k].duty, c->at[k].t);
        c->n = 0;
    }
    world_step_prepare(physics, prepare_end, steps_begun % 2, share, shares);
    return 1;
}

void world_stepper_prepare(double t) {
    prepare_end = t;
    window_workers_run_job(prepare_share);
}

void world_stepper_begin(void) {
    world_stepper_wait();
    unsigned slot = steps_begun++ % 2;
    if (!threaded) {
        world_step_bodies(physics, slot);
        return;
    }
    pthread_mutex_lock(&lock);
    step_slot = slot;
    stepping = 1;
    pthread_cond_broadcast(&turn);
    pthread_mutex_unlock(&lock);
}

void world_stepper_wait(void) {
    if (!threaded) return;
    pthread_mutex_lock(&lock);
    while (stepping) pthread_cond_wait(&turn, &lock);
    pthread_mutex_unlock(&lock);
}

void world_stepper_stop(void) {
    if (threaded) {
        world_stepper_wait();
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
}
