// world.json's "noise" (docs/world.md, "noise"): the switch that turns the
// e-puck's wheel noise off, on by default, refused at its place when not a
// boolean or when it names a noise the world does not have.
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

}  // namespace
