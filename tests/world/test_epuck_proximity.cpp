// The e-puck's proximity model (sim/src/world/epuck_sensors.c) against
// the calibration Cyberbotics measured on a real e-puck for Webots
// (E-puckDistanceSensor.proto, see docs/world.md): at each distance the
// reflection (reading with the emitters off minus the reading in the
// pulse) has the calibration's mean, less what the sensor reads with
// nothing near, and its spread.
#include <ostream>
#include <string>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "world/epuck_sensors.h"
#include "world/world.h"

namespace {

constexpr double ARENA_MM = 1000;
constexpr double RADIUS_MM = 37;
constexpr double NOTHING_NEAR = 67.19; // the calibration's reading at 70 mm and beyond
constexpr int SAMPLES = 4000;

struct spread {
    double mean, sd;
};

// Sensor 0 (18 deg right of the heading) looking straight at the right
// wall, its window gap_mm from it (gap < 0: the robot in the middle).
spread sensor0_reflection(double gap_mm) {
    world_robot robot{};
    robot.at = {gap_mm < 0 ? ARENA_MM / 2 : ARENA_MM - RADIUS_MM - gap_mm, ARENA_MM / 2};
    robot.heading_deg = 18;
    robot.firmware = -1;
    world_spec spec{};
    spec.width_mm = spec.height_mm = ARENA_MM;
    spec.robots = &robot;
    spec.n_robots = 1;
    spec.robot_kind = WORLD_ROBOT_EPUCK;
    spec.robot_radius_mm = RADIUS_MM;
    world *w = world_create(&spec);
    uint64_t rng = 12345;
    double sum = 0, squares = 0;
    for (int i = 0; i < SAMPLES; i++) {
        uint16_t off[EPUCK_SENSOR_COUNT], pulsed[EPUCK_SENSOR_COUNT];
        epuck_proximity_read(w, 0, off, pulsed, &rng);
        double r = double(off[0]) - double(pulsed[0]);
        sum += r;
        squares += r * r;
    }
    world_destroy(w);
    double mean = sum / SAMPLES;
    return {mean, std::sqrt(squares / SAMPLES - mean * mean)};
}

struct calibration_point {
    double gap_mm, counts, noise_share;
};

// How ctest lists a case (after its name): what the calibration expects.
void PrintTo(const calibration_point &p, std::ostream *out) {
    *out << p.counts << " counts, noise " << p.noise_share * 100 << "%";
}

class Proximity : public ::testing::TestWithParam<calibration_point> {};

TEST_P(Proximity, ReflectsTheCalibrationsMeanAndSpread) {
    calibration_point p = GetParam();
    spread s = sensor0_reflection(p.gap_mm);
    double sd = p.counts * p.noise_share;
    // 4000 samples: the mean within 5 of its standard errors (plus half a
    // count of rounding), the spread within 10%.
    EXPECT_NEAR(s.mean, p.counts - NOTHING_NEAR, 5 * sd / std::sqrt(SAMPLES) + 0.5) << "at " << p.gap_mm << " mm";
    EXPECT_NEAR(s.sd, sd, 0.1 * sd + 0.3) << "at " << p.gap_mm << " mm";
}

INSTANTIATE_TEST_SUITE_P(WebotsCalibration, Proximity,
                         ::testing::Values(calibration_point{5, 2133.33, 0.003},
                                           calibration_point{10, 1465.73, 0.007},
                                           calibration_point{15, 601.46, 0.0406},
                                           calibration_point{20, 383.84, 0.01472},
                                           calibration_point{40, 158.03, 0.0287},
                                           calibration_point{60, 104.09, 0.03065},
                                           // between two points: on the line through them
                                           calibration_point{25, (383.84 + 234.93) / 2, (0.01472 + 0.0241) / 2},
                                           // past the last point, and nothing in reach
                                           calibration_point{90, NOTHING_NEAR, 0.04897},
                                           calibration_point{-1, NOTHING_NEAR, 0.04897}),
                         // each case named by its gap (ctest lists the names): at_25mm, nothing_in_reach
                         [](const ::testing::TestParamInfo<calibration_point> &point) {
                             return point.param.gap_mm < 0 ? std::string("nothing_in_reach")
                                                          : "at_" + std::to_string((int)point.param.gap_mm) + "mm";
                         });

TEST(Proximity, FallsWithDistanceToNothingAt70mm) {
    double last = 1e9;
    for (double d = 0; d <= 80; d += 2.5) {
        double r = epuck_reflection_counts(d);
        EXPECT_LE(r, last) << "at " << d << " mm";
        last = r;
    }
    EXPECT_DOUBLE_EQ(epuck_reflection_counts(70), 0);
    EXPECT_DOUBLE_EQ(epuck_reflection_counts(200), 0);
}

} // namespace
