/* What every robot OpenSwarm builds for has, under one name, so an app
 * builds for each port unchanged (the templates use only this and the
 * kernel). Each port has its own robot.h; this is the e-puck2's.
 *
 *   robot_devices_init()   register the robot's devices (after Sys_Init_Kernel)
 *   ROBOT_EVENT_LED        command: one byte, ROBOT_RGB(r, g, b), 0..3 each:
 *                          the robot's status light (the e-puck2's RGB LEDs;
 *                          under QEMU, a line on the console)
 */
#ifndef OPENSWARM_ROBOT_H
#define OPENSWARM_ROBOT_H

#include "openswarm/event.h"
#include "openswarm/types.h"

#define ROBOT_EVENT_LED ((sys_event_id)(SYS_EVENT_PORT_FIRST + 15))
#define ROBOT_RGB(r, g, b) ((uint8_t)((r) | ((g) << 2) | ((b) << 4)))

#ifdef __cplusplus
extern "C" {
#endif

sys_status robot_devices_init(void);

#ifdef __cplusplus
}
#endif

#endif
