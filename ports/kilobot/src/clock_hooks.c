/* The Kilobot's 1 ms clock hooks and what each tick runs: the kernel's
 * tick, then the devices' and the app's hooks. The board's tick interrupt
 * calls kilobot_tick (port.c on the robot, ports/native in the native
 * mode). */
#include "openswarm/kilobot.h"
#include "openswarm/port.h"
#include "devices/devices_internal.h"

void (*kilobot_tick_hook)(void);
void (*kilobot_elapsed_hook)(uint16_t ms);
void (*kilobot_sensors_tick_hook)(void);
void (*kilobot_motors_tick_hook)(void);

void kilobot_tick(void) {
    os_tick();
    void (*motors)(void) = kilobot_motors_tick_hook;
    if (motors != NULL) motors();
    void (*sensors)(void) = kilobot_sensors_tick_hook;
    if (sensors != NULL) sensors();
    void (*hook)(void) = kilobot_tick_hook;
    if (hook != NULL) hook();
    void (*elapsed)(uint16_t) = kilobot_elapsed_hook;
    if (elapsed != NULL) elapsed(1);
}
