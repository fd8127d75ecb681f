#include "semihosting.h"

#include <stdint.h>
#include <string.h>

#define SYS_OPEN 0x01u
#define SYS_WRITE 0x05u
#define SYS_READ 0x06u
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

/* SYS_OPEN's modes are fopen's, numbered: 1 "rb", 9 "ab" (appending,
 * so a file given in place of a pipe is not truncated). */
int32_t semihosting_open(const char *path, bool for_writing) {
    uint32_t block[3] = {(uint32_t)(uintptr_t)path, for_writing ? 9u : 1u, (uint32_t)strlen(path)};
    return (int32_t)semihosting_call(SYS_OPEN, block);
}

/* SYS_READ and SYS_WRITE answer how many bytes were NOT moved. */
uint32_t semihosting_read(int32_t handle, void *data, uint32_t length) {
    uint32_t block[3] = {(uint32_t)handle, (uint32_t)(uintptr_t)data, length};
    uint32_t left = semihosting_call(SYS_READ, block);
    return left <= length ? length - left : 0;
}

bool semihosting_write(int32_t handle, const void *data, uint32_t length) {
    uint32_t block[3] = {(uint32_t)handle, (uint32_t)(uintptr_t)data, length};
    return semihosting_call(SYS_WRITE, block) == 0;
}
