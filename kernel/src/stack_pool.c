/* Thread stacks, carved from one static pool in fixed-size blocks.
 *
 * A bitmap marks used blocks; a stack is a run of contiguous blocks, found
 * first-fit. Each stack's lowest bytes hold a guard pattern: a thread that
 * overflows its stack overwrites it, and the kernel checks it at every
 * scheduling decision a thread makes and at every tick. */
#include "kernel_internal.h"

#include <string.h>

#define BLOCK ((size_t)OS_CFG_STACK_BLOCK_BYTES)
#define BLOCKS OS_STACK_BLOCKS

typedef char block_is_aligned[(OS_CFG_STACK_BLOCK_BYTES % PORT_STACK_ALIGN) == 0 ? 1 : -1];

static uint8_t pool[BLOCKS * BLOCK] __attribute__((aligned(PORT_STACK_ALIGN)));
static uint8_t used[(BLOCKS + 7) / 8];

static const uint8_t guard_pattern[OS_STACK_GUARD_BYTES] = OS_STACK_GUARD;

static bool block_used(size_t i) { return (used[i / 8] >> (i % 8)) & 1u; }

static void mark(size_t first, size_t count, bool in_use) {
    for (size_t i = first; i < first + count; i++) {
        if (in_use)
            used[i / 8] |= (uint8_t)(1u << (i % 8));
        else
            used[i / 8] &= (uint8_t)~(1u << (i % 8));
    }
}

void os_stack_pool_reset(void) { memset(used, 0, sizeof used); }

uint8_t *os_stack_alloc(uint16_t bytes, os_block_count *blocks, size_t *size) {
    size_t need = ((size_t)bytes + PORT_STACK_EXTRA + OS_STACK_GUARD_BYTES + BLOCK - 1) / BLOCK;
    size_t run = 0;
    for (size_t i = 0; i < BLOCKS; i++) {
        run = block_used(i) ? 0 : run + 1;
        if (run == need) {
            size_t first = i + 1 - need;
            uint8_t *stack = &pool[first * BLOCK];
            mark(first, need, true);
            memcpy(stack, guard_pattern, OS_STACK_GUARD_BYTES);
            *blocks = (os_block_count)need;
            *size = need * BLOCK;
            return stack;
        }
    }
    return NULL;
}

void os_stack_free(uint8_t *stack, os_block_count blocks) {
    mark((size_t)(stack - pool) / BLOCK, blocks, false);
}

/* A thread whose stack guard is broken has overflowed: it is stopped
 * before it runs on. Checked at every scheduling decision a thread makes
 * (yield, send, block, exit) and at every tick. */
void os_stop_if_overflowed(sys_tcb *t) {
    if (t->state == SYS_PROCESS_ZOMBIE || os_stack_guard_intact(t)) return;
    os.stats.stack_overflows++;
    os_fault(SYS_FAULT_STACK_OVERFLOW, t->pid);
    os_terminate(t);
}
