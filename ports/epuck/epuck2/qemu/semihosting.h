/* ARM semihosting, as QEMU implements it (-semihosting-config enable=on):
 * the emulator's exit status from the firmware. */
#ifndef EPUCK2_QEMU_SEMIHOSTING_H
#define EPUCK2_QEMU_SEMIHOSTING_H

#include <stdbool.h>
#include <stdint.h>

void semihosting_exit(int status) __attribute__((noreturn));

/* The arguments QEMU was given (-semihosting-config ...,arg=A,arg=B) as
 * one line "A B" in line[size]; false if there are none or they do not
 * fit. */
bool semihosting_command_line(char *line, uint32_t size);

#endif
