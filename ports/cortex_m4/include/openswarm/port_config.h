/* Cortex-M4 port: the pool sizes of cortex_m4_pools.h, and tickless idle
 * on: under QEMU every tick the CPU sleeps through is host time saved
 * (docs/benchmarks.md, "Tickless idle on the e-puck2"). An application
 * turns it off with OS_CFG_TICKLESS 0 (openswarm.json: "kernel":
 * {"tickless": false}). */
#ifndef OPENSWARM_PORT_CONFIG_H
#define OPENSWARM_PORT_CONFIG_H

#include "cortex_m4_pools.h"

#ifndef OS_CFG_TICKLESS
#define OS_CFG_TICKLESS 1
#endif

#endif
