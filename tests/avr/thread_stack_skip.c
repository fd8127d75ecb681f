/* A thread calls a function whose frame is deeper than the room left on
 * its stack, and writes only the frame's top byte: the frame reaches past
 * the guard into the stack below it (its neighbour's) without changing a
 * byte of either, so the kernel's guard check cannot see it, and the run
 * passed. openswarm-sim sees the stack pointer go below the stack's lowest
 * byte and fails the run at that instruction (avr.thread_stack_skip). */
#include "openswarm/kernel.h"
#include "openswarm/kilobot_sim.h"

#define STACK_BYTES 64

static void neighbour(void *arg) {
    (void)arg;
    for (;;) Sys_Sleep(100);
}

/* A 160-byte frame (the stack holds 64 bytes and the port's 64 for
 * interrupts and the switch), only its top byte used. */
static __attribute__((noinline)) uint8_t wide_frame(uint8_t v) {
    volatile uint8_t frame[160];
    frame[sizeof frame - 1] = v;
    return frame[sizeof frame - 1];
}

static void skipper(void *arg) {
    (void)arg;
    Sys_Sleep(10);
    (void)wide_frame(1);
    Sys_Sleep(10);
    sim_exit(0); /* the guard intact, the kernel saw nothing */
}

int main(void) {
    Sys_Init_Kernel();
    Sys_Start_Process_Ex(neighbour, NULL, STACK_BYTES, 0, NULL); /* the pool's lowest stack */
    Sys_Start_Process_Ex(skipper, NULL, STACK_BYTES, 0, NULL);   /* the one above it */
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
