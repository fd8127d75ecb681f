/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The Kilobot's motion from its motor duties (kilobot_motion.h). */
#include "world/kilobot_motion.h"

#include <math.h>

#define PI 3.14159265358979323846
/* Past this multiple of its calibrated drive a motor gives no more: the
 * legs slip rather than walk faster. */
#define MAX_DRIVE 2.5
/* Unequal drive curves the path: a 10% difference turns it at a twentieth
 * of the calibrated turn rate (about 2 deg/s, a 25 cm circle at 1 cm/s). */
#define CURVE_PER_DRIVE 0.5
#define TURN_NOISE_RAD_S 0.05 /* heading wander while walking, per s^1/2 */

static double uniform_int(uint64_t *rng, int lo, int hi) {
    return lo + (int)(world_random_uniform(rng) * (hi - lo + 1));
}

/* Spreads as factory calibration finds them: straight duties 60-85, turn
 * duties 60-90, motors stalling at 30-45. Whole numbers, so the EEPROM's
 * bytes are exactly the robot's own duties. */
void kilobot_motors_draw(kilobot_motors_model *m, uint64_t *rng) {
    for (int side = 0; side < 2; side++) {
        m->stall[side] = uniform_int(rng, 30, 45);
        m->straight[side] = uniform_int(rng, 60, 85);
        m->turn[side] = uniform_int(rng, 60, 90);
    }
    m->speed_noise = 0.1;
}

void kilobot_motors_calibration(const kilobot_motors_model *m, int calibration[4]) {
    calibration[0] = (int)m->turn[0];
    calibration[1] = (int)m->turn[1];
    calibration[2] = (int)m->straight[0];
    calibration[3] = (int)m->straight[1];
}

void kilobot_motor_advance(kilobot_motor *motor, double t) {
    if (!motor->running && motor->duty >= KILOBOT_SPINUP_DUTY) {
        motor->kick_s += t - motor->since_s;
        if (motor->kick_s >= KILOBOT_SPINUP_MS / 1000.0) motor->running = 1;
    }
    motor->since_s = t;
}

void kilobot_motor_set(kilobot_motor *motor, const kilobot_motors_model *m, int side, uint8_t duty,
                       double t) {
    kilobot_motor_advance(motor, t);
    motor->duty = duty;
    if (duty < m->stall[side]) {
        motor->running = 0;
        motor->kick_s = 0;
    }
}

/* How hard a running motor drives, as a multiple of its duty at the
 * calibrated point (0 below the stall duty). */
static double drive(const kilobot_motor *motor, const kilobot_motors_model *m, int side,
                    double calibrated) {
    if (!motor->running || motor->duty < m->stall[side] || motor->duty >= KILOBOT_SLIP_DUTY) return 0.0;
    double d = (motor->duty - m->stall[side]) / (calibrated - m->stall[side]);
    return d > MAX_DRIVE ? MAX_DRIVE : d;
}

/* One motor alone pivots the robot about the rear leg on its side: the
 * centre, 9 mm ahead of and 13 mm beside that leg, goes round it. */
static kilobot_twist pivot(double turn_rad_s, double side_sign) {
    kilobot_twist t;
    t.turn_rad_s = side_sign * turn_rad_s;
    t.forward_mm_s = KILOBOT_LEG_SIDE_MM * turn_rad_s;
    t.left_mm_s = side_sign * KILOBOT_LEG_BACK_MM * turn_rad_s;
    return t;
}

kilobot_twist kilobot_motion(const kilobot_motor motors[2], const kilobot_motors_model *m, double dt,
                             uint64_t *rng) {
    const double turn = KILOBOT_TURN_DEG_S * PI / 180.0;
    kilobot_twist t = {0, 0, 0};
    int left = motors[0].running, right = motors[1].running;
    if (left && right) {
        double a = drive(&motors[0], m, 0, m->straight[0]), b = drive(&motors[1], m, 1, m->straight[1]);
        t.forward_mm_s = KILOBOT_FORWARD_MM_S * (a + b) / 2.0;
        t.turn_rad_s = CURVE_PER_DRIVE * turn * (a - b);
    } else if (left) {
        t = pivot(turn * drive(&motors[0], m, 0, m->turn[0]), +1.0);
    } else if (right) {
        t = pivot(turn * drive(&motors[1], m, 1, m->turn[1]), -1.0);
    }
    if ((t.forward_mm_s == 0 && t.turn_rad_s == 0) || dt <= 0) return t;
    /* Slip-stick noise: white in the speeds, so the spread of the path
     * grows with the square root of the time walked. */
    double scale = 1.0 / sqrt(dt);
    t.forward_mm_s += m->speed_noise * fabs(t.forward_mm_s) * scale * world_random_normal(rng);
    t.turn_rad_s += (m->speed_noise * fabs(t.turn_rad_s) + TURN_NOISE_RAD_S) * scale *
                    world_random_normal(rng);
    return t;
}
