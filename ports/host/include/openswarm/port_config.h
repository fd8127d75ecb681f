/* Host port: the kernel's generic pool sizes suit it (no overrides), unless
 * a board on the host port plays a robot and brings that robot's defaults
 * (OPENSWARM_HOST_BOARD_CONFIG: a header, e.g. the e-puck in the world
 * simulator's), so that an app's configuration means what it does there. */
#ifndef OPENSWARM_PORT_CONFIG_H
#define OPENSWARM_PORT_CONFIG_H

#ifdef OPENSWARM_HOST_BOARD_CONFIG
#include OPENSWARM_HOST_BOARD_CONFIG
#endif

#endif
