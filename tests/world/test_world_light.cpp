// world.json's "light" (docs/world.md, "light"): a lamp's height and the
// switch that turns the robot's own shadow off, each refused at its place
// when out of range or of the wrong kind.
#include <gtest/gtest.h>

#include <string>

#include "world_file_fixture.hpp"

namespace {

TEST_F(WorldFile, LampHeight) {
    world_spec w{};
    ASSERT_EQ(load(R"({"arena": {"width_mm": 600, "height_mm": 400},
"light": {"sources": [{"x_mm": 1, "y_mm": 2, "intensity_mv": 3, "height_mm": 40}]}})", &w), "");
    EXPECT_EQ(w.lights[0].height_mm, 40);
    world_spec_free(&w);
    std::string err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400},
"light": {"sources": [{"x_mm": 1, "y_mm": 2, "intensity_mv": 3, "height_mm": -5}]}})");
    EXPECT_NE(err.find("world.json:2:78: light.sources[0].height_mm: expected the bulb's height above the floor in mm"),
              std::string::npos) << err;
    EXPECT_NE(err.find("\"height_mm\": 150"), std::string::npos) << err;
}

// "shadow": false turns the battery's shadow off (for worlds whose subject
// is not shading, native.int16_move_to_light's); anything but a boolean is
// refused at its place.
TEST_F(WorldFile, LightShadowSwitch) {
    world_spec w{};
    ASSERT_EQ(load(R"({"arena": {"width_mm": 600, "height_mm": 400}, "light": {}})", &w), "");
    EXPECT_EQ(w.light_unshaded, 0);
    world_spec_free(&w);
    ASSERT_EQ(load(R"({"arena": {"width_mm": 600, "height_mm": 400}, "light": {"shadow": false}})", &w), "");
    EXPECT_EQ(w.light_unshaded, 1);
    world_spec_free(&w);
    std::string err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400},
"light": {"shadow": "off"}})");
    EXPECT_NE(err.find("world.json:2:21: light.shadow: expected true (the robot's battery shades its light sensor) "
                       "or false (no shadow), found text \"off\"; e.g. \"shadow\": false"),
              std::string::npos) << err;
}

}  // namespace
