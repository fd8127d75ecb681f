/* The two vibration motors: Timer2 fast PWM (mode 3, 8 MHz / 8 / 256 =
 * 3.9 kHz) on OC2A = PB3 (left) and OC2B = PD3 (right). Mode 3 because
 * simavr 1.6 does not implement phase-correct PWM (mode 1) on this MCU. A
 * duty of 0 disconnects the pin: fast PWM would still emit a 1-count pulse. */
#include "openswarm/kilobot.h"

#include <avr/io.h>

static void pwm_start(void) {
    DDRB |= _BV(PB3);
    DDRD |= _BV(PD3);
    PORTB &= (uint8_t)~_BV(PB3);
    PORTD &= (uint8_t)~_BV(PD3);
    TCCR2A = _BV(WGM21) | _BV(WGM20);
    TCCR2B = _BV(CS21);
}

void kilobot_motors_apply(uint8_t left, uint8_t right) {
    if (!(TCCR2B & _BV(CS21))) pwm_start();
    OCR2A = left;
    OCR2B = right;
    uint8_t com = TCCR2A & (uint8_t)~(_BV(COM2A1) | _BV(COM2B1));
    if (left != 0) com |= _BV(COM2A1);
    if (right != 0) com |= _BV(COM2B1);
    TCCR2A = com;
}

static void motors_write(sys_device *dev, const void *raw, uint8_t size) {
    (void)dev;
    if (size < sizeof(kilobot_motors)) return;
    const kilobot_motors *m = raw;
    kilobot_motors_apply(m->left, m->right);
}

sys_device kilobot_motor_pair = {"motors", SYS_DEVICE_OUTPUT, KILOBOT_EVENT_MOTORS, 0, NULL, NULL,
                                 motors_write, NULL, 0};
