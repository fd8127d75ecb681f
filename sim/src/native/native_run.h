/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The native mode: an app built as a shared object for the host
 * (`openswarm build --native`, ports/native) run by the thousand, in a
 * world or placed by the command line, checked against the exact mode
 * (docs/world.md, "Native mode"). */
#ifndef OPENSWARM_NATIVE_RUN_H
#define OPENSWARM_NATIVE_RUN_H

#include "sim.h"

/* The run the options describe (parsed and checked); the exit status. */
int native_run(const options *o);

#endif
