/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The apps of a native run: the shared objects its robots run - each
 * world group's "firmware", or the command line's files - each loaded once
 * per thread, so robots of different apps run side by side, each in a
 * copy of its own app (docs/world.md, "Native mode"). */
#ifndef OPENSWARM_NATIVE_APPS_H
#define OPENSWARM_NATIVE_APPS_H

#include "sim.h"
#include "native/native_load.h"

typedef struct native_apps {
    const char **paths;  /* each app's file, in the order the robots first name it */
    int n;
    int *app_of;         /* each robot's app: an index into paths */
    native_copy *copies; /* app a's copy on thread t: copies[a * threads + t] */
} native_apps;

/* Every robot's app, each loaded threads times; -1 after a message (a file
 * that is no native robot, or apps whose clocks differ). */
int native_apps_load(const options *o, int threads, native_apps *out);
/* Robots of one run either all run shared objects (the native mode) or
 * all firmware (the exact mode): -1 after a message naming a robot (its
 * world group) of each kind and the fix, 0 when they agree. */
int native_apps_one_mode(const options *o);

#endif
