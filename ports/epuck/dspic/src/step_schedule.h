/* Two steppers stepped from one timer (the camera takes the others): each
 * motor's next step is due some counts ahead; the timer's period is set to
 * the nearer, and at its interrupt the motors due step and the next period
 * is set. Plain C, no hardware: tested on the host
 * (tests/host/test_dspic_steps.cpp). */
#ifndef STEP_SCHEDULE_H
#define STEP_SCHEDULE_H

#include <stdint.h>

#define STEP_MOTORS 2u

typedef struct step_schedule {
    uint16_t period[STEP_MOTORS]; /* counts between two steps; 0: stopped */
    uint16_t due[STEP_MOTORS];    /* counts from the last interrupt to its next step */
} step_schedule;

/* Motor's steps now come every period counts (0: it stops), the first a
 * whole period from now, `now` counts after the last interrupt (the
 * timer stopped meanwhile). The counts from now to the next interrupt
 * (0: no motor runs: the timer stays off). */
uint16_t step_schedule_set(step_schedule *s, uint8_t motor, uint16_t period, uint16_t now);

/* At an interrupt, elapsed counts after the last: the motors that step
 * now (bit m for motor m); *next is the counts to the next interrupt (0:
 * none). */
uint8_t step_schedule_tick(step_schedule *s, uint16_t elapsed, uint16_t *next);

#endif
