// Which of a sweep's points a plot of one parameter joins into a line:
// the points that agree on every other parameter (sweep_plot.cpp draws the
// metric at the end against the parameter, a line each).
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

namespace openswarm {

// The lines for parameter `which` of points (a value each parameter),
// each a list of point indices in the sweep's order. A sweep that varies
// one parameter at a time around a base (a list of points) would also
// give a one-point line for every point where another parameter varies:
// those are left out when some line has two points or more.
std::vector<std::vector<size_t>> parameter_lines(const std::vector<std::vector<nlohmann::json>> &points,
                                                 size_t which);

}  // namespace openswarm
