/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A handler subscribed and never called, in the native mode: the exact
 * mode's warning (sim/src/board/handler_watch.c) for a native robot. */
#ifndef OPENSWARM_NATIVE_HANDLERS_H
#define OPENSWARM_NATIVE_HANDLERS_H

#include "sim.h"

/* At the end of a run, after the robots' threads ended: each subscription
 * in robot index's kernel whose handler the kernel never called, from the
 * shared object at so, as a warning (robot_index for the warnings, -1: the
 * only robot); how many. */
int native_handlers_report(int index, int robot_index, robot_kind kind, const char *so, double seconds);

#endif
