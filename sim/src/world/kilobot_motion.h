/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* How a Kilobot moves for the duties its firmware gives its two vibration
 * motors (docs/world.md, "Kilobot motion", has the numbers and sources).
 *
 * A motor stands still below its stall duty. From standstill it needs a
 * kick, SPINUP_MS at SPINUP_DUTY or more (kilolib's spinup_motors gives 15
 * ms at 255), then it runs at any duty from the stall duty up. Alone, a
 * motor pivots the robot about the rear leg on its own side: the left one
 * turns it left (counter-clockwise), at TURN_DEG_S at that robot's
 * calibrated turn duty. Held at KILOBOT_SLIP_DUTY or more a motor only
 * shakes the robot. Together they walk it forward, at FORWARD_MM_S at
 * its calibrated straight duties; unequal drive curves the path. Each
 * robot's motors differ (stall and calibrated duties, drawn per robot), and
 * every step adds noise to the speeds, as the slip-stick gait does. */
#ifndef OPENSWARM_KILOBOT_MOTION_H
#define OPENSWARM_KILOBOT_MOTION_H

#include <stdint.h>

#include "world/world_random.h"

#define KILOBOT_FORWARD_MM_S 10.0 /* Rubenstein et al. 2012: about 1 cm/s */
#define KILOBOT_TURN_DEG_S 45.0   /* and about 45 deg/s turning */
#define KILOBOT_SPINUP_DUTY 200
/* From this duty on the legs slip: the robot hops in place (a robot whose
 * EEPROM was never calibrated reads 255 and goes nowhere). */
#define KILOBOT_SLIP_DUTY 180
#define KILOBOT_SPINUP_MS 10.0
/* The rear legs, from the centre: 9 mm back, 13 mm to each side. */
#define KILOBOT_LEG_BACK_MM 9.0
#define KILOBOT_LEG_SIDE_MM 13.0

/* One robot's motors as built: what its factory calibration found. */
typedef struct kilobot_motors_model {
    double stall[2];    /* left, right: no motion below this duty */
    double straight[2]; /* duties that walk it straight at FORWARD_MM_S */
    double turn[2];     /* duty that alone turns it at TURN_DEG_S */
    double speed_noise; /* relative sd of the speeds, per second^-1/2 */
} kilobot_motors_model;

/* A motor's state, followed at each duty change (cycle-exact). */
typedef struct kilobot_motor {
    uint8_t duty;
    int running;
    double kick_s;      /* time at SPINUP_DUTY or more since it stood still */
    double since_s;     /* when duty was set */
} kilobot_motor;

/* The robot's motion in its own frame for one step: the centre's speed
 * forward and to the left, and the turn rate (counter-clockwise). */
typedef struct kilobot_twist {
    double forward_mm_s, left_mm_s, turn_rad_s;
} kilobot_twist;

#ifdef __cplusplus
extern "C" {
#endif

/* A robot's motors drawn from a seed: duties spread as real ones are. */
void kilobot_motors_draw(kilobot_motors_model *m, uint64_t *rng);
/* Duties as the EEPROM's calibration bytes: turn left, turn right,
 * straight left, straight right. */
void kilobot_motors_calibration(const kilobot_motors_model *m, int calibration[4]);
/* The firmware set a motor's duty at time t. */
void kilobot_motor_set(kilobot_motor *motor, const kilobot_motors_model *m, int side, uint8_t duty,
                       double t);
/* Bring a motor's spin-up up to time t (before reading it). */
void kilobot_motor_advance(kilobot_motor *motor, double t);
/* The motion the motors give now, noise included for a step of dt. */
kilobot_twist kilobot_motion(const kilobot_motor motors[2], const kilobot_motors_model *m, double dt,
                             uint64_t *rng);

#ifdef __cplusplus
}
#endif

#endif
