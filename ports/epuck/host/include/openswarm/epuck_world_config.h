/* The e-puck in the world simulator (board epuck_world on the host port):
 * the e-puck2's pool sizes (ports/cortex_m4's cortex_m4_pools.h), so that an
 * app and the configuration `openswarm build` generates for the e-puck2
 * behave as on the robot. An application overrides any of them
 * (OS_CONFIG_FILE). */
#ifndef OPENSWARM_EPUCK_WORLD_CONFIG_H
#define OPENSWARM_EPUCK_WORLD_CONFIG_H

/* By path: ports/cortex_m4/include is not on the host port's include path
 * (its port_arch.h and port_config.h would stand in for the host's). */
#include "../../../../cortex_m4/include/openswarm/cortex_m4_pools.h"

#endif
