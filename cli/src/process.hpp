// Running the programs the tool drives (cmake, the simulator).
#pragma once

#include <string>
#include <vector>

namespace openswarm {

// Run argv[0] with its arguments, its output going to ours; its exit
// status (or 127 if it could not be started).
int run_program(const std::vector<std::string> &argv);

// Run it and capture its standard output.
int capture_program(const std::vector<std::string> &argv, std::string &output);

}  // namespace openswarm
