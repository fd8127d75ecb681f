// What an app's own source files use, read before the build (whose pool
// sizes depend on the answer).
#pragma once

#include <filesystem>

#include "ports.hpp"

namespace openswarm {

// The port's libraries whose header one of the app's C, C++ or assembler
// files (anywhere in dir, but for its build/ folder and hidden folders)
// includes. A library's functions are reached through its header, so an
// app that includes none of them cannot start the library's threads.
Libraries libraries_used(const std::filesystem::path &dir, const PortInfo &port);

}  // namespace openswarm
