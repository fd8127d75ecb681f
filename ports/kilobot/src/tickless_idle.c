/* Tickless idle (OS_CFG_TICKLESS): while every thread waits, the robot
 * sleeps with the 1 ms tick's interrupt off until the kernel's next
 * deadline, or until an interrupt comes first.
 *
 * Timer0 keeps counting through the sleep, in the same CTC mode: only its
 * interrupt enable changes, so the tick's phase never drifts, however long
 * the robot sleeps, and its compare flag tells apart the ticks already
 * counted. The alarm is Timer1's compare A: Timer1 counts CPU cycles, free
 * running (the IR receiver timestamps its pulses with it), so it also tells
 * exactly how long the robot slept. It wraps every 8.192 ms: a long sleep
 * is a chain of alarms at most 7 ms apart, each a few dozen cycles.
 * (Timer2 is the motors' PWM, not free while they run; Timer0 itself would
 * reach 32.8 ms with the /1024 prescaler, but simavr 1.6 restarts a
 * timer's count at each change of its clock, so the phase would be lost.)
 *
 * The alarms of the chain come in the middle of a millisecond, half a tick
 * from the ticks on either side, so which ticks lie before one never
 * depends on the prescaler's phase (the 0-63 cycles between a Timer0 count
 * and the next, which software cannot read); the last comes just past the
 * deadline's tick, 8 to 80 cycles after it: the kernel's time, timeouts
 * and kilo_ticks are exact; the thread runs about 36 us later than the
 * tick's own interrupt would have woken it. */
#include "openswarm/kilobot.h"
#include "openswarm/port.h"

#include <avr/interrupt.h>
#include <avr/io.h>

#include "devices/devices_internal.h"

#if OS_CFG_TICKLESS

#define CYCLES_PER_TICK (F_CPU / 1000u)
#define HALF_TICK (CYCLES_PER_TICK / 2u)
#define PAST_TICK 8u /* the last alarm, after the deadline's tick */
/* Alarms at most 7 ticks apart: then every time Timer1 is read while
 * asleep is within 7.5 ticks (60000 cycles) of the tick before the last
 * alarm, or of the sleep's start, and its count (which wraps at 65536)
 * tells how far. */
#define ALARM_MAX_TICKS 7u
#define SLEEP_MAX_TICKS 65535u /* then the robot wakes, credits them, and sleeps on */

/* AWAKE: the tick runs, every tick is credited. ASLEEP: the tick's
 * interrupt is off, the chain of alarms runs. ENDED: the last alarm came
 * (the tick is not back yet). OWED: the tick is back, the ticks slept
 * (slept) are not credited yet. */
enum { AWAKE, ASLEEP, ENDED, OWED };
static volatile uint8_t state;
static uint16_t slept;

/* Ticks are counted from the sleep's start. The last alarm that came (or
 * the start) was last_ticks ticks in; the tick before it (at it, for the
 * last alarm) was at Timer1 count last_tick, or up to 72 cycles earlier
 * (the prescaler's phase, and the time between reading Timer0 and Timer1). */
static uint16_t last_ticks, last_tick;
static uint16_t alarm_ticks; /* where the pending alarm (OCR1A) is */
static uint16_t final_ticks; /* the deadline */

/* The alarm after the one at last_ticks (or the start): the last, if the
 * deadline is at most 7 ticks on, else one in the middle of the 7th. */
static void set_alarm(void) {
    uint16_t left = final_ticks - last_ticks;
    if (left > ALARM_MAX_TICKS) {
        alarm_ticks = last_ticks + ALARM_MAX_TICKS;
        OCR1A = (uint16_t)(last_tick + ALARM_MAX_TICKS * CYCLES_PER_TICK + HALF_TICK);
    } else {
        alarm_ticks = final_ticks;
        OCR1A = (uint16_t)(last_tick + left * CYCLES_PER_TICK + PAST_TICK);
    }
}

/* The tick's interrupt goes off, the first alarm is set (at least 8000
 * cycles away); false if a tick is pending, or due within the 64 cycles of
 * Timer0's last count (it could come between the reads below and be
 * counted twice). */
static bool stop_tick(uint32_t ticks) {
    uint8_t count = TCNT0;
    uint16_t now = TCNT1;
    if (count == KILOBOT_TICK_COUNTS - 1u || (TIFR0 & _BV(OCF0A))) return false;
    TIMSK0 = 0;
    last_ticks = 0;
    last_tick = (uint16_t)(now - count * KILOBOT_TICK_PRESCALE);
    final_ticks = ticks > SLEEP_MAX_TICKS ? SLEEP_MAX_TICKS : (uint16_t)ticks;
    set_alarm();
    TIFR1 = _BV(OCF1A); /* Timer1 matched the old OCR1A at every wrap */
    TIMSK1 |= _BV(OCIE1A);
    state = ASLEEP;
    return true;
}

/* An alarm: the next one, or the sleep is over. Short: a long sleep has
 * one every 7 ms. */
ISR(TIMER1_COMPA_vect) {
    uint16_t at = OCR1A;
    last_ticks = alarm_ticks;
    if (last_ticks == final_ticks) {
        last_tick = (uint16_t)(at - PAST_TICK);
        TIMSK1 &= (uint8_t)~_BV(OCIE1A);
        state = ENDED;
        return;
    }
    last_tick = (uint16_t)(at - HALF_TICK);
    set_alarm();
}

/* Ticks from the sleep's start to now: those to the last alarm, the whole
 * ticks in the cycles since the tick before it, and one more if the
 * cycles left reach past the next tick, which Timer0's count says: it is
 * the position in the tick, less the prescaler's phase (the two differ by
 * less than 80 cycles, the answer by half a tick). */
static uint16_t ticks_slept(uint16_t cycles, uint8_t count) {
    uint16_t ticks = last_ticks;
    for (; cycles >= CYCLES_PER_TICK; cycles -= CYCLES_PER_TICK) ticks++;
    int16_t past = (int16_t)cycles - (int16_t)(count * KILOBOT_TICK_PRESCALE);
    if (past > (int16_t)HALF_TICK) ticks++; /* past is about 0 or a whole tick */
    return ticks;
}

void kilobot_tickless_stop(void) {
    if (state != ASLEEP && state != ENDED) return;
    TIMSK1 &= (uint8_t)~_BV(OCIE1A);
    if (state == ASLEEP && (TIFR1 & _BV(OCF1A))) { /* an alarm came, its interrupt not taken */
        last_ticks = alarm_ticks;
        last_tick = (uint16_t)(OCR1A - (last_ticks == final_ticks ? PAST_TICK : HALF_TICK));
    }
    /* A tick due within 64 cycles passes first: every tick is then either
     * before the reads (counted here, its flag cleared) or well after. */
    while (TCNT0 == KILOBOT_TICK_COUNTS - 1u) {
    }
    uint8_t count = TCNT0;
    uint16_t now = TCNT1;
    TIFR0 = _BV(OCF0A);
    TIMSK0 = _BV(OCIE0A);
    slept = ticks_slept((uint16_t)(now - last_tick), count);
    state = OWED;
}

/* The kernel's time first, then the application's clocks. */
void port_tickless_wake(void) {
    if (state == AWAKE) return;
    kilobot_tickless_stop();
    state = AWAKE;
    if (slept == 0) return;
    os_ticks_slept(slept);
    void (*hook)(uint16_t) = kilobot_elapsed_hook;
    if (hook != NULL) hook(slept);
}

void port_idle_for(uint32_t ticks) {
    if (ticks < 2u || kilobot_tick_needed() || !stop_tick(ticks)) {
        port_idle();
        return;
    }
    do port_idle(); /* the alarms of the chain come back here */
    while (state == ASLEEP);
    port_tickless_wake();
}
#endif
