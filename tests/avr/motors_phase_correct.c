/* The motors driven the classic Kilobot library's way: Timer2 in
 * phase-correct PWM (mode 1, clock / 8), OC2A = PB3 left and OC2B = PD3
 * right, non-inverting. No kernel. Steps, STEP_MS apart (checked by ctest
 * against motors_phase_correct.expected through --trace-csv):
 *   left 100 right 200; left 0 right 50; the left pin disconnected with its
 *   duty at 90 (it shows 0), right 60; inverting on the right (255 - 60);
 *   then fast PWM (mode 3), as our own port drives them, 30 and 40. */
#include <util/delay.h>

#include "openswarm/kilobot_sim.h"

#define STEP_MS 100

static void step(uint8_t tccr2a, uint8_t left, uint8_t right) {
    TCCR2A = tccr2a;
    OCR2A = left;
    OCR2B = right;
    _delay_ms(STEP_MS);
}

int main(void) {
    DDRB |= _BV(PB3);
    DDRD |= _BV(PD3);
    TCCR2A = _BV(WGM20);
    TCCR2B = _BV(CS21);
    _delay_ms(STEP_MS);
    uint8_t both = _BV(COM2A1) | _BV(COM2B1);
    step(both | _BV(WGM20), 100, 200);
    step(both | _BV(WGM20), 0, 50);
    step(_BV(COM2B1) | _BV(WGM20), 90, 60);
    step(both | _BV(COM2B0) | _BV(WGM20), 90, 60);
    step(both | _BV(WGM21) | _BV(WGM20), 30, 40);
    sim_exit(0);
}
