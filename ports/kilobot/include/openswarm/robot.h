/* What every robot OpenSwarm builds for has, under one name, so an app
 * builds for each port unchanged (the templates use only this and the
 * kernel). Each port has its own robot.h; this is the Kilobot's.
 *
 *   robot_devices_init()   register the robot's devices (after Sys_Init_Kernel)
 *                          and answer the overhead controller (kilobot.h:
 *                          BOOT, RESET, SLEEP, RUN, ...): define
 *                          KILOBOT_OVERHEAD_CONTROL 0 before including this
 *                          to get its messages as KILOBOT_EVENT_IR_RX instead
 *   robot_id()             the robot's own id (the Kilobot's uid, EEPROM 0xB0)
 *   robot_console_init()   printf from here on goes to the robot's console
 *   ROBOT_EVENT_LED        command: one byte, ROBOT_RGB(r, g, b), 0..3 each:
 *                          the robot's status light
 */
#ifndef OPENSWARM_ROBOT_H
#define OPENSWARM_ROBOT_H

#include "openswarm/kilobot.h"

#define ROBOT_EVENT_LED KILOBOT_EVENT_LED
#define ROBOT_RGB(r, g, b) KILOBOT_RGB(r, g, b)

static inline uint16_t robot_id(void) { return kilobot_uid(); }
static inline void robot_console_init(void) { kilobot_console_init(); }

#ifndef KILOBOT_OVERHEAD_CONTROL
#define KILOBOT_OVERHEAD_CONTROL 1
#endif

static inline sys_status robot_devices_init(void) {
    sys_status st = kilobot_devices_init();
    if (KILOBOT_OVERHEAD_CONTROL && st == SYS_OK) kilobot_overhead_control_start();
    return st;
}

#endif
