/* Stack switches for the native port on x86-64 (System V ABI).
 *
 * native_switch(save, to) is an ordinary call, so the compiler has already
 * saved the call-clobbered registers it needs: only the callee-saved ones
 * (rbx, rbp, r12-r15) and the control words of SSE (MXCSR) and x87 are
 * pushed, then the stack pointer changes hands. A new context's frame
 * (native_context.c) resumes into native_context_start. */
#if !defined(__x86_64__)
#error "the native port's stack switch is written for x86-64"
#endif

    .text
    .globl native_switch
    .hidden native_switch
    .type native_switch, @function
/* rdi = where to save this context's stack pointer, rsi = the one to resume */
native_switch:
    pushq %rbp
    pushq %rbx
    pushq %r12
    pushq %r13
    pushq %r14
    pushq %r15
    subq $8, %rsp
    stmxcsr (%rsp)
    fnstcw 4(%rsp)
    movq %rsp, (%rdi)
    movq %rsi, %rsp
    ldmxcsr (%rsp)
    fldcw 4(%rsp)
    addq $8, %rsp
    popq %r15
    popq %r14
    popq %r13
    popq %r12
    popq %rbx
    popq %rbp
    ret
    .size native_switch, .-native_switch

/* A new context's first code: r12 is its entry, r13 the argument; rsp is
 * 16-byte aligned here, as a call needs. An entry that returns goes on to
 * native_context_returned, which never does. */
    .globl native_context_start
    .hidden native_context_start
    .type native_context_start, @function
native_context_start:
    movq %r13, %rdi
    callq *%r12
    callq native_context_returned@PLT
    ud2
    .size native_context_start, .-native_context_start

/* native_call_on_stack(fn, sp): fn() with the stack pointer at sp (16-byte
 * aligned, below what must stay), then back. fn saves the callee-saved
 * registers itself. */
    .globl native_call_on_stack
    .hidden native_call_on_stack
    .type native_call_on_stack, @function
native_call_on_stack:
    pushq %rbp
    movq %rsp, %rbp
    movq %rsi, %rsp
    callq *%rdi
    movq %rbp, %rsp
    popq %rbp
    ret
    .size native_call_on_stack, .-native_call_on_stack

    .section .note.GNU-stack,"",@progbits
