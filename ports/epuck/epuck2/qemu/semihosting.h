/* ARM semihosting, as QEMU implements it (-semihosting-config enable=on):
 * the emulator's exit status from the firmware. */
#ifndef EPUCK2_QEMU_SEMIHOSTING_H
#define EPUCK2_QEMU_SEMIHOSTING_H

void semihosting_exit(int status) __attribute__((noreturn));

#endif
