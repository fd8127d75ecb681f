/* Native port: the pools of the robot it plays (the board's own
 * port_config.h, included by the board's include path as
 * openswarm/board_config.h), with tickless idle always on. It changes no
 * behaviour an app can see: the kernel's time and timeouts are the same
 * (docs/world.md, "Native mode"); it lets a swarm of sleeping robots cost
 * nothing between their deadlines. */
/* Its own guard: the board's port_config.h has the robot's. */
#ifndef OPENSWARM_NATIVE_PORT_CONFIG_H
#define OPENSWARM_NATIVE_PORT_CONFIG_H

#undef OS_CFG_TICKLESS
#define OS_CFG_TICKLESS 1
#include "openswarm/board_config.h"

#endif
