/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The apps of a native run (native_apps.h). */
#include "native/native_apps.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "world/world_run.h"

/* Who robot index is, for a message: its world group, or its index. */
static void name_robot(const options *o, int index, char *out, size_t room) {
    int group;
    if (o->world != NULL && world_robot_group(index, &group) != NULL)
        snprintf(out, room, "robots[%d]", group);
    else
        snprintf(out, room, "robot %d", index);
}

int native_apps_one_mode(const options *o) {
    int first_native = -1, first_exact = -1;
    for (int i = 0; i < o->robots && (first_native < 0 || first_exact < 0); i++) {
        /* robots of one file come in runs: the file is read once a run */
        if (i > 0 && strcmp(firmware_of(o, i), firmware_of(o, i - 1)) == 0) continue;
        if (native_is_robot(firmware_of(o, i))) {
            if (first_native < 0) first_native = i;
        } else if (first_exact < 0) {
            first_exact = i;
        }
    }
    if (first_native < 0 || first_exact < 0) return 0;
    char native[512], exact[512];
    name_robot(o, first_native, native, sizeof native);
    name_robot(o, first_exact, exact, sizeof exact);
    fprintf(stderr, "openswarm-sim: %s%s%s runs %s, an app built for the host (the native mode), and %s runs "
                    "%s, firmware for the exact mode: the robots of one run run in one mode. For the native "
                    "mode give %s the .so of its app (`openswarm build --native`: "
                    "build/kilobot-native/<app>.so); for the exact mode give %s its app's .elf\n",
            o->world != NULL ? o->world : "", o->world != NULL ? ": " : "", native, firmware_of(o, first_native),
            exact, firmware_of(o, first_exact), exact, native);
    return -1;
}

/* The app robot i runs: its index in paths, added if it is new. */
static int app_index(native_apps *apps, const char *path) {
    for (int a = 0; a < apps->n; a++)
        if (strcmp(apps->paths[a], path) == 0) return a;
    apps->paths[apps->n] = path;
    return apps->n++;
}

/* One world's robots share the nominal clock its windows are cut by. */
static int same_clock(const native_apps *apps, int threads) {
    for (int a = 1; a < apps->n; a++) {
        uint32_t hz = apps->copies[a * threads].entry.cpu_hz, first = apps->copies[0].entry.cpu_hz;
        if (hz == first) continue;
        fprintf(stderr, "openswarm-sim: %s runs at %u Hz and %s at %u Hz: the robots of one run share "
                        "one kind of robot; build both apps for the same board (`openswarm build --native "
                        "--port kilobot`)\n", apps->paths[0], (unsigned)first, apps->paths[a], (unsigned)hz);
        return -1;
    }
    return 0;
}

int native_apps_load(const options *o, int threads, native_apps *out) {
    int n = o->robots;
    out->n = 0;
    out->paths = malloc((size_t)(n > 0 ? n : 1) * sizeof *out->paths);
    out->app_of = malloc((size_t)(n > 0 ? n : 1) * sizeof *out->app_of);
    if (out->paths == NULL || out->app_of == NULL) return -1;
    for (int i = 0; i < n; i++) out->app_of[i] = app_index(out, firmware_of(o, i));
    out->copies = calloc((size_t)(out->n * threads), sizeof *out->copies);
    if (out->copies == NULL) return -1;
    for (int a = 0; a < out->n; a++)
        if (native_load(out->paths[a], threads, &out->copies[a * threads]) != 0) return -1;
    return same_clock(out, threads);
}
