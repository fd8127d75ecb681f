/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The OpenSwarm kernel's thread stacks' worst use, read from the firmware's
 * RAM. The kernel (OS_CFG_STACK_CHECK) carves them from os_stack_pool, puts
 * a 4-byte guard at each one's lowest address and keeps every byte of the
 * pool no live thread has used painted (kernel/src/stack_pool.c). So a
 * live stack is its guard, the paint the thread never reached, and what it
 * used, up to its top: the last byte that is not paint before the next
 * guard or the pool's end (free blocks above it are paint). The worst use
 * is from the lowest byte no longer paint, or the lowest the stack
 * watch saw its stack pointer reach if that is deeper (a frame reserved
 * but never written), to that top; a top byte that happens to equal the
 * paint shortens the stack's room by that byte.
 * Stacks are listed by address, which is the order threads started in
 * while none has ended. */
#include <string.h>

#include "sim.h"

#define PAINT 0xE7 /* kernel/src/kernel_internal.h's OS_STACK_PAINT */
static const uint8_t guard[STACK_GUARD_BYTES] = {0xA5, 0x5A, 0xC3, 0x3C}; /* its OS_STACK_GUARD */

int stack_guard_at(const uint8_t *ram, uint32_t i, uint32_t end) {
    return i + sizeof guard <= end && memcmp(ram + i, guard, sizeof guard) == 0;
}

int thread_stacks_read(const robot *r, uint32_t pool, uint32_t size, thread_stack *out, int room) {
    if (size == 0 || pool + size > r->avr->ramend + 1u) return -1;
    const uint8_t *ram = r->avr->data;
    uint32_t end = pool + size;
    int n = 0;
    for (uint32_t i = pool; i < end && n < room;) {
        if (!stack_guard_at(ram, i, end)) {
            i++;
            continue;
        }
        uint32_t deepest = i + sizeof guard;
        while (deepest < end && ram[deepest] == PAINT) deepest++;
        uint32_t top = deepest, k = deepest;
        for (; k < end && !stack_guard_at(ram, k, end); k++)
            if (ram[k] != PAINT) top = k + 1;
        uint32_t by_sp = stack_watch_thread_deepest(r, i); /* frames never written too */
        if (by_sp != 0 && by_sp < deepest) deepest = by_sp;
        out[n++] = (thread_stack){top - deepest, top - (i + (uint32_t)sizeof guard)};
        i = k;
    }
    return n;
}
