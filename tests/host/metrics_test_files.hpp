// Small hand-made run folders for the metrics' tests.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace metrics_test {

// The folders fresh_dir made, removed when the test program ends (each
// run's pid is in their names, so they would pile up in /tmp otherwise).
inline struct made_dirs {
    std::vector<std::filesystem::path> dirs;
    ~made_dirs() {
        std::error_code ignored;
        for (const auto &dir : dirs) std::filesystem::remove_all(dir, ignored);
    }
} made;

// An empty folder of the test's own under the system's temporary one.
inline std::filesystem::path fresh_dir(const std::string &name) {
    auto dir = std::filesystem::temp_directory_path() /
               ("openswarm-metrics-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    made.dirs.push_back(dir);
    return dir;
}

inline void write_file(const std::filesystem::path &file, const std::string &text) {
    std::ofstream(file) << text;
}

}  // namespace metrics_test
