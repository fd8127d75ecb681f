/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The exact mode's robots in a world (world_run.h): their LEDs as the
 * pins show them, the light sensor's ADC input, the IR channel of edges
 * (air/ir_channel.c), and their motors' duty changes at their exact cycle. */
#include "world/world_avr.h"

#include <avr_adc.h>
#include <sim_io.h>

#include "world/world_run.h"

static robot *robots;

static void led(int index, uint8_t rgb[3]) { trace_led(&robots[index], rgb); }

static void light(int index, int millivolts) {
    avr_raise_irq(avr_io_getirq(robots[index].avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_ADC7), (uint32_t)millivolts);
}

static void motors_changed(void *ctx, int index, uint8_t left, uint8_t right, avr_cycle_count_t cycle) {
    (void)ctx;
    world_run_motors(index, left, right, (double)cycle / robots[index].avr->frequency);
}

_Static_assert(OUTPUT_IR_FIRMWARE_COUNTERS == KILOBOT_IR_COUNTERS, "ir.csv's firmware columns");

static void ir(int index, output_ir *out) {
    out->firmware_known = firmware_ir_counters(&robots[index], out->firmware);
    ir_channel_counts(index, &out->heard, &out->lost_channel);
}

static const world_robots avr_robots = {led, light, ir_channel_place, ir_channel_links, ir};

void world_avr_robot_noise(robot *r, int index) {
    analog_noise_attach(r, world_robot_noise_seed(index), WORLD_ANALOG_NOISE_COUNTS);
}

int world_avr_start(robot *all, int n, const options *o, uint32_t nominal_hz) {
    robots = all;
    for (int i = 0; i < n; i++) all[i].trace.on_motors = motors_changed;
    return world_run_start(n, o, &avr_robots, nominal_hz, 0);
}
