/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* SLEEP in power-down mode (SMCR SM = 010), which simavr 1.6 treats as idle.
 *
 * In power-down the ATmega328P stops its I/O clock: Timer0, Timer1 and
 * Timer2 (synchronous, as a Kilobot runs it) stand still, counts and all,
 * and only the watchdog, an external or pin-change interrupt (or a TWI
 * address match) wake the CPU. simavr keeps the timers running, so their
 * interrupts wake a sleeping classic-library robot every 32.8 ms where a
 * real one sleeps until its 8 s watchdog.
 *
 * Here, just before a robot executes SLEEP with power-down selected and
 * sleep enabled, the timers' pending events are taken out of simavr's
 * schedule, with how long each had left; simavr then sleeps to the next
 * event left (the watchdog's, or the lockstep window's end), fast. Once the
 * robot runs again, the events go back with the time they had left and
 * each timer's count base moves by the time asleep, so the counts resume
 * where they stopped. The chip's wake-up delay (its start-up time) is not
 * modelled. */
#include <string.h>

#include <avr_timer.h>
#include <sim_cycle_timers.h>

#include "sim.h"


/* Does this module's memory hold param? Timers pass themselves, or a part
 * of themselves (a comparator), to their scheduled events. */
static int belongs_to(const avr_io_t *port, const void *param) {
    const char *base = (const char *)port, *p = param;
    return p >= base && p < base + sizeof(avr_timer_t);
}

static int is_timer(const avr_io_t *port) { return port->kind != NULL && strcmp(port->kind, "timer") == 0; }

static int scheduled_by_timer(const avr_t *avr, const void *param) {
    for (const avr_io_t *port = avr->io_port; port != NULL; port = port->next)
        if (is_timer(port) && belongs_to(port, param)) return 1;
    return 0;
}

void power_down_freeze(robot *r) {
    power_down *pd = &r->power_down;
    avr_t *avr = r->avr;
    pd->asleep = 1;
    pd->since = avr->cycle;
    pd->n_events = 0;
    for (avr_cycle_timer_slot_p s = avr->cycle_timers.timer; s != NULL; s = s->next) {
        if (!scheduled_by_timer(avr, s->param) || pd->n_events == MAX_FROZEN_EVENTS) continue;
        frozen_event *e = &pd->events[pd->n_events++];
        e->fn = s->timer;
        e->param = s->param;
        e->left = s->when > avr->cycle ? s->when - avr->cycle : 0;
    }
    for (int i = 0; i < pd->n_events; i++) avr_cycle_timer_cancel(avr, pd->events[i].fn, pd->events[i].param);
}

void power_down_thaw(robot *r) {
    power_down *pd = &r->power_down;
    avr_t *avr = r->avr;
    avr_cycle_count_t slept = avr->cycle - pd->since;
    for (avr_io_t *port = avr->io_port; port != NULL; port = port->next)
        if (is_timer(port)) ((avr_timer_t *)port)->tov_base += slept;
    for (int i = 0; i < pd->n_events; i++)
        avr_cycle_timer_register(avr, pd->events[i].left, pd->events[i].fn, pd->events[i].param);
    pd->asleep = 0;
}
