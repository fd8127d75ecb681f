/* Thread stacks, carved from one static pool in fixed-size blocks.
 *
 * The live threads' control blocks are the only record of what is used:
 * each holds its stack and its length in blocks, and a thread keeps its
 * stack until it is reaped. So the pool needs no bitmap. A new stack takes
 * the lowest gap large enough (first fit); such a gap starts at the pool's
 * start or right after a live stack, so those are the only places tried.
 * With OS_CFG_STACK_CHECK each stack's lowest bytes hold a guard pattern:
 * a thread that overflows its stack overwrites it, and the kernel checks it
 * at every scheduling decision a thread makes and at every tick. */
#include "kernel_internal.h"

#define BLOCK ((size_t)OS_CFG_STACK_BLOCK_BYTES)
#define BLOCKS ((size_t)OS_STACK_BLOCKS)

typedef char block_is_aligned[(OS_CFG_STACK_BLOCK_BYTES % PORT_STACK_ALIGN) == 0 ? 1 : -1];

static uint8_t pool[BLOCKS * BLOCK] __attribute__((aligned(PORT_STACK_ALIGN)));

static size_t first_block(const sys_tcb *t) { return (size_t)(t->stack - pool) / BLOCK; }

/* Do blocks [first, first + count) lie in the pool, clear of every live stack? */
static bool gap_is_free(size_t first, size_t count) {
    if (first + count > BLOCKS) return false;
    for (const sys_tcb *t = &os.threads[1]; t != &os.threads[OS_CFG_MAX_THREADS]; t++) {
        if (t->stack == NULL) continue;
        size_t f = first_block(t);
        if (first < f + t->stack_blocks && f < first + count) return false;
    }
    return true;
}

uint8_t *os_stack_alloc(uint16_t bytes, os_block_count *blocks, size_t *size) {
    /* Blocks for bytes, the port's extra and the guard; bytes is divided
     * first, so a size near 64 KiB cannot wrap round a 16-bit size_t. */
    size_t need = bytes / BLOCK + (bytes % BLOCK + PORT_STACK_EXTRA + OS_STACK_GUARD_BYTES + BLOCK - 1) / BLOCK;
    size_t best = BLOCKS; /* BLOCKS: no room */
    /* The pool's start is tried for every thread without a stack (the
     * system thread first), then the end of each live stack. */
    for (const sys_tcb *t = os.threads; t != &os.threads[OS_CFG_MAX_THREADS]; t++) {
        size_t at = t->stack == NULL ? 0 : first_block(t) + t->stack_blocks;
        if (at < best && gap_is_free(at, need)) best = at;
    }
    if (best == BLOCKS) return NULL;
    uint8_t *stack = &pool[best * BLOCK];
#if OS_CFG_STACK_CHECK
    static const uint8_t guard[OS_STACK_GUARD_BYTES] = OS_STACK_GUARD;
    for (unsigned i = 0; i < OS_STACK_GUARD_BYTES; i++) stack[i] = guard[i]; /* stores of constants */
#endif
    *blocks = (os_block_count)need;
    *size = need * BLOCK;
    return stack;
}

#if OS_CFG_STACK_CHECK
/* t's stack guard was found broken (os_check_stack): it has overflowed,
 * and is stopped before it runs on, unless it is ending anyway. */
void os_stack_overflowed(sys_tcb *t) {
    if (t->state == SYS_PROCESS_ZOMBIE) return;
    os_count(&os.stats.stack_overflows);
    os_fault(SYS_FAULT_STACK_OVERFLOW, t->pid);
    os_terminate(t);
}
#endif
