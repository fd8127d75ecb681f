/* The e-puck's eight IR proximity sensors: each emitter lights a pair
 * (sensors i and i + 4). Timer2 divides time into 1250 us periods, eight a
 * round (100 rounds a second); in each a pair is read 260 us after the
 * period starts, with its emitters off (even periods: the ambient light)
 * or pulsed since the start (odd ones: pulse and ambient). The ADC
 * converts the pair's two channels one after the other; the second's end
 * switches the emitters off (a pulse of about 290 us). A round's readings
 * go to the device layer, which subtracts. The same schedule as the
 * e-puck2's driver (ports/epuck/epuck2/drivers/proximity.c). */
#include "board.h"

#include "board_pins.h"
#include "dspic_compiler.h"
#include "dspic_port.h"
#include "../../src/epuck_board.h"
#include "p30f6014a_registers.h"

/* Timer2 at Fcy / 8 = 1.8432 MHz: 1250 us = 2304 counts exactly, the
 * sample point 260 us = 479 counts (259.9 us). */
#define PERIOD_COUNTS 2304u
#define SAMPLE_COUNTS 479u
#define PERIODS_PER_ROUND 8u

/* TAD = TCY x 20 / 2 = 678 ns (at least 667 ns for 12 bits); 8 TAD of
 * sampling and 14 of conversion: 15 us a channel. */
#define ADC_TIMING (ADCON3_SAMC(8u) | ADCON3_ADCS(19u))

static epuck_proximity_samples samples;
static uint8_t period;     /* in the round: pair period / 2, pulsed if odd */
static bool at_sample;     /* Timer2's next match: the sample point */
static bool second_sensor; /* the ADC converts the pair's i + 4 */

static unsigned pair(void) { return period / 2u; }
static bool pulsed(void) { return (period & 1u) != 0; }

static void emitters(unsigned which, bool on) {
    static const uint16_t f_pins[4] = {PULSE_PAIR0_PIN, PULSE_PAIR1_PIN, 0, 0};
    static const uint16_t g_pins[4] = {0, 0, PULSE_PAIR2_PIN, PULSE_PAIR3_PIN};
    if (on) {
        LATF |= f_pins[which];
        LATG |= g_pins[which];
    } else {
        LATF &= (uint16_t)~PULSE_PINS_F;
        LATG &= (uint16_t)~PULSE_PINS_G;
    }
}

static void convert(unsigned sensor) {
    ADCHS = (uint16_t)(PROXIMITY_FIRST_CHANNEL + sensor); /* CH0SA; CH0NA 0: against AVss */
    ADCON1 |= ADCON1_SAMP; /* conversion follows by itself (SSRC auto) */
}

void board_proximity_start(void) {
    TRISF &= (uint16_t)~PULSE_PINS_F;
    TRISG &= (uint16_t)~PULSE_PINS_G;
    emitters(0, false);
    ADPCFG &= (uint16_t)~PROXIMITY_ANALOG_PINS;
    ADCON1 = ADCON1_SSRC_AUTO; /* integer results, sampling started by SAMP */
    ADCON2 = 0;                /* AVdd and AVss, one channel, an interrupt each conversion */
    ADCON3 = ADC_TIMING;
    IPC1 = (uint16_t)((IPC1 & ~(IPC_FIELD << IPC1_T2_SHIFT)) | (DSPIC_PRIORITY_KERNEL << IPC1_T2_SHIFT));
    IPC2 = (uint16_t)((IPC2 & ~(IPC_FIELD << IPC2_ADC_SHIFT)) | (DSPIC_PRIORITY_KERNEL << IPC2_ADC_SHIFT));
    IFS0 &= (uint16_t)~IRQ0_T2;
    IFS0 &= (uint16_t)~IRQ0_ADC;
    IEC0 |= IRQ0_T2 | IRQ0_ADC;
    ADCON1 |= ADCON1_ADON;
    T2CON = 0;
    TMR2 = 0;
    PR2 = SAMPLE_COUNTS - 1u;
    at_sample = true;
    T2CON = TCON_ON | TCON_PRESCALE_8;
}

/* Timer2 restarts at each match: PR2 is the interval to the next one. */
DSPIC_ISR(_T2Interrupt);
DSPIC_ISR(_T2Interrupt) {
    IFS0 &= (uint16_t)~IRQ0_T2;
    if (at_sample) {
        PR2 = PERIOD_COUNTS - SAMPLE_COUNTS - 1u;
        second_sensor = false;
        convert(pair());
    } else {
        PR2 = SAMPLE_COUNTS - 1u;
        if (pulsed()) emitters(pair(), true);
    }
    at_sample = !at_sample;
}

static void deliver(void) { epuck_proximity_arrived(&samples); }

DSPIC_ISR(_ADCInterrupt);
DSPIC_ISR(_ADCInterrupt) {
    IFS0 &= (uint16_t)~IRQ0_ADC;
    unsigned sensor = pair() + (second_sensor ? 4u : 0u);
    (pulsed() ? samples.pulsed : samples.off)[sensor] = ADCBUF0;
    if (!second_sensor) {
        second_sensor = true;
        convert(sensor + 4u);
        return;
    }
    emitters(0, false);
    period = (uint8_t)((period + 1u) % PERIODS_PER_ROUND);
    if (period == 0) dspic_isr_run(deliver);
}
