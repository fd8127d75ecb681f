/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The Kilobot's LED and motors as the robot shows them.
 *
 * LED: a channel bit lights when its pin is an output (DDR), PORT low.
 * Red PD5 (bit 0) and PD4 (bit 1), green PC3 and PC2, blue PC5 and PC4.
 * Motors: Timer2 PWM duty, OC2A left, OC2B right.
 *
 * A colour or a duty pair is written one register at a time; what the
 * robot shows is the state once the writes settle, so changes are reported
 * after SETTLE_CYCLES of quiet, stamped with the time the burst began. */
#include <avr_ioport.h>
#include <avr_timer.h>
#include <sim_cycle_timers.h>
#include <sim_io.h>

#include "sim.h"

#define SETTLE_CYCLES 200

static void emit(robot_trace *t, const char *device, int a, int b, int c) {
    double s = (double)t->burst / (double)t->avr->frequency;
    if (t->print) {
        if (c >= 0)
            printf("%s[%10.6f s] %-6s red %d green %d blue %d\n", t->prefix, s, device, a, b, c);
        else
            printf("%s[%10.6f s] %-6s left %d right %d\n", t->prefix, s, device, a, b);
        fflush(stdout);
    }
    if (t->csv)
        fprintf(t->csv, "%.6f,%llu,%d,%s,%d,%d,%d\n", s, (unsigned long long)t->burst, t->index,
                device, a, b, c < 0 ? 0 : c);
}

static int led_rgb(const robot_trace *t, int *r, int *g, int *b) {
    *r = ((t->ddrd >> 5) & 1) | (((t->ddrd >> 4) & 1) << 1);
    *g = ((t->ddrc >> 3) & 1) | (((t->ddrc >> 2) & 1) << 1);
    *b = ((t->ddrc >> 5) & 1) | (((t->ddrc >> 4) & 1) << 1);
    return *r | *g << 2 | *b << 4;
}

static avr_cycle_count_t settled(struct avr_t *avr, avr_cycle_count_t when, void *param) {
    (void)avr;
    (void)when;
    robot_trace *t = param;
    int r, g, b;
    int rgb = led_rgb(t, &r, &g, &b);
    if (rgb != t->shown_rgb) {
        t->shown_rgb = rgb;
        emit(t, "led", r, g, b);
    }
    if (t->pwm[0] != t->shown_pwm[0] || t->pwm[1] != t->shown_pwm[1]) {
        t->shown_pwm[0] = t->pwm[0];
        t->shown_pwm[1] = t->pwm[1];
        emit(t, "motors", t->pwm[0], t->pwm[1], -1);
    }
    t->burst = 0;
    return 0;
}

static void changed(robot_trace *t) {
    if (t->burst == 0) t->burst = t->avr->cycle;
    avr_cycle_timer_cancel(t->avr, settled, t);
    avr_cycle_timer_register(t->avr, SETTLE_CYCLES, settled, t);
}

static void ddrc_changed(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    robot_trace *t = param;
    t->ddrc = (uint8_t)value;
    changed(t);
}

static void ddrd_changed(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    robot_trace *t = param;
    t->ddrd = (uint8_t)value;
    changed(t);
}

static void left_pwm(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    robot_trace *t = param;
    t->pwm[0] = (uint8_t)value;
    changed(t);
}

static void right_pwm(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    robot_trace *t = param;
    t->pwm[1] = (uint8_t)value;
    changed(t);
}

void trace_attach(robot *r, int print, FILE *csv) {
    robot_trace *t = &r->trace;
    /* The robot starts dark and still: only changes are reported. */
    t->avr = r->avr;
    t->index = r->index;
    t->prefix = r->console.prefix;
    t->print = print;
    t->csv = csv;
    avr_t *avr = r->avr;
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('C'), IOPORT_IRQ_DIRECTION_ALL),
                            ddrc_changed, t);
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('D'), IOPORT_IRQ_DIRECTION_ALL),
                            ddrd_changed, t);
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_TIMER_GETIRQ('2'), TIMER_IRQ_OUT_PWM0),
                            left_pwm, t);
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_TIMER_GETIRQ('2'), TIMER_IRQ_OUT_PWM1),
                            right_pwm, t);
}

/* A change still settling when the run ends is reported too. */
void trace_flush(robot *r) {
    if (r->trace.burst != 0) settled(r->avr, 0, &r->trace);
}
