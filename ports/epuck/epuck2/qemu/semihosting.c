#include "semihosting.h"

#include <stdint.h>

#define SYS_EXIT_EXTENDED 0x20u           /* semihosting v2: exit with a status */
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u

/* BKPT 0xAB is the M-profile semihosting trap: operation in r0, its
 * argument block in r1. */
void semihosting_exit(int status) {
    uint32_t block[2] = {ADP_STOPPED_APPLICATION_EXIT, (uint32_t)status};
    register uint32_t op __asm__("r0") = SYS_EXIT_EXTENDED;
    register uint32_t *arg __asm__("r1") = block;
    __asm__ __volatile__("bkpt 0xab" : "+r"(op) : "r"(arg) : "memory");
    for (;;) {
    }
}
