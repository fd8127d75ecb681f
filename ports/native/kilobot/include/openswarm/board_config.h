/* The Kilobot's pools and defaults, as on the robot: an app's
 * configuration means in the native mode what it means there. */
#ifndef OPENSWARM_NATIVE_BOARD_CONFIG_H
#define OPENSWARM_NATIVE_BOARD_CONFIG_H

#include "../../../../kilobot/include/openswarm/port_config.h"

#endif
