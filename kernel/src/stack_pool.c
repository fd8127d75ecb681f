/* Thread stacks, carved from one static pool in fixed-size blocks.
 *
 * The live threads' control blocks are the only record of what is used:
 * each holds its stack and its length in blocks, and a thread keeps its
 * stack until it is reaped. So the pool needs no bitmap. A new stack takes
 * the lowest gap large enough (first fit): the search starts at the pool's
 * start and jumps to the end of each live stack in the way.
 * With OS_CFG_STACK_CHECK each stack's lowest bytes hold a guard pattern:
 * a thread that overflows its stack overwrites it, and the kernel checks it
 * at every scheduling decision a thread makes and at every tick that leads
 * to one (at least once a slice). The rest of a free stack holds a paint
 * byte (OS_STACK_PAINT): painted at kernel start and when a stack is
 * freed, never when one is taken or used, so a thread's deepest use is the
 * lowest byte that is no longer paint (openswarm-sim reads it: its
 * --counters' thread stacks). */
#include "kernel_internal.h"

#include <string.h>

#define BLOCK ((size_t)OS_CFG_STACK_BLOCK_BYTES)
#define BLOCKS ((size_t)OS_STACK_BLOCKS)

typedef char block_is_aligned[(OS_CFG_STACK_BLOCK_BYTES % PORT_STACK_ALIGN) == 0 ? 1 : -1];

#ifdef PORT_STACK_POOL
/* The port keeps the pool (PORT_STACK_POOL: an address of BLOCKS * BLOCK
 * bytes, aligned): a native-mode robot's stacks are its own memory, apart
 * from the RAM image the simulator swaps (ports/native). */
#define os_stack_pool ((uint8_t *)PORT_STACK_POOL)
const size_t os_stack_pool_bytes = BLOCKS * BLOCK;
#else
/* Named for the simulator, which finds it by its symbol. */
static uint8_t os_stack_pool[BLOCKS * BLOCK] __attribute__((aligned(PORT_STACK_ALIGN)));
#endif

/* Block numbers and counts fit in os_block_count: one byte on robots,
 * where 16-bit arithmetic doubles the code. */
static os_block_count first_block(const sys_tcb *t) {
    return (os_block_count)((size_t)(t->stack - os_stack_pool) / BLOCK);
}

/* Where the search for count free blocks goes on after first: 0 if
 * blocks [first, first + count) lie clear of every live stack, else the end
 * of a live stack that overlaps them (always past first). */
static os_block_count past_overlap(os_block_count first, os_block_count count) {
    os_block_count end = (os_block_count)(first + count);
    for (const sys_tcb *t = &os.threads[1]; t != &os.threads[OS_CFG_MAX_THREADS]; t++) {
        if (t->stack == NULL) continue;
        os_block_count f = first_block(t);
        os_block_count f_end = (os_block_count)(f + t->stack_blocks);
        if (first < f_end && f < end) return f_end;
    }
    return 0;
}

size_t os_stack_alloc(sys_tcb *t, uint16_t bytes) {
    /* Blocks for bytes, the port's extra and the guard; bytes is divided
     * first, so a size near 64 KiB cannot wrap round a 16-bit size_t. */
    size_t blocks_needed = bytes / BLOCK + (bytes % BLOCK + PORT_STACK_EXTRA + OS_STACK_GUARD_BYTES + BLOCK - 1) / BLOCK;
    if (blocks_needed > BLOCKS) return 0;
    os_block_count need = (os_block_count)blocks_needed;
    os_block_count start = 0;
    for (os_block_count next; (next = past_overlap(start, need)) != 0; start = next) {
        if (need > (os_block_count)(BLOCKS - next)) return 0; /* no room */
    }
    uint8_t *stack = &os_stack_pool[(size_t)start * BLOCK];
#if OS_CFG_STACK_CHECK
    static const uint8_t guard[OS_STACK_GUARD_BYTES] = OS_STACK_GUARD;
    for (unsigned i = 0; i < OS_STACK_GUARD_BYTES; i++) stack[i] = guard[i]; /* stores of constants */
#endif
    t->stack = stack;
    t->stack_blocks = need;
    return (size_t)need * BLOCK;
}

#if OS_CFG_STACK_CHECK
/* A port whose tools mark stack frames (the host's AddressSanitizer)
 * forgets the last kernel's marks here. */
#ifndef PORT_STACK_POOL_FORGET
#define PORT_STACK_POOL_FORGET(pool, bytes) ((void)0)
#endif

void os_stack_pool_reset(void) {
    PORT_STACK_POOL_FORGET(os_stack_pool, BLOCKS * BLOCK);
    memset(os_stack_pool, OS_STACK_PAINT, BLOCKS * BLOCK);
}

void os_stack_free(sys_tcb *t) {
    memset(t->stack, OS_STACK_PAINT, (size_t)t->stack_blocks * BLOCK);
    t->stack = NULL;
}

/* t's stack guard was found broken (os_check_stack): it has overflowed,
 * and is stopped before it runs on, unless it is ending anyway. */
void os_stack_overflowed(sys_tcb *t) {
    if (t->state == SYS_PROCESS_ZOMBIE) return;
    os_count(&os_stats.stack_overflows);
    os_fault(SYS_FAULT_STACK_OVERFLOW, t->pid);
    os_terminate(t);
}
#endif
