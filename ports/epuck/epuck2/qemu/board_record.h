/* Records the QEMU board writes among the console's lines for the runner
 * (`openswarm run` prints them as it prints a simulated Kilobot's trace):
 * a line starting with the ASCII record separator 0x1E, then the record's
 * name, the time in microseconds and its values:
 *
 *     \x1eled 252004 0 3 0\n        the status light: red, green, blue (0..3)
 *     \x1ewheels 252004 -300 300\n    the wheels' speeds, steps/s
 *     \x1ering 252004 5\n              the ring LEDs lit (bit 0: LED0)
 *     \x1ebody 252004 1\n, front ...    the body and front LEDs
 *     \x1elosses 1100000 0 0 0 ...\n  the kernel's sys_stats counters, in order,
 *                                  just before the end (the runner's warnings)
 *     \x1estop 1100000\n             the run reached the time it was given
 */
#ifndef EPUCK2_QEMU_BOARD_RECORD_H
#define EPUCK2_QEMU_BOARD_RECORD_H

#include <stdint.h>

void board_record(const char *name, const int32_t *values, uint8_t count);

#endif
