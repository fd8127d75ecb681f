// One trial of a sweep: its folder (OUT/point-NN/trial-NN) with the world
// it ran in, the simulator's outputs, metrics.csv, and outcome.json,
// written last. A trial the simulator ran before in the same world with
// the same firmware is not run again (a sweep resumes where it stopped);
// when the metrics asked for changed since, it is only measured again.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "sweep_spec.hpp"

namespace openswarm {

// One metric's swarm values over a trial: (time_s, value).
struct TrialSeries {
    std::string metric;
    std::vector<std::pair<double, double>> values;
};

struct SweepTrial {
    size_t point = 0;
    int trial = 0;
    uint32_t seed = 0;
    std::filesystem::path dir;
    std::filesystem::path firmware; // the image the world's robots run
    std::string firmware_hash;      // of its bytes, to tell a rebuilt app
    ParameterValues parameters;     // the app's, as the point sets them
    // Filled by run_sweep_trial (or read_sweep_trial):
    bool attempted = false; // run_sweep_trial was called
    bool pending = false;   // not run yet (by any rank, shard or run), or stopped (Ctrl-C)
    bool reused = false;    // simulated by an earlier run of the sweep
    bool remeasured = false; // reused, and measured again: the metrics changed
    bool refused = false; // the simulator refused the world (bad input: the sweep stops)
    std::string failure;  // empty when it ran and was measured
    // Its metrics, read once from its folder when the sweep gathers them
    // (empty for a failed or pending trial).
    std::vector<TrialSeries> series;
};

// Runs (or reuses) the trial, measures it and writes its outcome.json.
void run_sweep_trial(const Sweep &s, const std::filesystem::path &simulator, SweepTrial &t);

// The trial as its folder's outcome.json tells (done, failed and why, or
// pending when there is none): one run elsewhere (another rank or shard).
void read_sweep_trial(SweepTrial &t);

// The swarm's values over time from a trial's metrics.csv, by metric name
// in the order they come (time_s, value).
std::vector<TrialSeries> read_trial_metrics(const std::filesystem::path &dir);

}  // namespace openswarm
