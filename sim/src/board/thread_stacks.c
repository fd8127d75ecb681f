/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The OpenSwarm kernel's thread stacks' worst use, read from the firmware's
 * RAM. The kernel (OS_CFG_STACK_CHECK) carves them from os_stack_pool, puts
 * a 4-byte guard at each one's lowest address and keeps every byte of the
 * pool no live thread has used painted (kernel/src/stack_pool.c). So a
 * live stack is its guard, the paint the thread never reached, and what it
 * used, up to its top: the last byte that is not paint before the next
 * guard or the pool's end (free blocks above it are paint). The worst use
 * is from the lowest byte no longer paint to that top; a frame reserved
 * deeper but never written would not show, and a top byte that happens to
 * equal the paint shortens the stack's room by that byte.
 * Stacks are listed by address, which is the order threads started in
 * while none has ended. */
#include <string.h>

#include "sim.h"

#define AVR_DATA_OFFSET 0x800000u
#define PAINT 0xE7 /* kernel/src/kernel_internal.h's OS_STACK_PAINT */
static const uint8_t guard[4] = {0xA5, 0x5A, 0xC3, 0x3C}; /* its OS_STACK_GUARD */

typedef struct stack_pool {
    uint32_t address, size; /* in data space; size 0: none */
} stack_pool;

static void note_symbol(const char *name, uint32_t value, uint32_t size, int type, void *ctx) {
    (void)type;
    stack_pool *p = ctx;
    size_t n = strlen("os_stack_pool");
    if (name == NULL || value < AVR_DATA_OFFSET || strncmp(name, "os_stack_pool", n) != 0) return;
    if (name[n] != '\0' && name[n] != '.') return; /* name.lto_priv.N under LTO */
    p->address = value - AVR_DATA_OFFSET;
    p->size = size;
}

/* Read once per firmware file: robots that share one share the answer. */
static stack_pool pool_of(const char *elf_path) {
    static const char *read_path;
    static stack_pool pool;
    if (elf_path != read_path) {
        pool = (stack_pool){0, 0};
        firmware_symbols(elf_path, note_symbol, &pool);
        read_path = elf_path;
    }
    return pool;
}

static int guard_at(const uint8_t *ram, uint32_t i, uint32_t end) {
    return i + sizeof guard <= end && memcmp(ram + i, guard, sizeof guard) == 0;
}

int thread_stacks_read(const robot *r, const char *elf_path, thread_stack *out, int room) {
    stack_pool p = pool_of(elf_path);
    if (p.size == 0 || p.address + p.size > r->avr->ramend + 1u) return -1;
    const uint8_t *ram = r->avr->data;
    uint32_t end = p.address + p.size;
    int n = 0;
    for (uint32_t i = p.address; i < end && n < room;) {
        if (!guard_at(ram, i, end)) {
            i++;
            continue;
        }
        uint32_t deepest = i + sizeof guard;
        while (deepest < end && ram[deepest] == PAINT) deepest++;
        uint32_t top = deepest, k = deepest;
        for (; k < end && !guard_at(ram, k, end); k++)
            if (ram[k] != PAINT) top = k + 1;
        out[n++] = (thread_stack){top - deepest, top - (i + (uint32_t)sizeof guard)};
        i = k;
    }
    return n;
}
