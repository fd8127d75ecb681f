/* What the QEMU board's files share. */
#ifndef EPUCK2_QEMU_BOARD_QEMU_H
#define EPUCK2_QEMU_BOARD_QEMU_H

#include <stdint.h>

/* The selector's position the run was given (--selector=N), 0 if none. */
extern uint8_t board_selector_position;

/* The robot's id the run was given (--id=N), 0 if none. */
extern uint16_t board_robot_id;

#endif
