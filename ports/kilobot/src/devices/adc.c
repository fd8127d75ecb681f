/* The ADC, shared by the IR receiver (distance: ADC0 high gain, ADC1 low
 * gain), the sensors (battery ADC6, ambient light ADC7, the MCU's own
 * temperature sensor) and kilolib. Every conversion of the port starts and
 * ends here, so they all use the same reference and clock.
 *
 * The ADC clock is 8 MHz / 64 = 125 kHz, inside the 50-200 kHz the
 * datasheet asks for full 10-bit resolution: a conversion takes 13 ADC
 * clocks (104 us), 25 (200 us) for the first after the ADC is enabled. */
#include "openswarm/kilobot.h"

#include <avr/interrupt.h>
#include <avr/io.h>

#include "devices_internal.h"

/* The reader whose conversion the ADC holds (running, or done and not yet
 * collected), named by the address of one of its locals: readers suspended
 * at the same time are on different stacks, so no two share it. NULL when
 * no reader holds it; a start by anyone else clears it, which tells the
 * reader its result is gone. */
static const void *volatile reader;

/* The temperature sensor is only measured against the internal 1.1 V
 * reference; every other input against AVcc. */
static uint8_t admux_for(uint8_t input) {
    uint8_t reference =
        input == KILOBOT_ADC_TEMPERATURE ? (uint8_t)(_BV(REFS1) | _BV(REFS0)) : (uint8_t)_BV(REFS0);
    return (uint8_t)(reference | (input & 0x0Fu));
}

static bool converting(void) { return (ADCSRA & _BV(ADSC)) != 0; }

/* A reader's conversion is waited for: it cannot be cut short any sooner
 * (clearing ADEN stops it, but the next one is then a 25-clock first
 * conversion). One the IR receiver left running at a collision is not: the
 * ADC ignores this start, and the frame gets that conversion's high gain,
 * as it always did. */
void kilobot_adc_start(uint8_t input) {
    if (reader != NULL) {
        reader = NULL;
        while (converting()) {
        }
    }
    ADMUX = admux_for(input);
    ADCSRA = _BV(ADEN) | _BV(ADSC) | _BV(ADPS2) | _BV(ADPS1);
}

int16_t kilobot_adc_take(void) {
    while (converting()) {
    }
    return (int16_t)ADC;
}

/* The conversion runs with interrupts as the caller had them. In a thread
 * they are enabled, so the IR receiver's interrupt is not held back: at a
 * start pulse it takes the ADC over (kilobot_adc_start) for the distance,
 * and this reading is lost (-1), as the classic library's is during a
 * reception. */
int16_t kilobot_adc_read(uint8_t input) {
    uint8_t mine; /* only its address matters */
    uint8_t sreg = SREG;
    cli();
    if (converting()) { /* the IR receiver's, after a collision, or another reader's */
        SREG = sreg;
        return -1;
    }
    kilobot_adc_start(input);
    reader = &mine;
    SREG = sreg;
    while (converting()) {
    }
    cli();
    int16_t value = -1;
    if (reader == &mine) {
        value = (int16_t)ADC;
        reader = NULL;
    }
    SREG = sreg;
    return value;
}
