// The object-clustering metrics (cli/src/metrics/object_clusters.cpp) on layouts
// whose clusters and compactness are known by hand.
#include <gtest/gtest.h>

#include "../../cli/src/metrics/object_clusters.hpp"

using openswarm::ObjectPosition;

namespace {

constexpr double R = 50; // the paper's objects: 10 cm across

TEST(ClusterMetrics, TouchingObjectsFormOneCluster) {
    // A row of four touching, one far away: 4 of 5.
    std::vector<ObjectPosition> o = {{0, 0}, {100, 0}, {200, 0}, {300, 0}, {2000, 2000}};
    EXPECT_DOUBLE_EQ(openswarm::largest_cluster_fraction(o, R), 0.8);
}

TEST(ClusterMetrics, AGapAnEpuckCannotPassStillLinks) {
    // 109 mm apart: 9 mm gap, within the 10 mm; 111 mm: apart.
    EXPECT_DOUBLE_EQ(openswarm::largest_cluster_fraction({{0, 0}, {109, 0}}, R), 1.0);
    EXPECT_DOUBLE_EQ(openswarm::largest_cluster_fraction({{0, 0}, {111, 0}}, R), 0.5);
}

TEST(ClusterMetrics, ClustersLinkThroughNeighbours) {
    // An L of three: the ends are 141 mm apart but linked through the corner;
    // a separate pair. Largest: 3 of 5.
    std::vector<ObjectPosition> o = {{0, 0}, {100, 0}, {100, 100}, {1000, 0}, {1100, 0}};
    EXPECT_DOUBLE_EQ(openswarm::largest_cluster_fraction(o, R), 0.6);
}

TEST(ClusterMetrics, ScatteredObjectsAreEachTheirOwn) {
    std::vector<ObjectPosition> o = {{0, 0}, {500, 0}, {0, 500}, {500, 500}};
    EXPECT_DOUBLE_EQ(openswarm::largest_cluster_fraction(o, R), 0.25);
    EXPECT_DOUBLE_EQ(openswarm::largest_cluster_fraction({}, R), 0.0);
}

TEST(ClusterMetrics, CompactnessIsTheSecondMomentOverFourRSquared) {
    // Four corners of a 200 mm square: each 141.42 mm from the centre,
    // squared 20000; sum 80000; / (4 x 2500) = 8.
    std::vector<ObjectPosition> o = {{0, 0}, {200, 0}, {0, 200}, {200, 200}};
    EXPECT_NEAR(openswarm::compactness(o, R), 8.0, 1e-12);
    // Moved together the measure does not change; spread twice as far, x4.
    for (auto &p : o) p.x_mm += 1000, p.y_mm -= 300;
    EXPECT_NEAR(openswarm::compactness(o, R), 8.0, 1e-12);
    for (auto &p : o) p.x_mm *= 2, p.y_mm *= 2;
    EXPECT_NEAR(openswarm::compactness(o, R), 32.0, 1e-9);
    EXPECT_DOUBLE_EQ(openswarm::compactness({{5, 5}}, R), 0.0);
}

}  // namespace
