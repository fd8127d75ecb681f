/* A CPU fault in an interrupt handler cannot end a thread: the board
 * stops with the reason (qemu.isr_fault: exit status 3). */
#include "openswarm/kernel.h"
#include "test_target.h"

static void waiter(void *arg) {
    (void)arg;
    target_interrupt_in(100, 0);
    Sys_Sleep(10);
    target_puts("not stopped\n");
    target_exit(0);
}

void target_interrupt(int16_t value) {
    (void)value;
    __asm__ __volatile__("udf #1");
}

int main(void) {
    target_init();
    Sys_Init_Kernel();
    Sys_Start_Process_Ex(waiter, NULL, 256, 0, NULL);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    target_exit(1);
}
