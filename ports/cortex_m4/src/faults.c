/* CPU faults (HardFault, MemManage, BusFault, UsageFault). One in a
 * thread, outside the kernel, ends that thread as a kernel fault
 * (SYS_FAULT_CPU: reported, counted, SYS_EVENT_FAULT) and the robot goes
 * on; one anywhere else (an interrupt handler, the system thread, the
 * kernel with interrupts masked) stops the board with the reason. */
#include "openswarm/cortex_m4.h"
#include "openswarm/fault.h"
#include "openswarm/port.h"
#include "openswarm/process.h"
#include "system_control.h"

#define EXC_RETURN_THREAD_PSP_BITS 0xCu /* bit 3: to thread mode, bit 2: on PSP */
#define CFSR_STACKING_ERRORS ((1u << 4) | (1u << 12)) /* MSTKERR, STKERR: no usable frame */
#define XPSR_THUMB 0x01000000u

void cortex_m4_fault(uint32_t *frame, uint32_t exc_return, uint32_t basepri) __attribute__((used));
void port_thread_fault(uint32_t cfsr, uint32_t pc) __attribute__((noreturn, used));

/* What went wrong, in the words of the fault status (ARMv7-M B3.2.15). */
static const char *fault_reason(uint32_t cfsr, uint32_t hfsr) {
    if (cfsr & (1u << 25)) return "division by zero";
    if (cfsr & (1u << 24)) return "unaligned access";
    if (cfsr & (1u << 16)) return "undefined instruction";
    if (cfsr & (1u << 17)) return "invalid state (a call to an even address?)";
    if (cfsr & (1u << 18)) return "invalid exception return";
    if (cfsr & (1u << 19)) return "no coprocessor (FPU off?)";
    if (cfsr & 0xFFu) return "memory protection violation";
    if (cfsr & 0xFF00u) return "bus error (no memory at that address)";
    if (hfsr & (1u << 1)) return "vector table read error";
    return "hard fault";
}

static void describe(const char *where, uint32_t cfsr, uint32_t pc) {
    cortex_m4_print("CPU fault: ");
    cortex_m4_print(fault_reason(cfsr, SCB_HFSR));
    cortex_m4_print(" at pc 0x");
    cortex_m4_print_hex(pc);
    if (cfsr & (1u << 7)) { /* MMARVALID */
        cortex_m4_print(", address 0x");
        cortex_m4_print_hex(SCB_MMFAR);
    } else if (cfsr & (1u << 15)) { /* BFARVALID */
        cortex_m4_print(", address 0x");
        cortex_m4_print_hex(SCB_BFAR);
    }
    cortex_m4_print(where);
}

void cortex_m4_fault(uint32_t *frame, uint32_t exc_return, uint32_t basepri) {
    uint32_t cfsr = SCB_CFSR;
    SCB_CFSR = cfsr; /* write one to clear: the next fault reads fresh */
    bool in_thread = (exc_return & EXC_RETURN_THREAD_PSP_BITS) == EXC_RETURN_THREAD_PSP_BITS &&
                     (cfsr & CFSR_STACKING_ERRORS) == 0 && basepri == 0 &&
                     Sys_Get_ProcessID() != SYS_PID_SYSTEM;
    if (!in_thread) {
        describe(" outside any thread: stopped\n", cfsr, (cfsr & CFSR_STACKING_ERRORS) ? 0 : frame[6]);
        board_halt(3);
    }
    /* Return into port_thread_fault(cfsr, pc) in the faulting thread. */
    frame[0] = cfsr;
    frame[1] = frame[6];
    frame[6] = (uint32_t)(uintptr_t)port_thread_fault & ~1u;
    frame[7] = XPSR_THUMB;
}

void port_thread_fault(uint32_t cfsr, uint32_t pc) {
    describe("\n", cfsr, pc);
    os_thread_fault(SYS_FAULT_CPU);
    for (;;) {
        /* not reached: os_thread_fault ends the thread */
    }
}

/* Which stack holds the frame, and whether the kernel had interrupts
 * masked, decide; the C function does the rest. */
__attribute__((naked)) void HardFault_Handler(void) {
    __asm__ __volatile__("tst lr, #4\n\t"
                         "ite eq\n\t"
                         "mrseq r0, msp\n\t"
                         "mrsne r0, psp\n\t"
                         "mov r1, lr\n\t"
                         "mrs r2, basepri\n\t"
                         "push {r1, lr}\n\t"
                         "bl cortex_m4_fault\n\t"
                         "pop {r1, pc}");
}
void MemManage_Handler(void) __attribute__((alias("HardFault_Handler")));
void BusFault_Handler(void) __attribute__((alias("HardFault_Handler")));
void UsageFault_Handler(void) __attribute__((alias("HardFault_Handler")));
