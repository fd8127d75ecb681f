/* The wheels' safety post-processor: a command's speeds, clamped to the
 * steppers' range and moved towards from the last speeds applied by at
 * most max_step each, so a reversal from full speed forward becomes a ramp
 * the steppers can follow instead of lost steps. The device keeps the
 * speeds last applied. */
#include "devices_internal.h"

epuck_wheel_limits epuck_wheel_default_limits = {EPUCK_MAX_STEPS_PER_S, 200};

static epuck_wheel_speeds applied;

void epuck_wheels_forget(void) { applied.left = applied.right = 0; }

static int16_t clamp(int32_t v, int32_t limit) {
    if (v > limit) return (int16_t)limit;
    if (v < -limit) return (int16_t)-limit;
    return (int16_t)v;
}

static int16_t towards(int16_t from, int16_t to, int16_t max_step) {
    return clamp((int32_t)from + clamp((int32_t)to - from, max_step), EPUCK_MAX_STEPS_PER_S);
}

uint8_t epuck_wheels_limited(sys_device *dev, const void *in, uint8_t size, void *out,
                             uint8_t capacity) {
    const epuck_wheel_speeds *want = in;
    epuck_wheel_speeds *got = out;
    if (size != sizeof *want || capacity < sizeof *got) return 0;
    const epuck_wheel_limits *limits = dev->params != NULL ? dev->params : &epuck_wheel_default_limits;
    int16_t top = clamp(limits->max_speed, EPUCK_MAX_STEPS_PER_S);
    int16_t step = limits->max_step > 0 ? limits->max_step : 1;
    applied.left = towards(applied.left, clamp(want->left, top), step);
    applied.right = towards(applied.right, clamp(want->right, top), step);
    *got = applied;
    return sizeof *got;
}
