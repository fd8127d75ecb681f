/* What every robot OpenSwarm builds for has, under one name, so an app
 * builds for each port unchanged (the templates use only this and the
 * kernel). Each port has its own robot.h; this is the e-puck's (both).
 *
 *   robot_devices_init()   register the robot's devices (after Sys_Init_Kernel)
 *   ROBOT_EVENT_LED        command: one byte, ROBOT_RGB(r, g, b), 0..3 each:
 *                          the robot's status light (the e-puck's RGB LEDs;
 *                          under QEMU, a line on the console)
 */
#ifndef OPENSWARM_ROBOT_H
#define OPENSWARM_ROBOT_H

#include "openswarm/epuck.h"

#define ROBOT_EVENT_LED EPUCK_EVENT_RGB_LEDS
#define ROBOT_RGB(r, g, b) EPUCK_RGB(r, g, b)

static inline sys_status robot_devices_init(void) { return epuck_devices_init(); }

#endif
