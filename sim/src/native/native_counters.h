/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* --counters PERIOD in the native mode: every robot's kernel and IR
 * counters, one "counters t=... robot=..." line each, as the exact mode
 * prints them (docs/world.md, "Fault injection"); the IR counters for
 * ir.csv too. */
#ifndef OPENSWARM_NATIVE_COUNTERS_H
#define OPENSWARM_NATIVE_COUNTERS_H

#include "sim.h"
#include "native/native_apps.h"

/* Where each app's IR counters are in its shared object. */
void native_counters_locate(const native_apps *apps);
/* Robot index's IR counters now (kilobot_ir_stats' seven, in order), as
 * firmware_ir_counters reads the exact mode's: 1, or 0 when its app keeps
 * none (or another layout). Between windows. */
int native_counters_ir(int index, uint16_t out[KILOBOT_IR_COUNTERS]);
/* Every robot's line, at seconds of the nominal clock (between windows). */
void native_counters_print(int n_robots, double seconds);

#endif
