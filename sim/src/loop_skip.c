/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Finding loops that repeat exactly (loop_skip.h); lockstep.c skips them.
 *
 * What the comparison covers, and why it is enough (simavr 1.6): the CPU
 * is its registers, SREG (kept split in avr->sreg), SP and the I/O
 * registers, all in avr->data with the RAM, the PC, and the interrupt
 * state (the delay after SEI, the vectors pending and running). The
 * peripherals' own state changes only when the CPU touches one of their
 * registers - each has a callback or IRQs, wrapped here - or when one of
 * their cycle timers fires; the core's own calls to them (WDR, SPM) move
 * timers or need a register written first. Interrupts come from those.
 * Whatever else acts on a robot from outside (an IR edge, the overhead
 * controller, a power cut) is a timer too, or goes through
 * lockstep_settle. So a visit that finds all of it as the last one left
 * it, with no wrapped register touched and the timers as they were, has
 * seen a loop that will go on repeating until the first timer fires. */
#include "loop_skip.h"

#include <stdlib.h>
#include <string.h>

#include <sim_interrupts.h>

/* Visits without a repeat before the anchor is given up, and the wait
 * before the next (doubling up to the longest): a loop that computes
 * something new each time round, or polls a sensor, costs a copy of the
 * RAM only now and then. */
#define MAX_MISSES 4
#define FIRST_BACKOFF 256
#define LONGEST_BACKOFF 8192

static uint8_t tap_read(struct avr_t *avr, avr_io_addr_t addr, void *param) {
    loop_skip *s = param;
    s->touched = 1;
    const io_tap *t = &s->taps[AVR_DATA_TO_IO(addr)];
    return t->read != NULL ? t->read(avr, addr, t->read_param) : avr->data[addr];
}

static void tap_write(struct avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param) {
    loop_skip *s = param;
    s->touched = 1;
    const io_tap *t = &s->taps[AVR_DATA_TO_IO(addr)];
    if (t->write != NULL)
        t->write(avr, addr, v, t->write_param);
    else
        avr->data[addr] = v; /* what simavr does at a register without a write callback */
}

/* Registers that are plain memory to simavr need no wrapper: they are in
 * the compared state. */
static void tap_io(robot *r) {
    avr_t *avr = r->avr;
    loop_skip *s = r->skip;
    for (int i = 0; i < MAX_IOs; i++) {
        io_tap *t = &s->taps[i];
        if (avr->io[i].r.c != NULL || avr->io[i].irq != NULL) {
            t->read = avr->io[i].r.c;
            t->read_param = avr->io[i].r.param;
            avr->io[i].r.c = tap_read;
            avr->io[i].r.param = s;
        }
        if (avr->io[i].w.c != NULL || avr->io[i].irq != NULL) {
            t->write = avr->io[i].w.c;
            t->write_param = avr->io[i].w.param;
            avr->io[i].w.c = tap_write;
            avr->io[i].w.param = s;
        }
    }
}

static void untap_io(robot *r) {
    avr_t *avr = r->avr;
    for (int i = 0; i < MAX_IOs; i++) {
        const io_tap *t = &r->skip->taps[i];
        if (avr->io[i].r.c == tap_read) {
            avr->io[i].r.c = t->read;
            avr->io[i].r.param = t->read_param;
        }
        if (avr->io[i].w.c == tap_write) {
            avr->io[i].w.c = t->write;
            avr->io[i].w.param = t->write_param;
        }
    }
}

int loop_skip_attach(robot *r, avr_cycle_timer_t window_timer) {
    r->skip_anchor = LOOP_SKIP_NO_ANCHOR;
    loop_skip *s = calloc(1, sizeof *s);
    size_t size = (size_t)r->avr->ramend + 1;
    uint8_t *data = malloc(size);
    if (s == NULL || data == NULL) {
        free(s);
        free(data);
        return -1;
    }
    s->window_timer = window_timer;
    s->data = data;
    s->data_size = size;
    s->backoff = FIRST_BACKOFF;
    r->skip = s;
    tap_io(r);
    return 0;
}

void loop_skip_detach(robot *r) {
    if (r->skip == NULL) return;
    untap_io(r);
    free(r->skip->data);
    free(r->skip);
    r->skip = NULL;
    r->skip_anchor = LOOP_SKIP_NO_ANCHOR;
}

avr_cycle_count_t loop_skip_next_timer(const robot *r) {
    for (const avr_cycle_timer_slot_t *t = r->avr->cycle_timers.timer; t != NULL; t = t->next)
        if (t->timer != r->skip->window_timer) return t->when;
    return UINT64_MAX;
}

/* The timers but the window's, in order; -1 if more than fit. */
static int list_timers(const robot *r, timer_seen *out) {
    int n = 0;
    for (const avr_cycle_timer_slot_t *t = r->avr->cycle_timers.timer; t != NULL; t = t->next) {
        if (t->timer == r->skip->window_timer) continue;
        if (n == LOOP_SKIP_MAX_TIMERS) return -1;
        out[n++] = (timer_seen){t->timer, t->param, t->when};
    }
    return n;
}

static void keep_state(robot *r) {
    const avr_t *avr = r->avr;
    loop_skip *s = r->skip;
    s->since = avr->cycle;
    memcpy(s->sreg, avr->sreg, sizeof s->sreg);
    s->interrupt_state = avr->interrupt_state;
    s->running_ptr = avr->interrupts.running_ptr;
    s->n_timers = list_timers(r, s->timers);
    s->quiet_until = loop_skip_next_timer(r);
    memcpy(s->data, avr->data, s->data_size);
    s->touched = 0;
}

static int same_timers(const robot *r) {
    const loop_skip *s = r->skip;
    timer_seen now[LOOP_SKIP_MAX_TIMERS];
    int n = list_timers(r, now);
    return n >= 0 && n == s->n_timers && memcmp(now, s->timers, (size_t)n * sizeof *now) == 0;
}

/* Cheapest first: most visits that differ differ in a register. */
static int same_state(const robot *r) {
    const avr_t *avr = r->avr;
    const loop_skip *s = r->skip;
    return memcmp(avr->data, s->data, 32) == 0 && memcmp(avr->sreg, s->sreg, sizeof s->sreg) == 0 &&
           avr->interrupt_state == s->interrupt_state && avr->interrupts.running_ptr == s->running_ptr &&
           same_timers(r) && memcmp(avr->data, s->data, s->data_size) == 0;
}

/* Nothing but the CPU acted since the last visit, p cycles ago, and what
 * the robot's watches would see of the repeats is what they saw of this
 * one: interrupts on at some instruction (a masked stretch stays far
 * below --mask-limit), no handler overrun waiting to be named by the PC
 * (fault_place_after_window). */
static int quiet_repeat(const robot *r, avr_cycle_count_t p) {
    const avr_t *avr = r->avr;
    const loop_skip *s = r->skip;
    return p <= LOOP_SKIP_MAX_PERIOD && !s->touched && avr->cycle < s->quiet_until &&
           avr->state == cpu_Running && r->state == cpu_Running && !r->power_down.asleep &&
           !avr_has_pending_interrupts((avr_t *)avr) &&
           (r->masked_since == 0 || r->masked_since > s->since) && !r->console.overrun_pending &&
           !r->serial.overrun_pending;
}

static void anchor_here(robot *r) {
    r->skip_anchor = r->avr->pc;
    keep_state(r);
}

/* Given up for a while: the next anchor is wherever the robot is then. */
static void give_up(robot *r) {
    loop_skip *s = r->skip;
    r->skip_anchor = LOOP_SKIP_NO_ANCHOR;
    s->misses = 0;
    s->rearm_at = r->avr->cycle + s->backoff;
    if (s->backoff < LONGEST_BACKOFF) s->backoff *= 2;
}

static void missed(robot *r) {
    if (++r->skip->misses >= MAX_MISSES || r->avr->state != cpu_Running)
        give_up(r);
    else
        anchor_here(r);
}

avr_cycle_count_t loop_skip_repeats(robot *r) {
    loop_skip *s = r->skip;
    avr_cycle_count_t p = r->avr->cycle - s->since;
    if (p == 0) return 0; /* kept here, or skipped to here, this very cycle */
    if (!quiet_repeat(r, p) || !same_state(r)) {
        missed(r);
        return 0;
    }
    s->misses = 0;
    s->backoff = FIRST_BACKOFF;
    s->since = r->avr->cycle;
    s->period = p;
    return p;
}

/* A timer set from outside between windows (an IR edge) may fall due
 * before the next visit and leave no trace by then: it bounds the repeat. */
void loop_skip_window_start(robot *r) {
    loop_skip *s = r->skip;
    if (s->parked) return;
    avr_t *avr = r->avr;
    if (r->skip_anchor == LOOP_SKIP_NO_ANCHOR) {
        if (avr->cycle >= s->rearm_at && avr->state == cpu_Running) anchor_here(r);
        return;
    }
    if (avr->cycle - s->since > 2 * LOOP_SKIP_MAX_PERIOD) { /* never came back to the anchor */
        missed(r);
        return;
    }
    avr_cycle_count_t next = loop_skip_next_timer(r);
    if (next < s->quiet_until) s->quiet_until = next;
}

/* The watches' own clock moves with the cycles: a masked stretch under
 * way began that much later. */
void loop_skip_jump(robot *r, uint64_t periods) {
    loop_skip *s = r->skip;
    avr_cycle_count_t by = periods * s->period;
    r->avr->cycle += by;
    if (r->masked_since != 0) r->masked_since += by;
    s->since = r->avr->cycle;
    s->skipped += by;
}

void loop_skip_forget(robot *r) {
    loop_skip *s = r->skip;
    if (s == NULL) return;
    r->skip_anchor = LOOP_SKIP_NO_ANCHOR;
    s->parked = 0;
    s->misses = 0;
    s->backoff = FIRST_BACKOFF;
    s->rearm_at = 0;
}
