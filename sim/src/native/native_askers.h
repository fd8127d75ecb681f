/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The robots waiting for carrier sense after a window, answered in the
 * order they asked: by the nominal cycle they asked at, then by index.
 * A binary heap: at 10 000 robots a scan of every asker for the first
 * one, once per answer, was quadratic in the askers. */
#ifndef OPENSWARM_NATIVE_ASKERS_H
#define OPENSWARM_NATIVE_ASKERS_H

#include <stdint.h>

/* Robot index asked at nominal cycle at. */
void native_askers_push(uint64_t at, int index);
/* The one that asked first, taken off; -1: none. */
int native_askers_pop(void);

#endif
