/* The C half of the traps (traps.s): say what trapped and where, and decide
 * whether the trap struck a thread, which is then ended, or anything else
 * (an interrupt, a critical section, the system thread, an event handler
 * on its stack), which stops the robot: the kernel's state cannot be
 * trusted then. */
#include "dspic_port.h"
#include "openswarm/fault.h"
#include "p30f6014a_registers.h"

/* The trap frame's upper word: SR<7:0> in <15:8> (IPL<2:0> in <15:13>),
 * the IPL3 bit in <7>, PC<22:16> below. */
#define FRAME_IPL 0xE000u
#define FRAME_IPL3 0x0080u

uint16_t dspic_trap(uint16_t frame_high, uint16_t pc);
void dspic_thread_fault(uint16_t fault) __attribute__((noreturn));

static const char *trap_name(uint16_t flags) {
    if (flags & INTCON1_STKERR) return "stack error";
    if (flags & INTCON1_ADDRERR) return "address error";
    if (flags & INTCON1_MATHERR) return "math error (division by zero)";
    return "trap";
}

static bool struck_a_thread(uint16_t frame_high) {
    const port_context_t *running = dspic_running;
    return (frame_high & (FRAME_IPL | FRAME_IPL3)) == 0 && running != NULL && running->base != NULL;
}

/* The fault the thread is ended with, after the report; or no return. */
uint16_t dspic_trap(uint16_t frame_high, uint16_t pc) {
    uint16_t flags = INTCON1;
    INTCON1 = (uint16_t)(flags & ~(INTCON1_STKERR | INTCON1_ADDRERR | INTCON1_MATHERR));
    dspic_console_print("CPU trap: ");
    dspic_console_print(trap_name(flags));
    dspic_console_print(" at pc 0x");
    dspic_console_print_hex(pc);
    if (!struck_a_thread(frame_high)) {
        dspic_console_print(" outside any thread: stopped\n");
        dspic_stop();
    }
    dspic_console_print("\n");
    return (flags & INTCON1_STKERR) ? SYS_FAULT_STACK_OVERFLOW : SYS_FAULT_CPU;
}

void dspic_thread_fault(uint16_t fault) {
    os_thread_fault((uint8_t)fault);
    for (;;) {
        /* not reached: os_thread_fault ends the thread */
    }
}
