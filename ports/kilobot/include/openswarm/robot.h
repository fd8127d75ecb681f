/* What every robot OpenSwarm builds for has, under one name, so an app
 * builds for each port unchanged (the templates use only this and the
 * kernel). Each port has its own robot.h; this is the Kilobot's.
 *
 *   robot_devices_init()   register the robot's devices (after Sys_Init_Kernel)
 *                          and answer the overhead controller (kilobot.h:
 *                          BOOT, RESET, SLEEP, RUN, ...). Define
 *                          KILOBOT_OVERHEAD_CONTROL before including this
 *                          (or openswarm.json's "kilobot" section does) as
 *                          KILOBOT_OVERHEAD_CONTROL_EVENTS to get them as
 *                          KILOBOT_EVENT_OHC and act on them yourself, or
 *                          KILOBOT_OVERHEAD_CONTROL_OFF to get them as
 *                          KILOBOT_EVENT_IR_RX like any other frame
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

#define KILOBOT_OVERHEAD_CONTROL_OFF 0
#define KILOBOT_OVERHEAD_CONTROL_PORT 1
#define KILOBOT_OVERHEAD_CONTROL_EVENTS 2
#ifndef KILOBOT_OVERHEAD_CONTROL
#define KILOBOT_OVERHEAD_CONTROL KILOBOT_OVERHEAD_CONTROL_PORT
#endif

static inline sys_status robot_devices_init(void) {
    sys_status st = kilobot_devices_init();
    if (st != SYS_OK) return st;
    if (KILOBOT_OVERHEAD_CONTROL == KILOBOT_OVERHEAD_CONTROL_EVENTS) return kilobot_overhead_control_start_events();
    if (KILOBOT_OVERHEAD_CONTROL == KILOBOT_OVERHEAD_CONTROL_PORT) kilobot_overhead_control_start();
    return SYS_OK;
}

#endif
