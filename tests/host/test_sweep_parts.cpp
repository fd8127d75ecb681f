// A sweep's parts that need no simulator: places in a world and the
// statistics of its summary (cli/src/sweep/).
#include <gtest/gtest.h>

#include <cmath>

#include "../../cli/src/sweep/sweep_lines.hpp"
#include "../../cli/src/sweep/sweep_stats.hpp"
#include "../../cli/src/sweep/world_paths.hpp"

using nlohmann::json;
using namespace openswarm;

namespace {

json world() {
    return json::parse(R"({"arena": {"width_mm": 500}, "robots": [{"count": 3, "poses": [{"x_mm": 1}]}]})");
}

}  // namespace

TEST(WorldPaths, SetsKeysAndListItems) {
    json w = world();
    ASSERT_EQ(world_path_problem(w, "robots[0].count"), "");
    set_world_path(w, "robots[0].count", 7);
    set_world_path(w, "robots[0].poses[0].x_mm", 12.5);
    EXPECT_EQ(w["robots"][0]["count"], 7);
    EXPECT_EQ(w["robots"][0]["poses"][0]["x_mm"], 12.5);
}

TEST(WorldPaths, MakesMissingObjectsOnTheWay) {
    json w = world();
    ASSERT_EQ(world_path_problem(w, "ir.loss_pct"), "");
    set_world_path(w, "ir.loss_pct", 20);
    EXPECT_EQ(w["ir"]["loss_pct"], 20);
    EXPECT_EQ(w["arena"]["width_mm"], 500); // the rest untouched
}

TEST(WorldPaths, RefusesWhatTheWorldCannotHold) {
    json w = world();
    EXPECT_EQ(world_path_problem(w, "robots[1].count"), "the world's robots has no item [1] (it holds 1)");
    EXPECT_EQ(world_path_problem(w, "arena.width_mm.x"), "the world's arena.width_mm is not an object, so it has no \"x\"");
    EXPECT_EQ(world_path_problem(w, "arena[0].x"), "the world's arena has no item [0] (it is not a list)");
    for (const char *bad : {"", "robots[0]", ".arena", "arena..width_mm", "arena.", "[0].x",
                            "robots[0]count", "arena width"})
        EXPECT_NE(world_path_problem(w, bad).find("is not a place in a world"), std::string::npos) << bad;
    EXPECT_NE(world_path_problem(w, "robots[x].count").find("a list item is [N]"), std::string::npos);
}

TEST(WorldPaths, EveryItemOfAList) {
    json w = json::parse(R"({"objects": [{"x_mm": 1, "mass_g": 50}, {"x_mm": 2, "mass_g": 50}, {"x_mm": 3}]})");
    ASSERT_EQ(world_path_problem(w, "objects[*].mass_g"), "");
    set_world_path(w, "objects[*].mass_g", 25);
    for (int k = 0; k < 3; k++) {
        EXPECT_EQ(w["objects"][k]["mass_g"], 25) << k;
        EXPECT_EQ(w["objects"][k]["x_mm"], k + 1) << "the rest of each item untouched";
    }
    json nested = json::parse(R"({"robots": [{"poses": [{"x_mm": 1}, {"x_mm": 2}]}, {"poses": [{"x_mm": 3}]}]})");
    set_world_path(nested, "robots[*].poses[*].heading_deg", 90);
    EXPECT_EQ(nested["robots"][1]["poses"][0]["heading_deg"], 90);
    EXPECT_EQ(nested["robots"][0]["poses"][1]["heading_deg"], 90);
    EXPECT_EQ(world_path_problem(json::parse(R"({"objects": []})"), "objects[*].mass_g"),
              "the world's objects has no items for [*] to set (it is empty)");
    EXPECT_EQ(world_path_problem(w, "arena[*].x"), "the world's arena has no items for [*] to set (it is not a list)");
    EXPECT_NE(world_path_problem(w, "objects[*]").find("is not a place in a world"), std::string::npos)
        << "a path ends in a key";
}

TEST(SweepLines, AGridJoinsThePointsThatAgreeOnTheOthers) {
    // a in {1, 2} x b in {x, y}: for a, a line for b = x and one for b = y.
    std::vector<std::vector<json>> grid = {{1, "x"}, {1, "y"}, {2, "x"}, {2, "y"}};
    EXPECT_EQ(parameter_lines(grid, 0), (std::vector<std::vector<size_t>>{{0, 2}, {1, 3}}));
    EXPECT_EQ(parameter_lines(grid, 1), (std::vector<std::vector<size_t>>{{0, 1}, {2, 3}}));
}

TEST(SweepLines, OneAtATimeLeavesOutTheOtherParametersPoints) {
    // Base (1, 10); a varied to 2 and 3, b to 20: for a, the line of the
    // base and a's points only, not b's point on its own.
    std::vector<std::vector<json>> oat = {{1, 10}, {2, 10}, {3, 10}, {1, 20}};
    EXPECT_EQ(parameter_lines(oat, 0), (std::vector<std::vector<size_t>>{{0, 1, 2}}));
    EXPECT_EQ(parameter_lines(oat, 1), (std::vector<std::vector<size_t>>{{0, 3}}));
    // Nothing varies with another held: every point stays, each its own line.
    std::vector<std::vector<json>> diagonal = {{1, 10}, {2, 20}};
    EXPECT_EQ(parameter_lines(diagonal, 0), (std::vector<std::vector<size_t>>{{0}, {1}}));
}

TEST(SweepStats, MeanSdAndStudentsInterval) {
    // 2, 4, 4, 4, 5, 5, 7, 9: mean 5, sample sd sqrt(32/7); t(7) = 2.365.
    Summary s = summarise({2, 4, 4, 4, 5, 5, 7, 9});
    EXPECT_EQ(s.n, 8u);
    EXPECT_DOUBLE_EQ(s.mean, 5);
    EXPECT_NEAR(s.sd, std::sqrt(32.0 / 7), 1e-12);
    EXPECT_NEAR(s.high - s.mean, 2.365 * std::sqrt(32.0 / 7) / std::sqrt(8.0), 1e-9);
    EXPECT_NEAR(s.mean - s.low, s.high - s.mean, 1e-12);
}

TEST(SweepStats, OneValueHasNoInterval) {
    Summary s = summarise({3});
    EXPECT_EQ(s.n, 1u);
    EXPECT_EQ(s.sd, 0);
    EXPECT_EQ(s.low, 3);
    EXPECT_EQ(s.high, 3);
    EXPECT_EQ(summarise({}).n, 0u);
}

TEST(SweepStats, StudentsQuantiles) {
    EXPECT_DOUBLE_EQ(student_t975(1), 12.706);
    EXPECT_DOUBLE_EQ(student_t975(30), 2.042);
    EXPECT_NEAR(student_t975(50), 2.009, 0.002); // tables: 2.009
    EXPECT_NEAR(student_t975(100), 1.984, 0.002); // tables: 1.984
    EXPECT_DOUBLE_EQ(student_t975(5000), 1.96);
    for (size_t df = 2; df < 2000; df++) EXPECT_LE(student_t975(df), student_t975(df - 1)) << df;
}
