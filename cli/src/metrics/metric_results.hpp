// A run's metrics once measured: each one's values over time, written as
// one tidy CSV (a row per time, metric and robot) and shown as a table.
#pragma once

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace openswarm {

struct MetricPoint {
    double time_s; // NaN: not known (a script's value at the end of a run without samples)
    double value;
};

struct MetricResult {
    std::string name, unit, doc;
    std::string source;             // "built-in", "firmware", "script PATH"
    std::vector<MetricPoint> swarm; // over time; for the firmware's, the mean over robots
    std::map<int, std::vector<MetricPoint>> robots; // the firmware's: each robot's reports
};

// time_s,metric,robot,value: robot empty for the swarm's value, the
// robot's index (as in trajectories.csv) for its own report. Throws
// MetricsError when it cannot be written.
void write_metrics_csv(const std::vector<MetricResult> &results, const std::filesystem::path &file);

// One line per metric: at the end, lowest and highest over time, samples,
// where it comes from; the firmware's per robot below it.
void print_metrics_table(const std::vector<MetricResult> &results, std::FILE *out);

}  // namespace openswarm
