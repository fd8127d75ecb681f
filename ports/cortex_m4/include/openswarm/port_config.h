/* Cortex-M4 port: the pool sizes of cortex_m4_pools.h. */
#ifndef OPENSWARM_PORT_CONFIG_H
#define OPENSWARM_PORT_CONFIG_H

#include "cortex_m4_pools.h"

#endif
