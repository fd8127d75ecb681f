// A sweep's results, gathered from its trials' metrics into tidy files:
// trials.csv (a row per trial: its point, seed, whether it ran and why
// not), results.csv (a row per trial, time and metric) and summary.csv (a
// row per point and metric: the trials' values at their end, mean, sd,
// n, 95% interval), and the summary as a table.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sweep_spec.hpp"
#include "sweep_trial.hpp"

namespace openswarm {

// Writes the three files into out; false with why when one cannot be.
bool write_sweep_results(const Sweep &s, const std::vector<SweepTrial> &trials, const std::filesystem::path &out,
                         std::string &why);

// Each point's metrics at the end of its trials: mean +- the interval's
// half-width, and n.
void print_sweep_summary(const Sweep &s, const std::vector<SweepTrial> &trials, std::FILE *to);

}  // namespace openswarm
