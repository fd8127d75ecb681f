; Thread switch for the dsPIC30F6014A, in XC16's assembler (GNU as for the
; dsPIC): never assembled here (XC16 is not in Debian); see README.md.
;
; The stack grows up: PUSH writes [W15++], POP reads [--W15]. C symbols
; carry a leading underscore. XC16's calling convention: arguments in W0,
; W1, ...; W0-W7 are the caller's to save, W8-W14 the callee's.
;
; port_switch(from, to) is an ordinary call, so the compiler has already
; saved W0-W7 it needs; an interrupt that switches threads gets here from
; its C handler, whose prologue saved W0-W7 and RCOUNT after the CPU
; stacked the PC and SR<7:0>. Saved here: W8-W14 and the CPU state one
; thread may leave different from another's: SR (the whole of it: the
; interrupt stacks only its low byte), CORCON, RCOUNT (a REPEAT in
; progress), PSVPAG and TBLPAG, the DO loop's registers (DCOUNT, DOSTART,
; DOEND: XC16 emits DO loops), and both DSP accumulators (the kernel and
; the board do not use the DSP engine; an app's __builtin_mac may, in any
; thread). SR's DA and CORCON's DL, the DO loop's status, are read-only:
; a thread switched out inside a DO loop is not resumed inside it
; correctly (see README.md, "uncertain"). Then W15 and SPLIM change hands.
; Called with the CPU at priority 7, returns the same way.

    .include "p30f6014A.inc"

    .equ CTX_SP, 0
    .equ CTX_SPLIM, 2

    .section .text, code
    .global _port_switch
; W0 = from, W1 = to (port_context_t *)
_port_switch:
    push.d  w8
    push.d  w10
    push.d  w12
    push    w14
    push    SR
    push    CORCON
    push    RCOUNT
    push    PSVPAG
    push    TBLPAG
    push    DCOUNT
    push    DOSTARTL
    push    DOSTARTH
    push    DOENDL
    push    DOENDH
    push    ACCAL
    push    ACCAH
    push    ACCAU
    push    ACCBL
    push    ACCBH
    push    ACCBU
    mov     w15, [w0+CTX_SP]
    mov     SPLIM, w2
    mov     w2, [w0+CTX_SPLIM]
    mov     w1, _dspic_running
    ; The new limit, then the new stack: no stack access in between (a
    ; push or pop there would be checked against the wrong limit), and the
    ; instruction after a SPLIM write does not read through W15.
    mov     [w1+CTX_SPLIM], w2
    mov     w2, SPLIM
    mov     [w1+CTX_SP], w15
    pop     ACCBU
    pop     ACCBH
    pop     ACCBL
    pop     ACCAU
    pop     ACCAH
    pop     ACCAL
    pop     DOENDH
    pop     DOENDL
    pop     DOSTARTH
    pop     DOSTARTL
    pop     DCOUNT
    pop     TBLPAG
    pop     PSVPAG
    pop     RCOUNT
    pop     CORCON
    pop     SR
    pop     w14
    pop.d   w12
    pop.d   w10
    pop.d   w8
    return

; First code of every thread: port_context_init leaves the entry function
; in W8 and its argument in W9 of the initial switch frame.
    .global _port_thread_start
_port_thread_start:
    mov     w9, w0
    bclr    SR, #5          ; CPU priority 7 -> 0: interrupts on
    bclr    SR, #6
    bclr    SR, #7
    call    w8
    goto    _os_thread_exit

; port_call_on_system_stack(system, fn): run fn on the suspended system
; thread's stack, above its saved W15 (all free: the stack grows up), with
; its limit. fn is an ordinary C function (it may use W0-W7), so what must
; survive it goes on that stack. The traps see the system's context as
; the running one meanwhile. Called and returns at priority 7.
    .global _port_call_on_system_stack
; W0 = system (port_context_t *), W1 = fn
_port_call_on_system_stack:
    mov     w15, w2
    mov     SPLIM, w3
    mov     _dspic_running, w4
    mov     [w0+CTX_SPLIM], w5
    mov     w5, SPLIM
    mov     [w0+CTX_SP], w15
    push    w2
    push    w3
    push    w4
    mov     w0, _dspic_running
    call    w1
    pop     w4
    pop     w3
    pop     w2
    mov     w4, _dspic_running
    mov     w3, SPLIM
    mov     w2, w15
    return

    .end
