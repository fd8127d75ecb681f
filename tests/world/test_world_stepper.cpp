// The physics stepped beside the robots (sim/src/world/world_stepper.c,
// docs/world.md "Physics"): up to WORLD_STEPS_AHEAD steps under way at
// once, each taken back in the order begun with where it left the bodies.
// An e-puck whose wheels change speed every step is stepped through the
// stepper, on the calling thread and on a thread of its own, as the
// simulator does (world_run.c: prepare, take the oldest when as many are
// under way as may be, begin): the poses taken must be, step by step, the
// poses of the same steps taken one at a time, and the robots must see
// each step only once the steps after it have begun.
#include <gtest/gtest.h>

#include <vector>

extern "C" {
#include "world/world_stepper.h"
}

namespace {

constexpr int STEPS = 40;

world_spec one_epuck(world_robot *robot) {
    *robot = world_robot{};
    robot->at = {300, 500};
    robot->firmware = -1;
    world_spec spec{};
    spec.width_mm = 1000;
    spec.height_mm = 1000;
    spec.robots = robot;
    spec.n_robots = 1;
    spec.robot_kind = WORLD_ROBOT_EPUCK;
    spec.robot_radius_mm = 37.0;
    spec.seed = 3;
    spec.wheel_noise_off = 1;
    return spec;
}

// Step k's wheels: a new speed each step, so a step walked with another
// step's twist lands elsewhere.
int16_t wheels_of(int k) { return int16_t(100 + 37 * k); }

// Step k ends at (k + 1) x WORLD_STEP_S.
double end_of(int k) { return (k + 1) * WORLD_STEP_S; }

// The x of the robot after each step, stepped one at a time.
std::vector<double> one_at_a_time() {
    world_robot robot;
    world_spec spec = one_epuck(&robot);
    world *w = world_create(&spec);
    std::vector<double> x;
    for (int k = 0; k < STEPS; k++) {
        world_epuck_wheels(w, 0, wheels_of(k), wheels_of(k));
        world_step(w, end_of(k));
        double y, deg;
        x.push_back(0);
        world_robot_pose(w, 0, &x.back(), &y, &deg);
    }
    world_destroy(w);
    return x;
}

// The same through the stepper; taken_after[j]: steps begun when step j
// was taken.
std::vector<double> through_stepper(int threaded, std::vector<int> *taken_after) {
    world_robot robot;
    world_spec spec = one_epuck(&robot);
    world *w = world_create(&spec);
    world_stepper_start(w, 1, 0, threaded);
    std::vector<double> x;
    auto take = [&](int begun) {
        x.push_back(world_stepper_take()->robots[0].x_mm);
        taken_after->push_back(begun);
    };
    for (int k = 0; k < STEPS; k++) {
        world_epuck_wheels(w, 0, wheels_of(k), wheels_of(k));
        world_stepper_prepare(end_of(k));
        if (world_stepper_pending() == WORLD_STEPS_AHEAD) take(k);
        world_stepper_begin();
    }
    while (world_stepper_pending() > 0) take(STEPS);
    world_stepper_stop();
    world_destroy(w);
    return x;
}

void expect_same_steps(int threaded) {
    std::vector<double> expected = one_at_a_time();
    std::vector<int> taken_after;
    std::vector<double> x = through_stepper(threaded, &taken_after);
    ASSERT_EQ(expected.size(), x.size()) << "steps taken";
    for (int k = 0; k < STEPS; k++) {
        EXPECT_DOUBLE_EQ(expected[size_t(k)], x[size_t(k)]) << "step " << k;
        int seen_after = k + WORLD_STEPS_AHEAD < STEPS ? k + WORLD_STEPS_AHEAD : STEPS;
        EXPECT_EQ(seen_after, taken_after[size_t(k)]) << "steps begun when step " << k << " was seen";
    }
    EXPECT_GT(x.back(), x.front() + 10.0) << "the robot drove (mm)";
}

TEST(WorldStepper, OnTheCallingThreadEachStepIsSeenAsTakenAlone) { expect_same_steps(0); }

TEST(WorldStepper, OnAThreadOfItsOwnEachStepIsSeenAsTakenAlone) { expect_same_steps(1); }

}  // namespace
