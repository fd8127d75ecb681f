/* The e-puck's pools, as its host build in the world takes them (the
 * e-puck2's): an app's configuration means natively what it means there. */
#ifndef OPENSWARM_NATIVE_BOARD_CONFIG_H
#define OPENSWARM_NATIVE_BOARD_CONFIG_H

#include "openswarm/epuck_world_config.h"

#endif
