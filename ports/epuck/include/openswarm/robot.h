/* What every robot OpenSwarm builds for has, under one name, so an app
 * builds for each port unchanged (the templates use only this and the
 * kernel). Each port has its own robot.h; this is the e-puck's (both).
 *
 *   robot_devices_init()   register the robot's devices (after Sys_Init_Kernel)
 *   robot_id()             the robot's own id: on the e-puck2, its STM32's
 *                          96-bit unique id folded to 16 bits; on the
 *                          e-puck, its data EEPROM's last word (0 erased);
 *                          under QEMU, the run's --id=N (0 without); in a
 *                          world, the robot's index in the world file
 *   robot_console_init()   printf from here on goes to the robot's console
 *                          (the e-puck2's USART3, the e-puck's UART1, QEMU's
 *                          serial port, the world's standard error)
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

/* Supplied by each board. */
uint16_t epuck_robot_id(void);
void epuck_console_init(void);

static inline uint16_t robot_id(void) { return epuck_robot_id(); }
static inline void robot_console_init(void) { epuck_console_init(); }

#endif
