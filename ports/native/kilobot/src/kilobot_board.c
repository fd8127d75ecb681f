/* The Kilobot's board in the native mode: its clock hooks, what its LED
 * and motors show (read from the register file as the chip's pins would
 * drive them: ports/kilobot's led.c and motors.c run as they are), the
 * charger's pin. */
#include "native_internal.h"

#include <avr/io.h>

#include "devices/devices_internal.h"
#include "openswarm/kilobot.h"

volatile uint8_t native_avr_io[0x100] __attribute__((aligned(2)));

void native_board_tick(void) { kilobot_tick(); }
int native_board_tick_hooked(void) { return kilobot_tick_hooked(); }
int native_board_tick_needed(void) { return kilobot_tick_needed(); }

void native_board_elapsed(uint16_t ms) {
    void (*hook)(uint16_t) = kilobot_elapsed_hook;
    if (hook != NULL) hook(ms);
}

/* A pin lights its LED channel's bit when it is an output driven low
 * (led.c): red PD5 (bit 0) and PD4 (bit 1), green PC3 and PC2, blue PC5
 * and PC4. */
static uint8_t lit(uint8_t ddr, uint8_t port, uint8_t pin) {
    return (ddr & _BV(pin)) && !(port & _BV(pin));
}

static uint8_t led_shown(void) {
    uint8_t c = DDRC, d = DDRD, pc = PORTC, pd = PORTD;
    uint8_t r = (uint8_t)(lit(d, pd, PD5) | lit(d, pd, PD4) << 1);
    uint8_t g = (uint8_t)(lit(c, pc, PC3) | lit(c, pc, PC2) << 1);
    uint8_t b = (uint8_t)(lit(c, pc, PC5) | lit(c, pc, PC4) << 1);
    return KILOBOT_RGB(r, g, b);
}

/* A motor's duty: its compare value while Timer2 runs and its output is
 * connected (motors.c disconnects a motor at 0). */
static uint8_t duty(uint8_t compare, uint8_t connect_bit) {
    return (TCCR2B & 7u) != 0 && (TCCR2A & _BV(connect_bit)) ? compare : 0;
}

static uint8_t shown_left, shown_right;

int native_outputs_report(void) {
    native_io *io = native_io_of_robot;
    io->led = led_shown();
    uint8_t left = duty(OCR2A, COM2A1), right = duty(OCR2B, COM2B1);
    if (left == shown_left && right == shown_right) return 1;
    if (io->n_motors >= NATIVE_MOTOR_ROOM) return 0;
    io->motors[io->n_motors++] = (native_motor_change){native_now, left, right};
    shown_left = left;
    shown_right = right;
    return 1;
}

/* The image is as loaded: every register 0. The charger's status output
 * holds PD0 high, low while it charges. */
void native_board_power_up(void) {
    PIND = native_io_of_robot->charging ? 0 : _BV(PD0);
}

/* Its inputs come frame by frame (kilobot_ir.c), never whole. */
void native_board_inputs(void) {}
