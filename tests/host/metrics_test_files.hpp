// Small hand-made run folders for the metrics' tests.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace metrics_test {

// An empty folder of the test's own under the system's temporary one.
inline std::filesystem::path fresh_dir(const std::string &name) {
    auto dir = std::filesystem::temp_directory_path() /
               ("openswarm-metrics-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline void write_file(const std::filesystem::path &file, const std::string &text) {
    std::ofstream(file) << text;
}

}  // namespace metrics_test
