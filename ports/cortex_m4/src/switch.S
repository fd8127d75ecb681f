/* Thread switch and interrupt epilogue for the Cortex-M4F (ARMv7E-M).
 *
 * Threads run in thread mode on the process stack (PSP); exceptions run on
 * the main stack (MSP). Every suspended thread was suspended the same way:
 * by port_switch, in thread mode, as an ordinary call - so only the
 * callee-saved registers are saved (r4-r11, lr; s16-s31 when the thread
 * has an FPU context, CONTROL.FPCA). An interrupt that makes the kernel
 * switch does not switch in handler mode: its end pends PendSV, which
 * returns into port_isr_epilogue in thread mode, on the interrupted
 * thread's stack, with the interrupted registers still in the hardware's
 * exception frame; there the kernel decides (port_switch, event handlers
 * on the system stack) like any thread would, and an SVC returns through
 * the original frame. */

    .syntax unified
    .cpu cortex-m4
    .fpu fpv4-sp-d16
    .thumb

    .equ KERNEL_MASK, 0x20          /* CORTEX_M4_PRIORITY_KERNEL */
    .equ CONTROL_FPCA, 4
    .equ EXC_RETURN_NO_FP, 0x10
    .equ EXC_RETURN_THREAD_PSP, 0xFFFFFFFD
    .equ XPSR_THUMB, 0x01000000
    .equ XPSR_ALIGNER, 0x200

/* port_switch(from, to): r0 = from, r1 = to (port_context_t *: sp first).
 * Called with BASEPRI masking; returns the same way when from resumes. */
    .section .text.port_switch,"ax",%progbits
    .global port_switch
    .type port_switch, %function
    .thumb_func
port_switch:
    push {r4-r11, lr}
    mrs r2, control
    tst r2, #CONTROL_FPCA
    it ne
    vpushne {s16-s31}
    push {r2}                       /* 40 or 104 bytes: 8-aligned */
    str sp, [r0]
    ldr sp, [r1]
    pop {r2}
    tst r2, #CONTROL_FPCA
    it ne
    vpopne {s16-s31}
    msr control, r2                 /* its FPCA: its next exceptions stack FP or not */
    isb
    pop {r4-r11, pc}
    .size port_switch, .-port_switch

/* First code of every thread: port_context_init leaves entry in r4 and
 * its argument in r5 of the initial switch frame. */
    .section .text.port_thread_start,"ax",%progbits
    .global port_thread_start
    .type port_thread_start, %function
    .thumb_func
port_thread_start:
    mov r0, r5
    movs r1, #0
    msr basepri, r1
    blx r4
    b os_thread_exit
    .size port_thread_start, .-port_thread_start

/* port_call_on_system_stack(system, fn): fn on the suspended system
 * thread's stack, below its switch frame (8-aligned). fn is a C function:
 * it keeps the callee-saved registers itself. */
    .section .text.port_call_on_system_stack,"ax",%progbits
    .global port_call_on_system_stack
    .type port_call_on_system_stack, %function
    .thumb_func
port_call_on_system_stack:
    push {r4, lr}
    mov r4, sp
    ldr r2, [r0]
    mov sp, r2
    blx r1
    mov sp, r4
    pop {r4, pc}
    .size port_call_on_system_stack, .-port_call_on_system_stack

/* PendSV: pended by the end of the last kernel-aware interrupt handler,
 * taken (lowest priority) when the CPU returns to the interrupted thread.
 * It masks the kernel's interrupts, makes the interrupted thread's FPU
 * registers be written into their frame now (a lazily stacked frame gets
 * them at the first FPU instruction; the epilogue may switch to a thread
 * that uses the FPU first), and returns into port_isr_epilogue(exc_return)
 * through a frame of its own on the thread's stack. */
    .section .text.PendSV_Handler,"ax",%progbits
    .global PendSV_Handler
    .type PendSV_Handler, %function
    .thumb_func
PendSV_Handler:
    movs r0, #KERNEL_MASK
    msr basepri, r0
    tst lr, #EXC_RETURN_NO_FP
    it eq
    vmrseq r0, fpscr                /* completes the lazy FP stacking */
    mrs r0, psp
    subs r0, #32                    /* a basic frame, still 8-aligned */
    str lr, [r0]                    /* r0: the interrupted frame's EXC_RETURN */
    ldr r1, =port_isr_epilogue
    bic r1, r1, #1
    str r1, [r0, #24]               /* pc */
    ldr r1, =XPSR_THUMB
    str r1, [r0, #28]               /* xpsr */
    msr psp, r0
    ldr lr, =EXC_RETURN_THREAD_PSP
    bx lr
    .size PendSV_Handler, .-PendSV_Handler

/* Thread mode, kernel interrupts masked, on the interrupted thread's
 * stack: r0 = the interrupted frame's EXC_RETURN. */
    .section .text.port_isr_epilogue,"ax",%progbits
    .type port_isr_epilogue, %function
    .thumb_func
port_isr_epilogue:
    push {r0, r1}
    tst r0, #EXC_RETURN_NO_FP
    bne 1f
    mrs r1, control                 /* the thread's FPU context is live: */
    orr r1, r1, #CONTROL_FPCA       /* port_switch must keep s16-s31 */
    msr control, r1
    isb
1:  bl cortex_m4_isr_decide
    mrs r1, control                 /* a basic frame for the SVC, so no */
    bic r1, r1, #CONTROL_FPCA       /* lazy FP state points at it */
    msr control, r1
    isb
    pop {r0, r1}
    svc #0
    b .                             /* not reached */
    .size port_isr_epilogue, .-port_isr_epilogue

/* SVC from port_isr_epilogue: drop its frame, unmask, and return through
 * the interrupted thread's own frame (r0 of the dropped frame says how). */
    .section .text.SVC_Handler,"ax",%progbits
    .global SVC_Handler
    .type SVC_Handler, %function
    .thumb_func
SVC_Handler:
    mrs r1, psp
    ldr r0, [r1]
    ldr r2, [r1, #28]
    adds r1, #32
    tst r2, #XPSR_ALIGNER
    it ne
    addne r1, #4
    msr psp, r1
    movs r1, #0
    msr basepri, r1
    bx r0
    .size SVC_Handler, .-SVC_Handler
