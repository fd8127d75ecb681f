/* The e-puck's two steppers, driven as the e-puck library drives them:
 * the four coils of each from port pins, one full step (the next of four
 * coil patterns) per interrupt of its own timer, so the timer's period
 * sets the speed. 1000 steps a wheel turn. */
#include "board.h"

#include <stdlib.h>

#include "board_pins.h"
#include "dspic_compiler.h"
#include "dspic_port.h"
#include "../../src/epuck_board.h"
#include "p30f6014a_registers.h"

/* The timers count Fcy / 256 = 57600 Hz: a period of 57600 / speed
 * counts (57599 at 1 step/s fits in 16 bits; at 1000 steps/s, 58 counts:
 * 993 steps/s, the rounding's 0.7%). */
#define STEP_CLOCK_HZ (DSPIC_FCY_HZ / 256u)

/* Coil patterns A..D (bit 0 = A): 0101, 0110, 1010, 1001 as A, B, C, D.
 * The left motor goes forward down the table, the right one up it (the
 * motors face opposite ways). */
static const uint8_t coil_patterns[4] = {0xA, 0x6, 0x5, 0x9};

typedef struct stepper {
    volatile uint16_t *tcon, *pr, *tmr;
    volatile uint16_t *ifs, *iec;
    uint16_t irq;
    uint8_t shift;  /* the coils' first pin on PORTD */
    int8_t forward; /* the step through the table that drives forward */
} stepper;

static const stepper left = {&T5CON, &PR5, &TMR5, &IFS1, &IEC1, IRQ1_T5, LEFT_COILS_SHIFT, -1};
static const stepper right = {&T4CON, &PR4, &TMR4, &IFS1, &IEC1, IRQ1_T4, RIGHT_COILS_SHIFT, 1};

/* Written with the motor's timer stopped, read by its interrupt. */
static volatile int8_t left_step, right_step;
static uint8_t left_phase, right_phase;

void board_steppers_init(void) {
    TRISD &= (uint16_t)~COIL_PINS;
    LATD &= (uint16_t)~COIL_PINS;
    IPC5 = (uint16_t)((IPC5 & ~((IPC_FIELD << IPC5_T4_SHIFT) | (IPC_FIELD << IPC5_T5_SHIFT))) |
                      (DSPIC_PRIORITY_STEPPERS << IPC5_T4_SHIFT) |
                      (DSPIC_PRIORITY_STEPPERS << IPC5_T5_SHIFT));
}

static void set_coils(uint8_t shift, uint16_t pattern) {
    LATD = (uint16_t)((LATD & ~(0xFu << shift)) | (pattern << shift));
}

/* Masked: the other motor's interrupt writes PORTD's latch too. */
static void set_speed(const stepper *m, volatile int8_t *step, int16_t speed) {
    port_irq_state_t s = port_irq_save();
    *m->tcon = 0;
    *m->iec &= (uint16_t)~m->irq;
    if (speed == 0) {
        set_coils(m->shift, 0); /* released: no current while standing */
    } else {
        unsigned long magnitude = (unsigned long)labs(speed);
        *step = (int8_t)(speed > 0 ? m->forward : -m->forward);
        *m->pr = (uint16_t)((STEP_CLOCK_HZ + magnitude / 2u) / magnitude - 1u);
        *m->tmr = 0;
        *m->ifs &= (uint16_t)~m->irq;
        *m->iec |= m->irq;
        *m->tcon = TCON_ON | TCON_PRESCALE_256;
    }
    port_irq_restore(s);
}

/* With the camera (board.h) Timer4 and Timer5 count HREF and VSYNC and
 * are not touched here: the coils stay released (board_steppers_init). */
void epuck_board_set_wheels(int16_t left_speed, int16_t right_speed) {
    if (EPUCK_DSPIC_CAMERA) return;
    set_speed(&left, &left_step, left_speed);
    set_speed(&right, &right_step, right_speed);
}

static void step(const stepper *m, uint8_t *phase, int8_t direction) {
    *phase = (uint8_t)((*phase + direction) & 3u);
    set_coils(m->shift, coil_patterns[*phase]);
}

#if !EPUCK_DSPIC_CAMERA
DSPIC_ISR(_T5Interrupt);
DSPIC_ISR(_T5Interrupt) {
    IFS1 &= (uint16_t)~IRQ1_T5;
    step(&left, &left_phase, left_step);
}

DSPIC_ISR(_T4Interrupt);
DSPIC_ISR(_T4Interrupt) {
    IFS1 &= (uint16_t)~IRQ1_T4;
    step(&right, &right_phase, right_step);
}
#endif
