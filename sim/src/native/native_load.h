/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Loading a native robot (an app built with `openswarm build --native`,
 * ports/native): the shared object once per thread that runs robots of it,
 * each copy with its own RAM image at its own address. */
#ifndef OPENSWARM_NATIVE_LOAD_H
#define OPENSWARM_NATIVE_LOAD_H

#include <stddef.h>
#include <stdint.h>

#include "openswarm/native_robot.h"

typedef struct native_copy {
    void *handle;
    uintptr_t base;     /* where it is loaded: an address less this is an offset into the file */
    native_entry entry;
    uint8_t *image;     /* this copy's RAM: its .data and .bss */
    size_t image_bytes;
    uint8_t *pristine;  /* the image as loaded: a robot at power-up */
} native_copy;

/* Is path a native robot (a host shared object), rather than firmware? */
int native_is_robot(const char *path);
/* Load path copies times; -1 after a message naming the file and the fix. */
int native_load(const char *path, int copies, native_copy *out);

#endif
