// The e-puck's wheel noise (sim/src/world/world.cpp, docs/world.md): each
// wheel's speed is its command times a factor drawn every 10 ms step,
// uniform in 1 +- 0.05 (Enki's e-puck model). Measured from a run: 200
// e-pucks driving straight at 500 steps/s for 10 s, each from its own
// stream; across them, the distance driven and the heading's drift have
// the spreads the model gives. With "noise": {"wheels": false} every robot
// drives exactly the same path; with "wheels_pct" the spread scales with
// the half-width.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "world/world.h"

namespace {

constexpr int ROBOTS = 200, STEPS = 1000, COMMAND = 500;
constexpr double STEP_S = 0.01, HALF_WIDTH = 0.05, AXLE_MM = 53.0;
constexpr double MM_PER_STEP = 3.14159265358979323846 * 41.0 / 1000.0;

struct spread {
    double mean, sd;
};

spread of(const std::vector<double> &v) {
    double sum = 0, squares = 0;
    for (double x : v) sum += x;
    double mean = sum / double(v.size());
    for (double x : v) squares += (x - mean) * (x - mean);
    return {mean, std::sqrt(squares / double(v.size() - 1))};
}

struct drive {
    spread distance_mm, heading_rad;
};

// One column, 100 mm apart, all heading along x from the same x: Box2D's
// floats then round every robot's x alike (robots in different columns
// differ by 0.3 mm after 10 s from rounding alone, as much as the noise).
drive drive_straight(int noise_off, double pct = 0) {
    std::vector<world_robot> robots(ROBOTS);
    for (int i = 0; i < ROBOTS; i++) {
        robots[size_t(i)].at = {100.0, 100.0 * (i + 1)};
        robots[size_t(i)].firmware = -1;
    }
    world_spec spec{};
    spec.width_mm = 1000;
    spec.height_mm = 100.0 * (ROBOTS + 1);
    spec.robots = robots.data();
    spec.n_robots = ROBOTS;
    spec.robot_kind = WORLD_ROBOT_EPUCK;
    spec.robot_radius_mm = 37;
    spec.seed = 7;
    spec.wheel_noise_off = noise_off;
    spec.wheel_noise_pct = pct;
    world *w = world_create(&spec);
    for (int k = 0; k < STEPS; k++) {
        for (int i = 0; i < ROBOTS; i++) world_epuck_wheels(w, i, COMMAND, COMMAND);
        world_step(w, (k + 1) * STEP_S);
    }
    std::vector<double> distance, heading;
    for (int i = 0; i < ROBOTS; i++) {
        double x, y, deg;
        world_robot_pose(w, i, &x, &y, &deg);
        distance.push_back(std::hypot(x - robots[size_t(i)].at.x, y - robots[size_t(i)].at.y));
        heading.push_back((deg > 180 ? deg - 360 : deg) * 3.14159265358979323846 / 180.0);
    }
    world_destroy(w);
    return {of(distance), of(heading)};
}

// The model's spreads after STEPS steps: a factor's sd is HALF_WIDTH /
// sqrt(3); the forward speed averages two factors, the turn takes their
// difference, and STEPS independent steps add their variances.
const double SPEED_MM_S = COMMAND * MM_PER_STEP;
const double FACTOR_SD = HALF_WIDTH / std::sqrt(3.0);
const double DISTANCE_SD = SPEED_MM_S * STEP_S * FACTOR_SD / std::sqrt(2.0) * std::sqrt(double(STEPS));
const double HEADING_SD = SPEED_MM_S * STEP_S / AXLE_MM * FACTOR_SD * std::sqrt(2.0) * std::sqrt(double(STEPS));

TEST(EpuckWheelNoise, SpreadsAsTheModelSays) {
    drive d = drive_straight(0);
    // 200 robots pin an sd down to about 5% (1 / sqrt(2 x 200)): 20% is
    // four of those; the means to a tenth of the distance's sd.
    EXPECT_NEAR(SPEED_MM_S * STEPS * STEP_S, d.distance_mm.mean, 0.5 * DISTANCE_SD) << "mm";
    std::printf("distance %.3f +- %.4f mm (model +- %.4f), heading %.5f +- %.5f rad (model +- %.5f)\n",
                d.distance_mm.mean, d.distance_mm.sd, DISTANCE_SD, d.heading_rad.mean, d.heading_rad.sd, HEADING_SD);
    EXPECT_NEAR(DISTANCE_SD, d.distance_mm.sd, 0.2 * DISTANCE_SD) << "mm";
    EXPECT_NEAR(0.0, d.heading_rad.mean, 0.5 * HEADING_SD) << "rad";
    EXPECT_NEAR(HEADING_SD, d.heading_rad.sd, 0.2 * HEADING_SD) << "rad";
}

TEST(EpuckWheelNoise, TheSwitchTurnsItOff) {
    drive d = drive_straight(1);
    EXPECT_NEAR(SPEED_MM_S * STEPS * STEP_S, d.distance_mm.mean, 1.0) << "mm";
    EXPECT_LT(d.distance_mm.sd, 1e-3) << "mm: every robot drives the same path";
    EXPECT_LT(d.heading_rad.sd, 1e-6) << "rad";
}

TEST(EpuckWheelNoise, ItsWidthScalesTheSpread) {
    // Twice the half-width, twice the sd: the factor's sd is linear in it.
    drive d = drive_straight(0, 2 * HALF_WIDTH * 100);
    EXPECT_NEAR(2 * DISTANCE_SD, d.distance_mm.sd, 0.2 * 2 * DISTANCE_SD) << "mm";
    EXPECT_NEAR(2 * HEADING_SD, d.heading_rad.sd, 0.2 * 2 * HEADING_SD) << "rad";
}

} // namespace
