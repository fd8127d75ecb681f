/* Kilobot (ATmega328P at 8 MHz) port: interrupt mask, 1 ms tick on
 * Timer0, sleeping idle, and the initial frame of a new thread. */
#include "openswarm/port.h"
#include "openswarm/kilobot.h"
#include "devices/devices_internal.h"

#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>

void port_thread_start(void); /* switch.S */

#define SWITCH_FRAME_REGISTERS 18u

/* Idle sleep (timers keep running), enabled once for good: the only SLEEP
 * instructions are port_idle's and sim_exit's, so there is no stray one
 * for avr-libc's enable-just-before-sleeping guard to catch. */
void port_init(void) {
    SMCR = SLEEP_MODE_IDLE | _BV(SE);
    /* The stack pool's block size as an absolute symbol, no byte of code:
     * openswarm-sim's stack watch finds a thread's guard at a block's start
     * with it. */
    __asm__(".global os_stack_block_bytes\n\t.set os_stack_block_bytes, %0" ::"n"(OS_CFG_STACK_BLOCK_BYTES));
}

/* Push value below sp as CALL pushes a return address, low byte first.
 * (In C, GCC reaches each byte through X with an add and a subtract.) */
static uint8_t *push_word(uint8_t *sp, uint16_t value) {
    __asm__ __volatile__("st -%a0, %A1\n\tst -%a0, %B1" : "+e"(sp) : "r"(value) : "memory");
    return sp;
}

void port_context_init(port_context_t *ctx, void *stack, size_t size, void (*entry)(void *),
                       void *arg) {
    uint8_t *sp = (uint8_t *)stack + size;
    sp = push_word(sp, (uint16_t)port_thread_start); /* where port_switch's ret goes */
    sp = push_word(sp, (uint16_t)entry); /* r2, r3: what port_thread_start calls */
    sp = push_word(sp, (uint16_t)arg);   /* r4, r5: its argument */
    /* r6..r17, r28, r29: whatever the stack holds, as a C function saves
     * the callee-saved registers it uses before it uses them. SP is the
     * free byte below the last one pushed. */
    ctx->sp = sp - (SWITCH_FRAME_REGISTERS - 4u) - 1u;
}

port_irq_state_t port_irq_save(void) {
    port_irq_state_t sreg = SREG;
    cli();
    return sreg;
}

/* A compiler barrier too, as cli() is: what the critical section stored is
 * in memory before an interrupt can see it. */
void port_irq_restore(port_irq_state_t state) {
    __asm__ __volatile__("out __SREG__, %0" ::"r"(state) : "memory");
}
void port_irq_enable(void) { sei(); }
void port_irq_disable(void) { cli(); }

void port_idle(void) {
    sei();       /* the instruction after SEI runs before any interrupt: */
    sleep_cpu(); /* no wake-up is lost between the two */
    /* simavr 1.6 does not sleep while an interrupt is pending, and takes
     * a pending interrupt only after it has seen the I flag set for a few
     * instructions: without this window an interrupt that became pending
     * just before SLEEP would stay pending for ever (time would stop). */
    __asm__ __volatile__("nop\n\tnop\n\tnop" ::: "memory");
    cli();
}

/* 8 MHz / 64 / 125 = 1000 Hz. Tickless idle times its sleeps with Timer1
 * counting CPU cycles, as the IR receiver runs it (kilobot_ir_start). */
void port_tick_start(void) {
    TCCR0A = _BV(WGM01); /* CTC */
    OCR0A = (uint8_t)(KILOBOT_TICK_COUNTS - 1u);
    TIMSK0 = _BV(OCIE0A);
    TCCR0B = _BV(CS01) | _BV(CS00); /* KILOBOT_TICK_PRESCALE */
#if OS_CFG_TICKLESS
    TCCR1B |= _BV(CS10);
#endif
}

/* Most ticks need nothing but the time and the slice's count
 * (os_tick_quiet) and no hook wants them: they return at once, without
 * os_isr_enter and os_isr_exit. (avr-gcc still saves the call-clobbered
 * registers for every tick: the others call functions.) */
ISR(TIMER0_COMPA_vect) {
#if OS_CFG_QUIET_TICK
    if (!kilobot_tick_hooked() && os_tick_quiet()) return;
#endif
    os_isr_enter();
    kilobot_tick();
    os_isr_exit();
}
