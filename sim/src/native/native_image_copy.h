/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A native robot's RAM image in and out of its app's copy: copied and
 * summed in one pass, so that a saved image whose sum has changed when it
 * comes back - another robot's stray write - is found (native_swarm.c). */
#ifndef OPENSWARM_NATIVE_IMAGE_COPY_H
#define OPENSWARM_NATIVE_IMAGE_COPY_H

#include <stddef.h>
#include <stdint.h>

/* dst = src (n bytes; the two apart), and what they sum to: any changed
 * byte changes it, and so do words moved or swapped. */
uint64_t native_image_copy_summed(uint8_t *dst, const uint8_t *src, size_t n);

#endif
