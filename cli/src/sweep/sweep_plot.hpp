// A sweep's pictures, one per metric (plots/<metric>.png and .svg): the
// metric over time at each point (the mean over its trials, a band of one
// standard deviation), and its value at the end against each swept
// parameter (the mean and its 95% interval; a line for each setting of
// the other parameters).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sweep_spec.hpp"
#include "sweep_trial.hpp"

namespace openswarm {

// Writes out/plots/; the plots' files, or false with why.
bool write_sweep_plots(const Sweep &s, const std::vector<SweepTrial> &trials, const std::filesystem::path &out,
                       std::vector<std::filesystem::path> &written, std::string &why);

}  // namespace openswarm
