/* The e-puck's two steppers, as the e-puck library drives them: the four
 * coils of each from port pins, one full step (the next of four coil
 * patterns) at a time. Both are timed by Timer3 (the camera counts its
 * lines and frames with Timer4 and Timer5): its period is set to the
 * nearer motor's next step (step_schedule.c). 1000 steps a wheel turn. */
#include "board.h"

#include <stdlib.h>

#include "board_pins.h"
#include "dspic_compiler.h"
#include "dspic_port.h"
#include "step_schedule.h"
#include "../../src/epuck_board.h"
#include "p30f6014a_registers.h"

/* Timer3 counts Fcy / 256 = 57600 Hz: 57600 / speed counts a step
 * (57600 at 1 step/s fits in 16 bits; at 1000 steps/s, 58 counts: 993
 * steps/s, the rounding's 0.7%). */
#define STEP_CLOCK_HZ (DSPIC_FCY_HZ / 256u)

/* Coil patterns A..D (bit 0 = A): 0101, 0110, 1010, 1001 as A, B, C, D.
 * The left motor goes forward down the table, the right one up it (the
 * motors face opposite ways). */
static const uint8_t coil_patterns[4] = {0xA, 0x6, 0x5, 0x9};

enum { LEFT, RIGHT };
static const uint8_t coil_shift[STEP_MOTORS] = {LEFT_COILS_SHIFT, RIGHT_COILS_SHIFT};
static const int8_t forward[STEP_MOTORS] = {-1, 1}; /* the step through the table that drives forward */

/* Written masked, read by Timer3's interrupt. */
static step_schedule schedule;
static int8_t direction[STEP_MOTORS];
static uint8_t phase[STEP_MOTORS];

void board_steppers_init(void) {
    TRISD &= (uint16_t)~COIL_PINS;
    LATD &= (uint16_t)~COIL_PINS;
    IPC1 = (uint16_t)((IPC1 & ~(IPC_FIELD << IPC1_T3_SHIFT)) | (DSPIC_PRIORITY_STEPPERS << IPC1_T3_SHIFT));
}

static void set_coils(uint8_t motor, uint16_t pattern) {
    LATD = (uint16_t)((LATD & ~(0xFu << coil_shift[motor])) | (pattern << coil_shift[motor]));
}

static void step(uint8_t motor) {
    phase[motor] = (uint8_t)((phase[motor] + direction[motor]) & 3u);
    set_coils(motor, coil_patterns[phase[motor]]);
}

static void step_due(uint8_t stepping) {
    for (uint8_t m = 0; m < STEP_MOTORS; m++)
        if (stepping & (1u << m)) step(m);
}

/* The timer's next interrupt `counts` from now (0: stopped). PR3 + 1
 * counts pass from a match to the next. */
static void program_timer(uint16_t counts) {
    if (counts == 0) {
        T3CON = 0;
        IEC0 &= (uint16_t)~IRQ0_T3;
        return;
    }
    PR3 = (uint16_t)(counts - 1u);
}

/* Timer3 matched (PR3 + 1 counts after the last match): the motors due
 * step; the counts to the next step (0: none). */
static uint16_t on_match(void) {
    IFS0 &= (uint16_t)~IRQ0_T3;
    uint16_t next;
    step_due(step_schedule_tick(&schedule, (uint16_t)(PR3 + 1u), &next));
    return next;
}

DSPIC_ISR(_T3Interrupt);
DSPIC_ISR(_T3Interrupt) { program_timer(on_match()); }

/* Masked: Timer3's interrupt reads the schedule and writes PORTD's latch.
 * The timer stops while the schedule changes; a match it had just reached
 * (its interrupt pending) is served first. */
static void set_speed(uint8_t motor, int16_t speed) {
    port_irq_state_t s = port_irq_save();
    T3CON = 0;
    if (IFS0 & IRQ0_T3) (void)on_match();
    uint16_t period = 0;
    if (speed == 0) {
        set_coils(motor, 0); /* released: no current while standing */
    } else {
        unsigned long magnitude = (unsigned long)labs(speed);
        direction[motor] = (int8_t)(speed > 0 ? forward[motor] : -forward[motor]);
        period = (uint16_t)((STEP_CLOCK_HZ + magnitude / 2u) / magnitude);
    }
    uint16_t next = step_schedule_set(&schedule, motor, period, TMR3);
    program_timer(next);
    if (next != 0) {
        TMR3 = 0;
        IEC0 |= IRQ0_T3;
        T3CON = TCON_ON | TCON_PRESCALE_256;
    }
    port_irq_restore(s);
}

void epuck_board_set_wheels(int16_t left_speed, int16_t right_speed) {
    set_speed(LEFT, left_speed);
    set_speed(RIGHT, right_speed);
}
