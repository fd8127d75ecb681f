/* Two steppers on one timer (step_schedule.h). */
#include "step_schedule.h"

/* The counts to the nearest step of a running motor, 0 if none runs. */
static uint16_t nearest(const step_schedule *s) {
    uint16_t next = 0;
    for (uint8_t m = 0; m < STEP_MOTORS; m++)
        if (s->period[m] != 0 && (next == 0 || s->due[m] < next)) next = s->due[m];
    return next;
}

/* Time moves on by `counts` (never past a running motor's step): the
 * motors whose step has come. */
static uint8_t advance(step_schedule *s, uint16_t counts) {
    uint8_t stepping = 0;
    for (uint8_t m = 0; m < STEP_MOTORS; m++) {
        if (s->period[m] == 0) continue;
        s->due[m] = s->due[m] > counts ? (uint16_t)(s->due[m] - counts) : 0u;
        if (s->due[m] == 0) {
            stepping |= (uint8_t)(1u << m);
            s->due[m] = s->period[m];
        }
    }
    return stepping;
}

uint16_t step_schedule_set(step_schedule *s, uint8_t motor, uint16_t period, uint16_t now) {
    /* The other motor keeps its rhythm: its next step stays where it was
     * (at least a count away: a step the stopped timer had just reached
     * comes at the next count). */
    for (uint8_t m = 0; m < STEP_MOTORS; m++) {
        if (s->period[m] == 0 || m == motor) continue;
        s->due[m] = s->due[m] > now ? (uint16_t)(s->due[m] - now) : 1u;
    }
    s->period[motor] = period;
    s->due[motor] = period;
    return nearest(s);
}

uint8_t step_schedule_tick(step_schedule *s, uint16_t elapsed, uint16_t *next) {
    uint8_t stepping = advance(s, elapsed);
    *next = nearest(s);
    return stepping;
}
