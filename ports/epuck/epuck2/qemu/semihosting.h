/* ARM semihosting, as QEMU implements it (-semihosting-config enable=on):
 * the emulator's exit status from the firmware, its command line, and the
 * host's files (target=native: QEMU's own open, read and write). */
#ifndef EPUCK2_QEMU_SEMIHOSTING_H
#define EPUCK2_QEMU_SEMIHOSTING_H

#include <stdbool.h>
#include <stdint.h>

void semihosting_exit(int status) __attribute__((noreturn));

/* The arguments QEMU was given (-semihosting-config ...,arg=A,arg=B) as
 * one line "A B" in line[size]; false if there are none or they do not
 * fit. */
bool semihosting_command_line(char *line, uint32_t size);

/* The host file path opened for reading or for appending: a handle, -1
 * if it cannot be opened. */
int32_t semihosting_open(const char *path, bool for_writing);
/* Up to length bytes from handle into data: how many came (0 at the end
 * of the file or on an error). A pipe's read returns what is there, or
 * blocks QEMU until something is. */
uint32_t semihosting_read(int32_t handle, void *data, uint32_t length);
/* length bytes to handle: true if they were all written. */
bool semihosting_write(int32_t handle, const void *data, uint32_t length);

#endif
