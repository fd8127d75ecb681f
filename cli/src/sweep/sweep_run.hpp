// `openswarm experiment SWEEP.json`: builds the app, runs every trial of
// every point (on this machine's cores, this rank's share under MPI, or
// one shard of a Slurm array), each into its own folder as it finishes,
// resuming what an earlier run left, and gathers the results.
#pragma once

#include <string>

#include "../experiment_ranks.hpp"
#include "../paths.hpp"
#include "../trial_video.hpp"

namespace openswarm {

struct SweepOptions {
    std::string file;
    std::string out;        // default: <file's folder>/<file's stem>-results
    unsigned jobs = 0;      // 0: one per core
    int trials = 0;         // 0: the file's
    double duration_s = 0;  // 0: the file's (or the world's)
    std::string shard;      // "K/N": every N-th trial from the K-th (0-based); empty: all
    bool native = false;    // every point in the native mode (--native)
    TrialVideo video;       // the trials filmed (--video)
};

// The tool's exit status: 0 every trial done, 1 some failed (the rest
// kept), 2 bad input.
int run_sweep(const SweepOptions &o, const Paths &paths, const Ranks &ranks);

}  // namespace openswarm
