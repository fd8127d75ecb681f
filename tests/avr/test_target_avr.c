/* The firmware suites' target on the Kilobot under openswarm-sim: the
 * simulator's console register, Timer2 for interrupts, its exit record. */
#include "test_target.h"

#include "openswarm/kilobot_sim.h"
#include "openswarm/port.h"

#include <avr/interrupt.h>
#include <avr/io.h>

void target_init(void) {}

void target_puts(const char *text) { sim_puts_P(text); }
void target_putc(char c) { sim_putc(c); }
void target_put_uint(uint32_t value) { sim_put_uint(value); }
void target_exit(uint8_t status) {
    sim_exit(status);
    for (;;) {
    }
}

static volatile int16_t pending_value;

/* Timer2 fires one compare interrupt us microseconds from now. */
void target_interrupt_in(uint16_t us, int16_t value) {
    pending_value = value;
    TCCR2A = _BV(WGM21);
    TCNT2 = 0;
    OCR2A = (uint8_t)us;
    TIFR2 = _BV(OCF2A);
    TIMSK2 = _BV(OCIE2A);
    TCCR2B = _BV(CS21); /* 8 MHz / 8: 1 us per count */
}

ISR(TIMER2_COMPA_vect) {
    TCCR2B = 0;
    TIMSK2 = 0;
    os_isr_enter();
    target_interrupt(pending_value);
    os_isr_exit();
}
