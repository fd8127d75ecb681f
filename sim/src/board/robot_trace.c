/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The Kilobot's LED and motors as the robot shows them.
 *
 * LED: a channel bit lights when its pin is an output (DDR), PORT low.
 * Red PD5 (bit 0) and PD4 (bit 1), green PC3 and PC2, blue PC5 and PC4.
 * Motors: Timer2 PWM duty, OC2A left, OC2B right. simavr reports the duty
 * in fast PWM (our port's mode 3) but runs no PWM at all in phase-correct
 * mode (mode 1, the classic library's); in mode 1 the duty is read from the
 * registers instead, whenever one of them is written: OCR2x while COM2x is
 * non-inverting (10), 255 - OCR2x while inverting (11), 0 while the pin is
 * disconnected. The chip takes a new OCR2x at the count's top, up to half a
 * PWM period (255 us at clock / 8) after the write; the trace shows it at
 * the write.
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

/* Timer2's registers (data addresses) and its phase-correct mode. */
#define TCCR2A_ADDR 0xB0
#define TCCR2B_ADDR 0xB1
#define OCR2A_ADDR 0xB3
#define OCR2B_ADDR 0xB4
#define WGM22_BIT 0x08 /* in TCCR2B; WGM21:0 are TCCR2A's bits 1:0 */
#define PHASE_CORRECT_PWM 1

static void emit(robot_trace *t, const char *device, int a, int b, int c) {
    double s = (double)t->burst / (double)t->avr->frequency;
    if (t->print) {
        if (c >= 0)
            printf("%s[%10.6f s] %-6s red %d green %d blue %d\n", t->prefix, s, device, a, b, c);
        else
            printf("%s[%10.6f s] %-6s left %d right %d\n", t->prefix, s, device, a, b);
        stdout_flush();
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

static void motors_changed(robot_trace *t) {
    if (t->on_motors) t->on_motors(t->on_motors_ctx, t->index, t->pwm[0], t->pwm[1], t->avr->cycle);
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
    motors_changed(t);
    changed(t);
}

static void right_pwm(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    robot_trace *t = param;
    t->pwm[1] = (uint8_t)value;
    motors_changed(t);
    changed(t);
}

/* A pin's duty in phase-correct PWM, by its two COM2x bits. */
static int phase_correct_duty(uint8_t com, uint8_t ocr) {
    switch (com) {
    case 2: return ocr;
    case 3: return 255 - ocr;
    default: return 0; /* disconnected: the pin is a plain output */
    }
}

static void timer2_written(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    (void)value;
    robot_trace *t = param;
    const uint8_t *d = t->avr->data;
    int mode = (d[TCCR2A_ADDR] & 0x03) | (d[TCCR2B_ADDR] & WGM22_BIT) >> 1;
    if (mode != PHASE_CORRECT_PWM) return;
    uint8_t left = (uint8_t)phase_correct_duty(d[TCCR2A_ADDR] >> 6 & 0x03, d[OCR2A_ADDR]);
    uint8_t right = (uint8_t)phase_correct_duty(d[TCCR2A_ADDR] >> 4 & 0x03, d[OCR2B_ADDR]);
    if (left == t->pwm[0] && right == t->pwm[1]) return;
    t->pwm[0] = left;
    t->pwm[1] = right;
    motors_changed(t);
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
    static const avr_io_addr_t timer2_registers[] = {TCCR2A_ADDR, TCCR2B_ADDR, OCR2A_ADDR, OCR2B_ADDR};
    for (size_t i = 0; i < sizeof timer2_registers / sizeof timer2_registers[0]; i++)
        avr_irq_register_notify(avr_iomem_getirq(avr, timer2_registers[i], NULL, AVR_IOMEM_IRQ_ALL),
                                timer2_written, t);
}

void trace_led(const robot *r, uint8_t rgb[3]) {
    int red, green, blue;
    led_rgb(&r->trace, &red, &green, &blue);
    rgb[0] = (uint8_t)red;
    rgb[1] = (uint8_t)green;
    rgb[2] = (uint8_t)blue;
}

/* A change still settling when the run ends is reported too. */
void trace_flush(robot *r) {
    if (r->trace.burst != 0) settled(r->avr, 0, &r->trace);
}

void trace_reset(robot *r) {
    robot_trace *t = &r->trace;
    if (t->avr == NULL) return; /* not traced */
    t->ddrc = t->ddrd = 0;
    t->pwm[0] = t->pwm[1] = 0;
    motors_changed(t);
    changed(t);
}
