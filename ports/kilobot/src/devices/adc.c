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

/* The temperature sensor is only measured against the internal 1.1 V
 * reference; every other input against AVcc. */
static uint8_t admux_for(uint8_t input) {
    uint8_t reference =
        input == KILOBOT_ADC_TEMPERATURE ? (uint8_t)(_BV(REFS1) | _BV(REFS0)) : (uint8_t)_BV(REFS0);
    return (uint8_t)(reference | (input & 0x0Fu));
}

void kilobot_adc_start(uint8_t input) {
    ADMUX = admux_for(input);
    ADCSRA = _BV(ADEN) | _BV(ADSC) | _BV(ADPS2) | _BV(ADPS1);
}

int16_t kilobot_adc_take(void) {
    while (ADCSRA & _BV(ADSC)) {
    }
    return (int16_t)ADC;
}

/* Interrupts stay masked for the conversion (as the classic library does):
 * the IR receiver's interrupt restarts the ADC on a distance channel, and a
 * conversion it cut into would return the distance reading. */
int16_t kilobot_adc_read(uint8_t input) {
    uint8_t sreg = SREG;
    cli();
    kilobot_adc_take(); /* one the IR receiver left running (a frame that stopped short) */
    kilobot_adc_start(input);
    int16_t value = kilobot_adc_take();
    SREG = sreg;
    return value;
}
