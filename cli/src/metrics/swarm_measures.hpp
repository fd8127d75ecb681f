// Measures of the robots at one sample, each a plain function of their
// positions or colours (the built-in metrics, builtin_metrics.cpp, call
// them sample by sample). NaN where a measure has no value: no robots, or
// one robot and no neighbour to measure to.
#pragma once

#include <vector>

#include "run_snapshots.hpp"
#include "run_world.hpp"

namespace openswarm {

// The mean over robots of the centre-to-centre distance to the nearest
// other robot, mm.
double mean_nearest_neighbour_mm(const std::vector<RobotSample> &robots);

// The share of robots in the largest group linked by neighbours whose
// centres are at most range_mm apart (straight line; walls ignored).
double largest_group_fraction(const std::vector<RobotSample> &robots, double range_mm);

// The share of robots showing the most common LED colour (off counts as a
// colour: a swarm all dark agrees).
double led_agreement(const std::vector<RobotSample> &robots);

// The mean over robots of the distance from their centre to the nearest
// light source, mm.
double mean_light_distance_mm(const std::vector<RobotSample> &robots, const std::vector<LightSource> &lights);

// The arena as a grid of square cells, and which of them a robot's centre
// has been in at any sample so far.
class CoverageGrid {
public:
    CoverageGrid(double width_mm, double height_mm, double cell_mm);
    void visit(const std::vector<RobotSample> &robots);
    // Cells visited / all cells.
    double fraction() const;

private:
    double cell_mm_;
    long columns_, rows_;
    std::vector<char> visited_;
    long count_ = 0;
};

}  // namespace openswarm
