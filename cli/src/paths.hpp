// Where the tool finds OpenSwarm's files: the SDK, ports, templates and the
// simulator, relative to itself (build tree or installed prefix).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace openswarm {

struct Paths {
    std::filesystem::path root;      // holds sdk/, ports/, templates/, kernel/, cmake/
    std::filesystem::path simulator; // openswarm-sim
    std::filesystem::path templates() const { return root / "templates"; }
    std::filesystem::path sdk_cmake() const { return root / "sdk" / "cmake"; }
};

// Throws std::runtime_error saying what is missing and what to do.
Paths locate_paths(const char *argv0);

// Why the tool cannot run its simulator ("" when openswarm-sim was found):
// what to build.
std::string simulator_problem(const Paths &paths);

// The full path of a program on PATH, if any.
std::optional<std::filesystem::path> find_program(const std::string &name);

}  // namespace openswarm
