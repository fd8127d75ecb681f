// An experiment's results folder, made before any trial runs.
#pragma once

#include <filesystem>

#include "experiment_ranks.hpp"

namespace openswarm {

// Made (by every rank, as each writes its trials there), or false after a
// message naming it, why, and the fix (from rank 0 only: the others find
// the same).
bool prepare_results_folder(const std::filesystem::path &out, const Ranks &ranks);

}  // namespace openswarm
