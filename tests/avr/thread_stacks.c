/* Three threads with stacks of the same size: one puts a 100-byte buffer
 * on its stack, one 4 bytes, and one uses a little and ends (its stack is
 * freed). openswarm-sim --counters lists the live threads' stacks' worst
 * use by address (avr.sim_thread_stacks): the deep one's mark is about
 * 96 bytes above the shallow one's, and the ended thread's stack is no
 * longer listed. */
#include "openswarm/kernel.h"

#define STACK_BYTES 160

/* A buffer of n bytes on the caller's stack, every byte written. */
#define USE_STACK(n)                                                         \
    do {                                                                     \
        volatile uint8_t buffer[n];                                          \
        for (uint8_t i = 0; i < sizeof buffer; i++) buffer[i] = (uint8_t)i;  \
    } while (0)

static void deep(void *arg) {
    (void)arg;
    USE_STACK(100);
    for (;;) Sys_Sleep(100);
}

static void shallow(void *arg) {
    (void)arg;
    USE_STACK(4);
    for (;;) Sys_Sleep(100);
}

static void ends(void *arg) {
    (void)arg;
    USE_STACK(50);
}

int main(void) {
    Sys_Init_Kernel();
    Sys_Start_Process_Ex(deep, NULL, STACK_BYTES, 0, NULL);
    Sys_Start_Process_Ex(ends, NULL, STACK_BYTES, 0, NULL);
    Sys_Start_Process_Ex(shallow, NULL, STACK_BYTES, 0, NULL);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
