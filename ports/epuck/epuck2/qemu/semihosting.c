#include "semihosting.h"

#include <stdint.h>

#define SYS_GET_CMDLINE 0x15u
#define SYS_EXIT_EXTENDED 0x20u           /* semihosting v2: exit with a status */
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u

/* BKPT 0xAB is the M-profile semihosting trap: operation in r0, its
 * argument block in r1, the result back in r0. */
static uint32_t semihosting_call(uint32_t operation, uint32_t *block) {
    register uint32_t op __asm__("r0") = operation;
    register uint32_t *arg __asm__("r1") = block;
    __asm__ __volatile__("bkpt 0xab" : "+r"(op) : "r"(arg) : "memory");
    return op;
}

void semihosting_exit(int status) {
    uint32_t block[2] = {ADP_STOPPED_APPLICATION_EXIT, (uint32_t)status};
    semihosting_call(SYS_EXIT_EXTENDED, block);
    for (;;) {
    }
}

bool semihosting_command_line(char *line, uint32_t size) {
    uint32_t block[2] = {(uint32_t)(uintptr_t)line, size};
    return size != 0 && semihosting_call(SYS_GET_CMDLINE, block) == 0;
}
