// An experiment's statistics: each controller's mean and standard
// deviation over its trials, sample by sample, and the summary table of
// them that `openswarm experiment` prints.
#pragma once

#include <string>
#include <vector>

#include "experiment_plot.hpp"
#include "experiment_spec.hpp"

namespace openswarm {

// The clustering metrics of one trial at one time.
struct Sample {
    double time_s, cluster, compactness;
};

// The curves of the controller name over the trials that ran (each its
// samples), as long as the shortest of them; empty if none ran.
ControllerCurves controller_curves(const std::string &name, const std::vector<const std::vector<Sample> *> &trials);

// The largest cluster at the reference time (or half-way) and at the end,
// and the compactness at the end, each controller's mean +- SD.
void print_experiment_table(const Experiment &e, const std::vector<ControllerCurves> &curves);

}  // namespace openswarm
