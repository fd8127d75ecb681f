; Thread switch for the ATmega328P.
;
; port_switch(from, to) is an ordinary call, so the compiler has already
; saved the call-clobbered registers it needs; only the callee-saved ones
; (r2-r17, r28, r29) are pushed here. An interrupt that switches threads
; gets here from its C handler, whose prologue saved the rest. Called with
; interrupts masked, so the two halves of SP are written atomically.

#include <avr/io.h>

    .section .text.port_switch,"ax",@progbits
    .global port_switch
    .type port_switch, @function
; r25:r24 = from (port_context_t *: its first member is sp)
; r23:r22 = to
port_switch:
    push r2
    push r3
    push r4
    push r5
    push r6
    push r7
    push r8
    push r9
    push r10
    push r11
    push r12
    push r13
    push r14
    push r15
    push r16
    push r17
    push r28
    push r29
    movw r30, r24
    in r0, _SFR_IO_ADDR(SPL)
    st Z, r0
    in r0, _SFR_IO_ADDR(SPH)
    std Z+1, r0
    movw r30, r22
    ld r0, Z
    out _SFR_IO_ADDR(SPL), r0
    ldd r0, Z+1
    out _SFR_IO_ADDR(SPH), r0
    pop r29
    pop r28
    pop r17
    pop r16
    pop r15
    pop r14
    pop r13
    pop r12
    pop r11
    pop r10
    pop r9
    pop r8
    pop r7
    pop r6
    pop r5
    pop r4
    pop r3
    pop r2
    ret
    .size port_switch, .-port_switch

; First code of every thread: port_context_init leaves the entry function
; in r3:r2 and its argument in r5:r4 of the initial switch frame. r1 is
; already zero: port_switch is only ever called from C code.
    .section .text.port_thread_start,"ax",@progbits
    .global port_thread_start
    .type port_thread_start, @function
port_thread_start:
    movw r24, r4
    movw r30, r2
    sei
    icall
    jmp os_thread_exit
    .size port_thread_start, .-port_thread_start

; port_call_on_system_stack(system, fn): run fn on the system thread's
; stack. The system thread is suspended, so everything below its saved SP
; is free. fn is an ordinary C function: it preserves the callee-saved
; registers itself, so only the stack pointer changes hands. Interrupts are
; masked on entry and on fn's return, so SP is written atomically.
    .section .text.port_call_on_system_stack,"ax",@progbits
    .global port_call_on_system_stack
    .type port_call_on_system_stack, @function
; r25:r24 = system (port_context_t *), r23:r22 = fn
port_call_on_system_stack:
    in r18, _SFR_IO_ADDR(SPL)
    in r19, _SFR_IO_ADDR(SPH)
    movw r30, r24
    ld r20, Z
    ldd r21, Z+1
    out _SFR_IO_ADDR(SPL), r20
    out _SFR_IO_ADDR(SPH), r21
    push r18
    push r19
    movw r30, r22
    icall
    pop r19
    pop r18
    out _SFR_IO_ADDR(SPL), r18
    out _SFR_IO_ADDR(SPH), r19
    ret
    .size port_call_on_system_stack, .-port_call_on_system_stack
