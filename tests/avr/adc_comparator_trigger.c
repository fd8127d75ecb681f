/* ADC conversions started by the analog comparator (ADATE, ADTS = 001),
 * the way the classic Kilobot library measures a sender's distance. No
 * kernel. Two robots: uid 1 flashes its IR LED 2 x PULSES times; the other
 * arms the ADC on the high-gain channel (ADC0) and counts, in its comparator
 * interrupt (rising edges), the flashes and the conversions they started
 * (ADSC set). For the second half it selects another trigger source
 * (external interrupt 0, ADTS = 010): the flashes must start no conversion
 * then. At 50 mm it prints (checked by ctest)
 *   comparator: edges 20 conversions 20 reading 817; other source: edges 20 conversions 0 */
#include <avr/eeprom.h>

#include "openswarm/kilobot_sim.h"

#define PULSES 20u
#define PULSE_GAP_CYCLES 4000u /* a conversion and the interrupt fit between flashes */
#define UID_ADDRESS ((const uint8_t *)0xB0)

/* [0] while the comparator is the trigger source, [1] while another is. */
static volatile uint8_t edges[2], conversions[2];
static volatile uint16_t reading;

/* As the classic receiver does: wait for the conversion the flash started
 * (under way already: the interrupt runs a few cycles after the edge, a
 * conversion takes 104), then read it. After PULSES flashes the trigger
 * source changes, here, between two. */
ISR(ANALOG_COMP_vect) {
    uint8_t half = edges[0] == PULSES;
    edges[half]++;
    if (ADCSRA & _BV(ADSC)) {
        conversions[half]++;
        while (ADCSRA & _BV(ADSC)) {}
        if (!half) reading = ADCW;
    }
    if (edges[0] == PULSES) ADCSRB = _BV(ADTS1);
}

static void flash(void) {
    __builtin_avr_delay_cycles(1000); /* the receiver is armed before the first flash */
    for (uint8_t i = 0; i < 2u * PULSES; i++) {
        PORTB |= _BV(PB0);
        __builtin_avr_delay_cycles(8);
        PORTB &= (uint8_t)~_BV(PB0);
        __builtin_avr_delay_cycles(PULSE_GAP_CYCLES);
    }
    sim_exit(0);
}

static void print_half(uint8_t half) {
    sim_puts_P(PSTR("edges "));
    sim_put_uint(edges[half]);
    sim_puts_P(PSTR(" conversions "));
    sim_put_uint(conversions[half]);
}

int main(void) {
    if (eeprom_read_byte(UID_ADDRESS) == 1) {
        DDRB |= _BV(PB0);
        flash();
    }
    ADMUX = 0;
    ADCSRA = _BV(ADEN) | _BV(ADATE) | _BV(ADPS1) | _BV(ADPS0);
    ADCSRB = _BV(ADTS0);
    ACSR = _BV(ACIE) | _BV(ACIS1) | _BV(ACIS0);
    sei();
    while (edges[1] < PULSES) {}
    sim_puts_P(PSTR("comparator: "));
    print_half(0);
    sim_puts_P(PSTR(" reading "));
    sim_put_uint(reading);
    sim_puts_P(PSTR("; other source: "));
    print_half(1);
    sim_putc('\n');
    sim_exit(0);
}
