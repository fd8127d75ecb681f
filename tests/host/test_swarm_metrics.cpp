// The built-in metrics' measures (cli/src/metrics/swarm_measures.cpp) on
// layouts whose answers are known by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "../../cli/src/metrics/swarm_measures.hpp"

using namespace openswarm;

namespace {

RobotSample at(double x, double y, int r = 0, int g = 0, int b = 0) { return {0, x, y, 0, r, g, b}; }

}  // namespace

TEST(SwarmMeasures, NearestNeighbourIsTheMeanOfEachRobotsNearest) {
    // Nearest: 30 (to the second), 30 (to the first), 70 (to the second).
    EXPECT_NEAR(mean_nearest_neighbour_mm({at(0, 0), at(30, 0), at(100, 0)}), (30 + 30 + 70) / 3.0, 1e-9);
    // A 3-4-5 triangle's sides: each robot's nearest is 3, 3 and 4 away.
    EXPECT_NEAR(mean_nearest_neighbour_mm({at(0, 0), at(3, 0), at(0, 4)}), (3 + 3 + 4) / 3.0, 1e-9);
}

TEST(SwarmMeasures, NearestNeighbourOfOneRobotIsNone) {
    EXPECT_TRUE(std::isnan(mean_nearest_neighbour_mm({at(5, 5)})));
    EXPECT_TRUE(std::isnan(mean_nearest_neighbour_mm({})));
}

TEST(SwarmMeasures, LargestGroupLinksRobotsWithinTheRange) {
    std::vector<RobotSample> line = {at(0, 0), at(80, 0), at(160, 0), at(400, 0)};
    EXPECT_DOUBLE_EQ(largest_group_fraction(line, 100), 0.75); // 0-80-160 chained, 400 alone
    EXPECT_DOUBLE_EQ(largest_group_fraction(line, 80), 0.75);  // exactly the range: linked
    EXPECT_DOUBLE_EQ(largest_group_fraction(line, 79.9), 0.25);
    EXPECT_DOUBLE_EQ(largest_group_fraction(line, 240), 1.0);
    // Two groups of two and three: the larger counts.
    std::vector<RobotSample> two = {at(0, 0), at(0, 50), at(500, 0), at(500, 50), at(500, 100)};
    EXPECT_DOUBLE_EQ(largest_group_fraction(two, 60), 0.6);
}

TEST(SwarmMeasures, LedAgreementIsTheShareShowingTheCommonestColour) {
    EXPECT_DOUBLE_EQ(led_agreement({at(0, 0, 3), at(0, 0, 3), at(0, 0, 0, 3), at(0, 0)}), 0.5);
    EXPECT_DOUBLE_EQ(led_agreement({at(0, 0), at(0, 0), at(0, 0)}), 1.0); // all dark agree
    EXPECT_DOUBLE_EQ(led_agreement({at(0, 0, 1, 2, 3), at(0, 0, 1, 2, 2), at(0, 0, 3, 2, 1)}), 1.0 / 3);
    EXPECT_TRUE(std::isnan(led_agreement({})));
}

TEST(SwarmMeasures, LightDistanceIsToTheNearestSource) {
    std::vector<LightSource> lights = {{0, 0, 1000}, {1000, 0, 1000}};
    // 50 mm from the first (a 30-40-50 triangle), 10 mm from the second.
    EXPECT_NEAR(mean_light_distance_mm({at(30, 40), at(1000, 10)}, lights), 30, 1e-9);
    EXPECT_TRUE(std::isnan(mean_light_distance_mm({at(1, 1)}, {})));
}

TEST(SwarmMeasures, CoverageCountsCellsVisitedSoFar) {
    CoverageGrid grid(100, 100, 50); // four cells
    EXPECT_DOUBLE_EQ(grid.fraction(), 0);
    grid.visit({at(10, 10), at(60, 10)});
    EXPECT_DOUBLE_EQ(grid.fraction(), 0.5);
    grid.visit({at(10, 10)}); // again: nothing new
    EXPECT_DOUBLE_EQ(grid.fraction(), 0.5);
    grid.visit({at(100, 100)}); // on the far walls: the last cell
    EXPECT_DOUBLE_EQ(grid.fraction(), 0.75);
}

TEST(SwarmMeasures, CoverageOfAnArenaNotAWholeNumberOfCells) {
    CoverageGrid grid(120, 40, 50); // 3 x 1 cells, the last one cut short
    grid.visit({at(110, 20)});
    EXPECT_DOUBLE_EQ(grid.fraction(), 1.0 / 3);
}
