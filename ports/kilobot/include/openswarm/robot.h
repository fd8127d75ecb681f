/* What every robot OpenSwarm builds for has, under one name, so an app
 * builds for each port unchanged (the templates use only this and the
 * kernel). Each port has its own robot.h; this is the Kilobot's.
 *
 *   robot_devices_init()   register the robot's devices (after Sys_Init_Kernel)
 *   ROBOT_EVENT_LED        command: one byte, ROBOT_RGB(r, g, b), 0..3 each:
 *                          the robot's status light
 */
#ifndef OPENSWARM_ROBOT_H
#define OPENSWARM_ROBOT_H

#include "openswarm/kilobot.h"

#define ROBOT_EVENT_LED KILOBOT_EVENT_LED
#define ROBOT_RGB(r, g, b) KILOBOT_RGB(r, g, b)

static inline sys_status robot_devices_init(void) { return kilobot_devices_init(); }

#endif
