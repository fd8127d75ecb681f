// Why trials failed, as one text that travels from an MPI rank to rank 0
// (experiment_ranks.cpp). A reason is whatever the simulator printed, so
// it may hold any character: newlines, tabs, digits, NULs.
#pragma once

#include <string>
#include <vector>

#include "experiment_ranks.hpp"

namespace openswarm {

// The failure reasons of the outcomes marked here, in one text.
std::string encode_failures(const std::vector<TrialOutcome> &outcomes);

// Sets each failure the text names on outcomes; false (why says where the
// text stops making sense) for a text encode_failures did not write.
bool decode_failures(const std::string &text, std::vector<TrialOutcome> &outcomes, std::string &why);

}  // namespace openswarm
