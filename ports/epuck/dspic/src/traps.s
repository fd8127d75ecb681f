; The dsPIC's traps that a thread can cause, in XC16's assembler: never
; assembled here (see README.md).
;
; Stack error: W15 went past SPLIM (a thread's stack overflowed: each
; thread's SPLIM is the top of its own block) or below the start of RAM.
; Address error: a misaligned word access or a jump outside memory. Math
; error: a division by zero. The CPU has stacked the PC and SR<7:0> where
; W15 pointed, possibly past the limit, so nothing more goes there: the
; handler moves to a stack of its own, and dspic_trap (traps.c) reports the
; trap and either stops the robot (it struck outside a thread) or names
; the fault. Then the thread is resumed in dspic_thread_fault, at priority
; 0, on its stack from its start (its frames are lost anyway), which ends
; it through os_thread_fault as any kernel fault.

    .include "p30f6014A.inc"

    .equ CTX_SPLIM, 2
    .equ CTX_BASE, 4
    .equ TRAP_STACK_BYTES, 64

    .section .nbss, bss, near
    .align 2
trap_stack:
    .space TRAP_STACK_BYTES

    .section .text, code
; One handler for the three: INTCON1 says which trapped. The interrupted
; thread's registers are not needed again.
    .global __StackError
    .global __AddressError
    .global __MathError
__StackError:
__AddressError:
__MathError:
    mov     [w15-2], w0     ; the frame's upper word: SR<7:0>, IPL3, PC<22:16>
    mov     [w15-4], w1     ; PC<15:0>
    mov     #(trap_stack + TRAP_STACK_BYTES - 2), w3
    mov     w3, SPLIM
    mov     #trap_stack, w15
    call    _dspic_trap     ; dspic_trap(frame_high, pc): returns the fault or stops
    mov     w0, w4
    mov     _dspic_running, w1
    mov     [w1+CTX_SPLIM], w2
    mov     w2, SPLIM
    mov     [w1+CTX_BASE], w15
    mov     #handle(_dspic_thread_fault), w2
    push    w2              ; a frame for RETFIE: PC<15:0>,
    clr     w2
    push    w2              ; then SR<7:0> = 0 (priority 0), IPL3 = 0, PC<22:16> = 0
    mov     w4, w0          ; dspic_thread_fault(fault)
    retfie

    .end
