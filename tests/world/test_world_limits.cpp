// What one world may hold (world_spec.h's WORLD_MAX_*, docs/world.md's
// "Limits"): past each limit the file is refused at the list or group
// that goes over, with the numbers and the fix; at the limits it loads.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "world_file_fixture.hpp"

namespace {

// n copies of item, comma-separated.
std::string repeated(const std::string &item, int n) {
    std::string list;
    for (int k = 0; k < n; k++) list += (k ? ", " : "") + item;
    return list;
}

// n rectangles, each 0.01 mm right of the one before: all overlapping,
// none the same (the worst case for the physics' broad phase).
std::string overlapping_rects(int n) {
    std::string list;
    for (int k = 0; k < n; k++)
        list += std::string(k ? ", " : "") + "{\"rect\": {\"x_mm\": " + std::to_string(100 + k * 0.01) +
                ", \"y_mm\": 100, \"width_mm\": 50, \"height_mm\": 20}}";
    return list;
}

// n polygons of 32 vertices (a 32-gon about (x, 300)).
std::string polygons(int n) {
    std::string polygon = "{\"polygon\": [";
    for (int k = 0; k < 32; k++) {
        double a = k * 6.283185307179586 / 32;
        polygon += std::string(k ? ", " : "") + "[" + std::to_string(300 + 50 * std::cos(a)) + ", " +
                   std::to_string(300 + 50 * std::sin(a)) + "]";
    }
    return repeated(polygon + "]}", n);
}

std::string first_line(const std::string &err) { return err.substr(0, err.find('\n')); }

const char *arena = R"({"arena": {"width_mm": 4000, "height_mm": 4000},
)";

TEST_F(WorldFile, MoreObstaclesThanTheLimitAreRefused) {
    EXPECT_EQ(first_line(error_of(arena + ("\"obstacles\": [" + overlapping_rects(1001) + "]}"))),
              "world.json:2:14: obstacles: 1001 obstacles: at most 1000 in one world (docs/world.md, \"Limits\"); "
              "merge neighbouring obstacles into one polygon (up to 32 vertices), or keep fewer");
    // 10000 identical ones (2.7 GB, then SIGSEGV in Box2D's broad phase)
    std::string identical = "{\"rect\": {\"x_mm\": 100, \"y_mm\": 100, \"width_mm\": 50, \"height_mm\": 20}}";
    EXPECT_NE(error_of(arena + ("\"obstacles\": [" + repeated(identical, 10000) + "]}"))
                  .find("obstacles: 10000 obstacles: at most 1000 in one world"),
              std::string::npos);
}

TEST_F(WorldFile, MoreObstacleVerticesThanTheLimitAreRefused) {
    // 125 polygons of 32 vertices are 4000; the 126th passes the limit
    std::string err = first_line(error_of(arena + ("\"obstacles\": [" + polygons(126) + "]}")));
    EXPECT_NE(err.find("obstacles[125]: the obstacles up to this one have 4032 vertices: at most 4000 in one world, "
                       "as many edges"),
              std::string::npos)
        << err;
    EXPECT_NE(err.find("merge neighbouring obstacles into one polygon, or simplify them"), std::string::npos) << err;
}

TEST_F(WorldFile, MoreObjectsThanTheLimitAreRefused) {
    std::string object = "{\"x_mm\": 200, \"y_mm\": 200, \"radius_mm\": 1}";
    EXPECT_EQ(first_line(error_of(arena + ("\"objects\": [" + repeated(object, 10001) + "]}"))),
              "world.json:2:12: objects: 10001 objects: at most 10000 in one world (docs/world.md, \"Limits\"); "
              "keep fewer");
}

TEST_F(WorldFile, MoreRobotsThanTheLimitAreRefused) {
    const char *big = R"({"arena": {"width_mm": 100000, "height_mm": 100000},
"robots": [{"count": 6000}, {"count": 5000}]})";
    EXPECT_EQ(first_line(error_of(big)),
              "world.json:2:39: robots[1].count: this group's 5000 robots bring the world's to 11000: at most 10000 "
              "in one world (docs/world.md, \"Limits\"); lower this group's count to at most 4000");
    const char *grid = R"({"arena": {"width_mm": 100000, "height_mm": 100000},
"robots": [{"count": 9999}, {"grid": {"x_mm": 50, "y_mm": 50, "columns": 2, "rows": 1, "spacing_mm": 40}}]})";
    EXPECT_NE(first_line(error_of(grid)).find("robots[1].grid: this group's 2 robots bring the world's to 10001"),
              std::string::npos);
}

// At every limit at once (obstacles all overlapping: the worst case for
// the physics): it loads.
TEST_F(WorldFile, AWorldAtTheLimitsLoads) {
    std::string objects;
    for (int k = 0; k < 10000; k++)
        objects += std::string(k ? ", " : "") + "{\"x_mm\": " + std::to_string(1000 + (k % 100) * 20) +
                   ", \"y_mm\": " + std::to_string(1000 + (k / 100) * 20) + ", \"radius_mm\": 5}";
    world_spec w{};
    ASSERT_EQ(load(R"({"arena": {"width_mm": 8000, "height_mm": 8000},
"obstacles": [)" + overlapping_rects(1000) + R"(],
"objects": [)" + objects + R"(],
"robots": [{"count": 5000, "region": {"x_mm": 3100, "y_mm": 0, "width_mm": 4900, "height_mm": 8000}},
           {"count": 5000, "region": {"x_mm": 3100, "y_mm": 0, "width_mm": 4900, "height_mm": 8000}}]})",
                   &w),
              "");
    EXPECT_EQ(w.n_obstacles, WORLD_MAX_OBSTACLES);
    EXPECT_EQ(w.n_objects, WORLD_MAX_OBJECTS);
    EXPECT_EQ(w.n_robots, WORLD_MAX_ROBOTS);
    world_spec_free(&w);
}

}  // namespace
