/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A native robot's firmware IR counters (kilobot_ir_stats, the Kilobot
 * device layer's kilobot_ir_counters), as the exact mode reads them from
 * the simulated MCU's RAM (firmware_ir_counters). */
#ifndef OPENSWARM_NATIVE_IR_COUNTERS_H
#define OPENSWARM_NATIVE_IR_COUNTERS_H

#include <stdint.h>

#include "sim.h"

/* Robot index's counters now, between windows, from the shared object at
 * so: 1, or 0 when the object keeps none (or another layout). */
int native_ir_counters(int index, const char *so, uint16_t out[KILOBOT_IR_COUNTERS]);

#endif
