// Measuring a run's folder: the built-in metrics asked for (or every one
// the run allows), the metrics its robots reported, and the user's
// scripts, into one list of results (metric_results.hpp). What
// `openswarm metrics` prints, and what an experiment measures per trial.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "metric_results.hpp"

namespace openswarm {

struct MetricsRequest {
    std::filesystem::path run_dir;
    std::filesystem::path world;      // empty: the run's world.json, when there
    std::vector<std::string> metrics; // as --metric takes them; empty: every one the run allows
    std::vector<std::filesystem::path> scripts;
    double every_s = 0;               // values this far apart at least (0: every sample); the last always
};

struct MetricsOutcome {
    std::vector<MetricResult> results;
    std::vector<std::string> notes; // built-ins left out and why, malformed metric lines
};

// Throws MetricsError (bad_input: exit 2; a script's failure: exit 1).
MetricsOutcome measure_run(const MetricsRequest &request);

}  // namespace openswarm
