// world.json's "ir" distance error (docs/world.md, "ir"): the published
// accuracy and precision when not given, 0 to turn either off, anything
// but a number in range refused at its place with the fix.
#include <gtest/gtest.h>

#include <string>

#include "world_file_fixture.hpp"

namespace {

TEST_F(WorldFile, IrDistanceErrorDefaults) {
    world_spec w{};
    ASSERT_EQ(load(R"({"arena": {"width_mm": 600, "height_mm": 400}})", &w), "");
    EXPECT_EQ(w.ir_distance_bias_mm, 2.0);  // "accuracy of +-2 mm"
    EXPECT_EQ(w.ir_distance_noise_mm, 0.5); // "precision under 1 mm"
    world_spec_free(&w);
    ASSERT_EQ(load(R"({"arena": {"width_mm": 600, "height_mm": 400},
"ir": {"distance_bias_mm": 0, "distance_noise_mm": 1.5}})", &w), "");
    EXPECT_EQ(w.ir_distance_bias_mm, 0.0);
    EXPECT_EQ(w.ir_distance_noise_mm, 1.5);
    world_spec_free(&w);
}

TEST_F(WorldFile, IrDistanceErrorRefused) {
    std::string err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400},
"ir": {"distance_noise_mm": "gaussian"}})");
    EXPECT_NE(err.find("world.json:2:29: ir.distance_noise_mm: expected mm, the sd of each message's own distance "
                       "error (0: none) 0..20, found text \"gaussian\"; e.g. \"distance_noise_mm\": 0.5"),
              std::string::npos) << err;
    err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400}, "ir": {"distance_bias_mm": -1}})");
    EXPECT_NE(err.find("world.json:1:75: ir.distance_bias_mm: expected mm within which each pair's distance "
                       "estimates are off (0: exact) 0..20, found -1; e.g. \"distance_bias_mm\": 2"),
              std::string::npos) << err;
}

}  // namespace
