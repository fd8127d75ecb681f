/* SLEEP in power-down mode, the way the classic Kilobot library sleeps
 * (its SLEEP state): Timer0 runs its 32.8 ms compare interrupt (clock /
 * 1024, as the classic's transmit timer) and Timer1 counts at clock / 1024;
 * the watchdog is armed for 8 s in interrupt mode. In power-down the
 * timers' clock stops, so only the watchdog wakes the robot, with Timer1
 * where it was. No kernel. It prints (checked by ctest)
 *   timer0 before N, while asleep 0; watchdog 1; timer1 advanced 0
 * and stops, at about 8.3 s (the watchdog's "8 s" are 2^20 cycles of its
 * 128 kHz oscillator, 8.19 s). */
#include <avr/wdt.h>

#include "openswarm/kilobot_sim.h"

static volatile uint8_t timer0_interrupts, watchdog_interrupts;

ISR(TIMER0_COMPA_vect) { timer0_interrupts++; }

ISR(WDT_vect) {
    watchdog_interrupts++;
    wdt_disable();
}

static void print(const char *label, uint16_t value) {
    sim_puts_P(label);
    sim_put_uint(value);
}

int main(void) {
    TCCR0A = 0;
    TCCR0B = _BV(CS02) | _BV(CS00);
    OCR0A = 0xFF;
    TIMSK0 = _BV(OCIE0A);
    TCCR1B = _BV(CS12) | _BV(CS10);
    sei();
    while (timer0_interrupts < 3) {} /* Timer0 is running: 100 ms */
    cli();
    uint8_t before = timer0_interrupts;
    wdt_enable(WDTO_8S);
    WDTCSR |= _BV(WDIE);
    set_sleep_mode(SLEEP_MODE_PWR_DOWN);
    uint16_t asleep_at = TCNT1;
    sleep_enable();
    sei();
    sleep_cpu();
    sleep_disable();
    cli();
    uint16_t advanced = TCNT1 - asleep_at;
    print(PSTR("timer0 before "), before);
    print(PSTR(", while asleep "), (uint8_t)(timer0_interrupts - before));
    print(PSTR("; watchdog "), watchdog_interrupts);
    print(PSTR("; timer1 advanced "), advanced);
    sim_putc('\n');
    sim_exit(0);
}
