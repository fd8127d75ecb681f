/* From reset to main: the memory the C code expects, the FPU, the fault
 * traps, and main on the process stack as the kernel's system thread. */
#include "openswarm/cortex_m4.h"
#include "system_control.h"

#include <string.h>

/* The linker script's (ld/cortex_m4_sections.ld). */
extern uint32_t _sidata[], _sdata[], _edata[], _sbss[], _ebss[], _process_stack_top[];

int main(void);
void cortex_m4_start(void) __attribute__((noreturn, used));

/* Threads run on the process stack, exceptions on the main stack: main,
 * which becomes the system thread, moves to its own stack before any C
 * code has put something on the one it leaves to the exceptions. */
__attribute__((naked, noreturn)) void Reset_Handler(void) {
    __asm__ __volatile__("ldr r0, =_process_stack_top\n\t"
                         "msr psp, r0\n\t"
                         "movs r0, #2\n\t" /* CONTROL.SPSEL */
                         "msr control, r0\n\t"
                         "isb\n\t"
                         "b cortex_m4_start");
}

void cortex_m4_start(void) {
    SCB_CPACR |= SCB_CPACR_FPU_FULL;
    __asm__ __volatile__("dsb\n\tisb" ::: "memory");
    FPU_FPCCR |= FPU_FPCCR_LAZY;
    memcpy(_sdata, _sidata, (size_t)((char *)_edata - (char *)_sdata));
    memset(_sbss, 0, (size_t)((char *)_ebss - (char *)_sbss));
    /* A division by zero traps instead of giving 0; the configurable
     * faults are reported as themselves, not escalated to HardFault. */
    SCB_CCR |= SCB_CCR_DIV_0_TRP | SCB_CCR_STKALIGN;
    SCB_SHCSR |= SCB_SHCSR_FAULTS_ENABLE;
    board_init();
    board_halt(main());
}
