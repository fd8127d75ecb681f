// A robot's legs (or wheels) grip the floor with at most friction x its
// weight (sim/src/world/world.cpp, docs/world.md "Physics"): an e-puck
// started at full speed from rest gains at most 0.8 x g x 10 ms in its
// first step, then drives at its wheels' speed. A robot that touches
// nothing walks without the legs' joint, one that touches a body walks
// with it (walk): both ways must give that grip. Two e-pucks side by side,
// just touching and driving alike, take the joint's way; a lone one the
// other.
#include <gtest/gtest.h>

#include <vector>

#include "world/world.h"

namespace {

constexpr double STEP_S = 0.01, RADIUS_MM = 37.0;
constexpr double GRIP_MM_S2 = 0.8 * 9810.0; /* the wheels' friction x g */
constexpr int FULL = 1000;                  /* steps/s */
const double FULL_MM_S = FULL * 3.14159265358979323846 * 41.0 / 1000.0;

// How far each robot has driven along x after each of two steps from rest.
std::vector<double> driven(const std::vector<world_point> &at) {
    std::vector<world_robot> robots(at.size());
    for (size_t i = 0; i < at.size(); i++) {
        robots[i].at = at[i];
        robots[i].firmware = -1;
    }
    world_spec spec{};
    spec.width_mm = 1000;
    spec.height_mm = 1000;
    spec.robots = robots.data();
    spec.n_robots = int(at.size());
    spec.robot_kind = WORLD_ROBOT_EPUCK;
    spec.robot_radius_mm = RADIUS_MM;
    spec.seed = 3;
    spec.wheel_noise_off = 1;
    world *w = world_create(&spec);
    std::vector<double> out;
    for (int k = 0; k < 2; k++) {
        for (size_t i = 0; i < at.size(); i++) world_epuck_wheels(w, int(i), FULL, FULL);
        world_step(w, (k + 1) * STEP_S);
        for (size_t i = 0; i < at.size(); i++) {
            double x, y, deg;
            world_robot_pose(w, int(i), &x, &y, &deg);
            out.push_back(x - at[i].x);
        }
    }
    world_destroy(w);
    return out;
}

// The first step at the grip's speed, the second at the wheels'.
const double FIRST_MM = GRIP_MM_S2 * STEP_S * STEP_S;
const double SECOND_MM = FIRST_MM + FULL_MM_S * STEP_S;

TEST(LegsGrip, ALoneRobotGainsAtMostItsGrip) {
    std::vector<double> x = driven({{300, 500}});
    EXPECT_NEAR(FIRST_MM, x[0], 0.005) << "mm after one step";
    EXPECT_NEAR(SECOND_MM, x[1], 0.005) << "mm after two";
}

TEST(LegsGrip, TouchingRobotsGainTheSame) {
    // 0.01 mm overlap: touching, within Box2D's slop, so neither is pushed.
    std::vector<double> x = driven({{300, 400}, {300, 400 + 2 * RADIUS_MM - 0.01}});
    for (size_t i = 0; i < 2; i++) {
        EXPECT_NEAR(FIRST_MM, x[i], 0.005) << "robot " << i << ", mm after one step";
        EXPECT_NEAR(SECOND_MM, x[2 + i], 0.005) << "robot " << i << ", mm after two";
    }
}

} // namespace
