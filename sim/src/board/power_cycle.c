/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A robot reset, or without power for a while (--faults reset, brownout).
 *
 * A reset is simavr's avr_reset: the CPU starts again at address 0 with
 * its I/O registers cleared, as after the chip's reset pin; RAM keeps what
 * it held (the firmware's start-up code sets .data and .bss again) and so
 * does the EEPROM. simavr 1.6 also cancels every cycle timer of the MCU,
 * and keeps its cycle count: the simulator's own timers (the IR channel's,
 * the overhead controller's, the lockstep's) are set again here, and the
 * robot stays in step with the others.
 *
 * A power cut resets the robot when it starts (LED dark, motors still),
 * then keeps it out of the lockstep until the power returns: it neither
 * runs nor hears, and its clock is moved to that moment; then it starts
 * from reset again. RAM is kept as it was (a real chip's would hold
 * garbage: firmware must not trust it, and the start-up code does not). */
#include <string.h>

#include <avr_ioport.h>
#include <avr_timer.h>
#include <sim_io.h>

#include "faults/faults.h"
#include "lockstep.h"
#include "loop_skip.h"

/* avr_reset clears the registers but not the values simavr's output IRQs
 * last carried, and a raise to the value an IRQ holds may notify nobody:
 * after a reset the LED's DDR bits set as before, or the IR LED lit again,
 * would go unseen (the trace, the IR channel). Lowered here, as the pins
 * are now; whoever listens is told. */
static void outputs_as_at_reset(avr_t *avr) {
    static const char ports[] = {'B', 'C', 'D'};
    for (size_t i = 0; i < sizeof ports; i++)
        avr_raise_irq(avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ(ports[i]), IOPORT_IRQ_DIRECTION_ALL), 0);
    avr_raise_irq(avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('B'), IOPORT_IRQ_PIN0), 0); /* the IR LED */
    avr_raise_irq(avr_io_getirq(avr, AVR_IOCTL_TIMER_GETIRQ('2'), TIMER_IRQ_OUT_PWM0), 0);
    avr_raise_irq(avr_io_getirq(avr, AVR_IOCTL_TIMER_GETIRQ('2'), TIMER_IRQ_OUT_PWM1), 0);
}

static void start_again(robot *r) {
    loop_skip_forget(r);
    avr_reset(r->avr);
    r->avr->state = cpu_Running;
    r->state = cpu_Running;
    memset(&r->power_down, 0, sizeof r->power_down);
    r->doze_until = 0;
    r->wake_registered = 0;
    r->masked_since = 0;
    stack_watch_reset(r);
    board_pins_again(r->avr);
    outputs_as_at_reset(r->avr);
    trace_reset(r);
    console_reset(r);
    ir_channel_robot_reset(r->index);
}

static robot *robots;
static uint32_t nominal_hz;

static int can_fault(int i) {
    const robot *r = &robots[i];
    return !robot_finished(r) && !robot_at_bootloader(r) && r->off_until == 0;
}

static avr_cycle_count_t off_until(int i) { return robots[i].off_until; }

/* The reset comes at the instruction the robot reached, and RAM keeps
 * what it held then: a robot parked at a loop's head runs on to it first. */
static void reset(int i, avr_cycle_count_t now) {
    (void)now; /* between windows, every robot is there */
    robot *r = &robots[i];
    lockstep_settle(r);
    start_again(r);
    ohc_robot_reset(r);
}

/* Out of the lockstep until power_on: a robot dozing until the power
 * returned would run the whole outage in the window that reaches it. */
#define NEVER ((avr_cycle_count_t)-1)

static void power_off(int i, avr_cycle_count_t now, avr_cycle_count_t on) {
    (void)now;
    robot *r = &robots[i];
    lockstep_settle(r);
    start_again(r);
    r->off_until = on;
    r->doze_until = NEVER;
}

static void power_on(int i, avr_cycle_count_t on) {
    robot *r = &robots[i];
    uint32_t f = r->avr->frequency;
    avr_cycle_count_t own = f == nominal_hz ? on : on * f / nominal_hz;
    if (own > r->avr->cycle) r->avr->cycle = own;
    r->off_until = 0;
    start_again(r);
    ohc_robot_reset(r);
}

const fault_robots *power_cycle_robots(robot *all, uint32_t hz) {
    static const fault_robots exact = {can_fault, off_until, reset, power_off, power_on};
    robots = all;
    nominal_hz = hz;
    return &exact;
}
