/* The Kilobot's ways out of a running program in the native mode: the
 * simulator boots the robot afresh (a restart, its mark kept) or stops it
 * at the bootloader (on a robot, the overhead controller would now
 * reprogram it). */
#include "native_internal.h"

#include "openswarm/kilobot.h"

void kilobot_enter_bootloader(void) { native_leave(NATIVE_BOOTLOADER); }

void kilobot_restart(uint16_t mark) {
    native_io_of_robot->restart_mark = mark;
    native_leave(NATIVE_RESTART);
}

uint16_t kilobot_restart_mark(void) {
    uint16_t mark = native_io_of_robot->restart_mark;
    native_io_of_robot->restart_mark = 0;
    return mark;
}
