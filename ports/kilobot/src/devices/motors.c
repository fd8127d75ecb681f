/* The two vibration motors: Timer2 fast PWM (mode 3, 8 MHz / 8 / 256 =
 * 3.9 kHz) on OC2A = PB3 (left) and OC2B = PD3 (right). Mode 3 because
 * simavr 1.6 does not implement phase-correct PWM (mode 1) on this MCU. A
 * duty of 0 disconnects the pin: fast PWM would still emit a 1-count pulse. */
#include "openswarm/kilobot.h"
#include "openswarm/port.h"

#include <avr/io.h>

#include "devices_internal.h"

/* Full-power limit armed by kilobot_spinup_limited. */
static uint16_t full_power_limit_ms;
static uint8_t full_power_fallback;
static uint16_t full_power_ms[2]; /* how long each motor has been at 255 */

static void pwm_start(void) {
    DDRB |= _BV(PB3);
    DDRD |= _BV(PD3);
    PORTB &= (uint8_t)~_BV(PB3);
    PORTD &= (uint8_t)~_BV(PD3);
    TCCR2A = _BV(WGM21) | _BV(WGM20);
    TCCR2B = _BV(CS21);
}

/* Both motors change at once: an interrupt between the writes would leave
 * the robot driving with one new and one old duty for its duration. */
void kilobot_motors_apply(uint8_t left, uint8_t right) {
    uint8_t com = (uint8_t)((left != 0 ? _BV(COM2A1) : 0) | (right != 0 ? _BV(COM2B1) : 0));
    port_irq_state_t s = port_irq_save();
    if (!(TCCR2B & _BV(CS21))) pwm_start();
    OCR2A = left;
    OCR2B = right;
    TCCR2A = (uint8_t)((TCCR2A & (uint8_t)~(_BV(COM2A1) | _BV(COM2B1))) | com);
    port_irq_restore(s);
}

/* Interrupt context, every 1 ms while a limit is armed. */
static void enforce_full_power_limit(void) {
    volatile uint8_t *ocr[2] = {&OCR2A, &OCR2B};
    for (uint8_t i = 0; i < 2; i++) {
        if (*ocr[i] != 255) {
            full_power_ms[i] = 0;
        } else if (++full_power_ms[i] > full_power_limit_ms) {
            *ocr[i] = full_power_fallback;
            full_power_ms[i] = 0;
        }
    }
}

/* The limit is checked by a tick hook that only this arms, so firmware
 * that never limits the motors carries neither the check nor its test. */
void kilobot_motors_limit_full_power(uint16_t limit_ms, uint8_t fallback) {
    port_irq_state_t s = port_irq_save();
    full_power_limit_ms = limit_ms;
    full_power_fallback = fallback;
    kilobot_motors_tick_hook = limit_ms != 0 ? enforce_full_power_limit : NULL;
    port_irq_restore(s);
}

void kilobot_motors_unlimit(void) {
    port_irq_state_t s = port_irq_save();
    kilobot_motors_tick_hook = NULL;
    port_irq_restore(s);
}

static void motors_write(sys_device *dev, const void *raw, uint8_t size) {
    (void)dev;
    if (size < sizeof(kilobot_motors)) return;
    const kilobot_motors *m = raw;
    kilobot_motors_apply(m->left, m->right);
}

sys_device kilobot_motor_pair = {"motors", SYS_DEVICE_OUTPUT, KILOBOT_EVENT_MOTORS, 0,
                                 kilobot_motor_commands, NULL, motors_write, NULL, 0};
