// world.json's "noise" (docs/world.md, "noise"): the switch that turns the
// e-puck's wheel noise off, on by default, refused at its place when not a
// boolean or when it names a noise the world does not have; "wheels_pct"
// its width. And "camera": the e-puck's frame rate and lag, and its noise.
#include <gtest/gtest.h>

#include <string>

#include "world_file_fixture.hpp"

namespace {

TEST_F(WorldFile, NoiseWheelsSwitch) {
    world_spec w{};
    ASSERT_EQ(load(R"({"arena": {"width_mm": 600, "height_mm": 400}})", &w), "");
    EXPECT_EQ(w.wheel_noise_off, 0) << "on unless turned off";
    world_spec_free(&w);
    ASSERT_EQ(load(R"({"arena": {"width_mm": 600, "height_mm": 400}, "noise": {"wheels": false}})", &w), "");
    EXPECT_EQ(w.wheel_noise_off, 1);
    world_spec_free(&w);
    std::string err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400},
"noise": {"wheels": 0}})");
    EXPECT_NE(err.find("world.json:2:21: noise.wheels: expected true (an e-puck's wheels err as the robot's do, "
                       "docs/world.md) or false (they turn exactly as commanded), found"),
              std::string::npos) << err;
    EXPECT_NE(err.find("e.g. \"wheels\": false"), std::string::npos) << err;
    err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400}, "noise": {"wheel": false}})");
    EXPECT_NE(err.find("noise"), std::string::npos) << err;
    EXPECT_NE(err.find("wheels"), std::string::npos) << "names the key it knows: " << err;
}

TEST_F(WorldFile, NoiseWheelsWidth) {
    world_spec w{};
    ASSERT_EQ(load(R"({"arena": {"width_mm": 600, "height_mm": 400}, "noise": {"wheels_pct": 12.5}})", &w), "");
    EXPECT_DOUBLE_EQ(world_wheel_noise(&w), 0.125);
    world_spec_free(&w);
    ASSERT_EQ(load(R"({"arena": {"width_mm": 600, "height_mm": 400}, "noise": {"wheels_pct": 0}})", &w), "");
    EXPECT_EQ(world_wheel_noise(&w), 0.0) << "0 %: off, as \"wheels\": false";
    world_spec_free(&w);
    ASSERT_EQ(load(R"({"arena": {"width_mm": 600, "height_mm": 400}})", &w), "");
    EXPECT_DOUBLE_EQ(world_wheel_noise(&w), 0.05) << "Enki's 5 % by default";
    world_spec_free(&w);
    std::string err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400},
"noise": {"wheels": true, "wheels_pct": 5}})");
    EXPECT_NE(err.find("world.json:2:41: noise.wheels_pct: \"wheels\" and \"wheels_pct\" both say"),
              std::string::npos) << err;
    err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400}, "noise": {"wheels_pct": 80}})");
    EXPECT_NE(err.find("wheels_pct"), std::string::npos) << err;
}

TEST_F(WorldFile, CameraRateAndLag) {
    const std::string epuck = R"({"robot": "epuck", "arena": {"width_mm": 600, "height_mm": 400}, )";
    world_spec w{};
    ASSERT_EQ(load(epuck + R"("robots": [{"count": 1}]})", &w), "");
    EXPECT_EQ(world_camera_period_ms(&w), 250) << "4 frames a second by default";
    EXPECT_EQ(world_camera_fov_deg(&w), 56.0);
    EXPECT_EQ(world_camera_range_mm(&w), 1500.0);
    EXPECT_EQ(w.camera_lag_ms, 0);
    world_spec_free(&w);
    ASSERT_EQ(load(epuck + R"("camera": {"frames_per_s": 10, "lag_ms": 250, "fov_deg": 30, "range_mm": 800},
"robots": [{"count": 1}]})", &w), "");
    EXPECT_EQ(world_camera_fov_deg(&w), 30.0);
    EXPECT_EQ(world_camera_range_mm(&w), 800.0);
    EXPECT_EQ(world_camera_period_ms(&w), 100);
    EXPECT_EQ(w.camera_lag_ms, 250);
    world_spec_free(&w);
    std::string err = error_of(epuck + R"("camera": {"frames_per_s": 3}})");
    EXPECT_NE(err.find("camera.frames_per_s: a frame comes on a 10 ms physics step, so the rate must divide 100"),
              std::string::npos) << err;
    EXPECT_NE(err.find("e.g. \"frames_per_s\": 4"), std::string::npos) << "the nearest rate below: " << err;
    err = error_of(epuck + R"("camera": {"lag_ms": 1001}})");
    EXPECT_NE(err.find("camera.lag_ms"), std::string::npos) << err;
    err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400}, "camera": {"lag_ms": 10}})");
    EXPECT_NE(err.find("a Kilobot has no camera"), std::string::npos) << err;
}

TEST_F(WorldFile, CameraNoise) {
    const std::string epuck = R"({"robot": "epuck", "arena": {"width_mm": 600, "height_mm": 400}, )";
    world_spec w{};
    ASSERT_EQ(load(epuck + R"("robots": [{"count": 1}]})", &w), "");
    EXPECT_EQ(w.camera_pixel_noise, 0.0) << "off unless given: no measured figure";
    EXPECT_EQ(w.camera_misread_pct_per_m, 0.0);
    world_spec_free(&w);
    ASSERT_EQ(load(epuck + R"("camera": {"pixel_noise": 2.5, "misread_pct_per_m": 20},
"robots": [{"count": 1}]})", &w), "");
    EXPECT_EQ(w.camera_pixel_noise, 2.5);
    EXPECT_EQ(w.camera_misread_pct_per_m, 20.0);
    world_spec_free(&w);
    std::string err = error_of(epuck + R"(
"camera": {"pixel_noise": 40}, "robots": [{"count": 1}]})");
    EXPECT_NE(err.find("world.json:2:27: camera.pixel_noise: expected each colour channel's noise"), std::string::npos)
        << err;
    EXPECT_NE(err.find("0..31, found 40; e.g. \"pixel_noise\": 2"), std::string::npos) << err;
    err = error_of(epuck + R"(
"camera": {"misread_pct_per_m": "high"}, "robots": [{"count": 1}]})");
    EXPECT_NE(err.find("world.json:2:33: camera.misread_pct_per_m: expected percent chance per metre"),
              std::string::npos) << err;
    EXPECT_NE(err.find("e.g. \"misread_pct_per_m\": 20"), std::string::npos) << err;
}

}  // namespace
