/* e-puck (dsPIC30F6014A, Microchip XC16) port: the interrupt mask by CPU
 * priority, the 1 ms tick on Timer1, Idle mode, and a new thread's first
 * frame. The switch is in switch.s, the traps in traps.s and traps.c. */
#include <stddef.h>

#include "dspic_compiler.h"
#include "dspic_port.h"
#include "openswarm/config.h"
#include "openswarm/port.h"
#include "p30f6014a_registers.h"

void port_thread_start(void); /* switch.s */

typedef char context_offsets_match_switch_s[(offsetof(port_context_t, sp) == 0 &&
                                             offsetof(port_context_t, splim) == 2 &&
                                             offsetof(port_context_t, base) == 4)
                                                ? 1
                                                : -1];

port_context_t *volatile dspic_running;

/* Timer1 counts instruction cycles (prescaler 1:1) up to PR1 and restarts:
 * 14746 cycles = 1.0000271 ms at 14.7456 MHz (+27 ppm, 2.3 s a day).
 * 1:8 would give 1843 x 8 = 0.99989 ms (-109 ppm). */
#define TICK_PR1 ((uint16_t)(DSPIC_FCY_HZ / 1000u - 1u))

/* The console first, so a fault is never silent. */
void port_init(void) {
    dspic_console_init();
}

/* The initial switch frame, from the stack's start upwards, as port_switch
 * pops it: the return address, W8-W14, then the special registers. */
enum frame_word {
    FRAME_RETURN_LOW,  /* PC<15:0>: port_thread_start */
    FRAME_RETURN_HIGH, /* PC<22:16>: 0, XC16 function pointers are 16-bit handles */
    FRAME_W8,          /* the entry function */
    FRAME_W9,          /* its argument */
    FRAME_W10,
    FRAME_W11,
    FRAME_W12,
    FRAME_W13,
    FRAME_W14,
    FRAME_SR,
    FRAME_CORCON,
    FRAME_RCOUNT,
    FRAME_PSVPAG,
    FRAME_TBLPAG,
    FRAME_DCOUNT,
    FRAME_DOSTARTL,
    FRAME_DOSTARTH,
    FRAME_DOENDL,
    FRAME_DOENDH,
    FRAME_ACCAL,
    FRAME_ACCAH,
    FRAME_ACCAU,
    FRAME_ACCBL,
    FRAME_ACCBH,
    FRAME_ACCBU,
    FRAME_WORDS
};

/* The kernel's guard, if it keeps one, is the lowest 4 bytes: a stack
 * growing up starts above it. */
#define GUARD_BYTES (4u * OS_CFG_STACK_CHECK)

void port_context_init(port_context_t *ctx, void *stack, size_t size, void (*entry)(void *),
                       void *arg) {
    uint16_t *base = (uint16_t *)((uint8_t *)stack + GUARD_BYTES);
    uint16_t *top = (uint16_t *)((uint8_t *)stack + (size & ~(size_t)1u));
    for (unsigned w = 0; w < FRAME_WORDS; w++) base[w] = 0;
    base[FRAME_RETURN_LOW] = (uint16_t)port_thread_start;
    base[FRAME_W8] = (uint16_t)entry;
    base[FRAME_W9] = (uint16_t)arg;
    base[FRAME_SR] = SR_IPL_MASK; /* port_switch returns masked */
    /* The C environment's program-space window and modes, as start-up set them. */
    base[FRAME_CORCON] = CORCON & (uint16_t)~CORCON_IPL3;
    base[FRAME_PSVPAG] = PSVPAG;
    base[FRAME_TBLPAG] = TBLPAG;
    ctx->sp = base + FRAME_WORDS;
    ctx->splim = top - DSPIC_TRAP_ROOM_BYTES / 2u - 1u;
    ctx->base = base;
}

port_irq_state_t port_irq_save(void) {
    port_irq_state_t previous = SR & SR_IPL_MASK;
    SR |= SR_IPL_MASK;
    DSPIC_BARRIER();
    return previous;
}

void port_irq_restore(port_irq_state_t state) {
    DSPIC_BARRIER();
    SR = (uint16_t)((SR & (uint16_t)~SR_IPL_MASK) | state);
}
void port_irq_enable(void) { port_irq_restore(0); }
void port_irq_disable(void) { (void)port_irq_save(); }

/* Idle with the CPU at priority 7: an enabled interrupt still ends Idle,
 * without being taken, so none is lost between the kernel's check and
 * the sleep; it is taken once the priority drops, in the NOPs' window. */
void port_idle(void) {
    DSPIC_IDLE();
    port_irq_enable();
    DSPIC_NOP();
    DSPIC_NOP();
    port_irq_disable();
}

void port_tick_start(void) {
    T1CON = 0;
    TMR1 = 0;
    PR1 = TICK_PR1;
    IPC0 = (uint16_t)((IPC0 & ~(IPC_FIELD << IPC0_T1_SHIFT)) | (DSPIC_PRIORITY_KERNEL << IPC0_T1_SHIFT));
    IFS0 &= (uint16_t)~IRQ0_T1;
    IEC0 |= IRQ0_T1;
    T1CON = TCON_ON | TCON_PRESCALE_1;
}

void dspic_isr_run(void (*body)(void)) {
    port_irq_state_t s = port_irq_save();
    os_isr_enter();
    body();
    os_isr_exit();
    port_irq_restore(s);
}

void (*dspic_tick_hook)(void);

static void tick(void) {
    os_tick();
    void (*hook)(void) = dspic_tick_hook;
    if (hook != NULL) hook();
}

DSPIC_ISR(_T1Interrupt);
DSPIC_ISR(_T1Interrupt) {
    IFS0 &= (uint16_t)~IRQ0_T1;
    dspic_isr_run(tick);
}
