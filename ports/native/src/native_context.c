/* Thread contexts of a native robot: each is its stack pointer; a new one
 * starts in native_context_start (native_switch.S) with the entry and its
 * argument in the frame's r12 and r13. */
#include "native_internal.h"

#include <string.h>

#include "openswarm/native_stack.h"
#include "openswarm/port.h"

/* The switch frame native_switch pops: the control words, then r15, r14,
 * r13, r12, rbx, rbp, and the return address. */
enum { FRAME_WORDS = 8, AT_R13 = 3, AT_R12 = 4, AT_RETURN = 7 };
#define MXCSR_AT_RESET 0x1F80u
#define X87_CONTROL_AT_RESET 0x037Fu

void *native_context_frame(void *stack, size_t size, void (*entry)(void *), void *arg) {
    uintptr_t top = ((uintptr_t)stack + size) & ~(uintptr_t)15;
    /* After the frame's return the stack is 16-byte aligned, as
     * native_context_start's call needs. */
    uint64_t *frame = (uint64_t *)(top - 16 - FRAME_WORDS * sizeof(uint64_t));
    memset(frame, 0, FRAME_WORDS * sizeof(uint64_t));
    frame[0] = MXCSR_AT_RESET | (uint64_t)X87_CONTROL_AT_RESET << 32;
    frame[AT_R13] = (uint64_t)(uintptr_t)arg;
    frame[AT_R12] = (uint64_t)(uintptr_t)entry;
    frame[AT_RETURN] = (uint64_t)(uintptr_t)native_context_start;
    return frame;
}

/* A thread starts with interrupts enabled, as on the robots. */
static void thread_start(void *ctx) {
    port_context_t *self = ctx;
    port_irq_enable();
    self->entry(self->arg);
    os_thread_exit();
}

void port_context_init(port_context_t *ctx, void *stack, size_t size, void (*entry)(void *),
                       void *arg) {
    ctx->entry = entry;
    ctx->arg = arg;
    ctx->sp = native_context_frame(stack, size, thread_start, ctx);
}

void port_switch(port_context_t *from, port_context_t *to) { native_switch(&from->sp, to->sp); }

/* Below the suspended system thread's saved frame, clear of the 128-byte
 * red zone a leaf function may use under its stack pointer. */
void port_call_on_system_stack(port_context_t *system, void (*fn)(void)) {
    uintptr_t sp = ((uintptr_t)system->sp - 128u) & ~(uintptr_t)15;
    native_call_on_stack(fn, (void *)sp);
}

void native_context_returned(void) {
    /* Only main's context can get here (a thread's start ends it first):
     * the program is over, as when main returns on the robot. */
    native_stop(0);
}

/* Below sp's 128-byte red zone, which the frame that read it may use. */
void native_run_afresh(uintptr_t sp, void (*fn)(void)) {
    port_irq_enable();
    native_call_on_stack(fn, (void *)((sp - 128u) & ~(uintptr_t)15));
    __builtin_unreachable();
}
