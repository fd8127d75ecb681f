// The experiment's plot (results.png and results.svg, drawn once with
// Cairo): for each controller the mean over its trials of the largest
// cluster's share and of the compactness against time, a band of one
// standard deviation either side, and a real-robot reference marked.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "experiment_spec.hpp"

namespace openswarm {

// One controller's curves: at each sample time, mean and standard
// deviation over its trials.
struct ControllerCurves {
    std::string name;
    std::vector<double> time_s, cluster_mean, cluster_sd, compact_mean, compact_sd;
};

// Writes dir/results.png and dir/results.svg; false (with why) on failure.
bool write_experiment_plot(const Experiment &e, const std::vector<ControllerCurves> &curves,
                           const std::filesystem::path &dir, std::string &why);

}  // namespace openswarm
