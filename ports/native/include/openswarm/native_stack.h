/* The native port's stack pointer, for code that moves it on the robot
 * (kilolib's activities restart from where their loop began). */
#ifndef OPENSWARM_NATIVE_STACK_H
#define OPENSWARM_NATIVE_STACK_H

#include <stdint.h>

static inline uintptr_t native_stack_pointer(void) {
    uintptr_t sp;
    __asm__ __volatile__("movq %%rsp, %0" : "=r"(sp));
    return sp;
}

/* fn, which never returns, with the stack below sp (what is at sp and
 * above stays) and interrupts enabled. */
void native_run_afresh(uintptr_t sp, void (*fn)(void)) __attribute__((noreturn));

#endif
