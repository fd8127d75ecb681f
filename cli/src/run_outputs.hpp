// A world run's output folder before the simulator writes into it: the
// last run's outputs are kept beside the new ones, or their replacement
// said - never overwritten unseen.
#pragma once

#include <filesystem>

namespace openswarm {

// out holds a run's outputs already (its trajectories.csv or viewer.html):
// the default folder (out_given false) is moved to OUT.last, which an
// older OUT.last gives way to, and the move is told; a folder the user
// named with --out is told to be overwritten. False after a message if
// the move failed. A world read from out itself (a run's world.json run
// again) leaves the folder where it is.
bool keep_last_run(const std::filesystem::path &out, bool out_given, const std::filesystem::path &world);

}  // namespace openswarm
