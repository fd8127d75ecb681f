// The CMake project an app is built from: its own CMakeLists.txt if it has
// one, else one the tool writes, which builds every source of the app
// (sdk/cmake/OpenSwarmApp.cmake) under openswarm.json's name.
#pragma once

#include <filesystem>
#include <string>

#include "app_config.hpp"

namespace openswarm {

// The folder CMake configures for the app in dir, built for port: dir, or
// the generated project's folder (write_app_project writes it).
std::filesystem::path app_project_dir(const std::filesystem::path &dir, const std::string &port);

// For an app without a CMakeLists.txt, write the project that builds it
// (C++ enabled when the app has C++ sources); nothing for one that has.
// Throws std::runtime_error if it cannot be written.
void write_app_project(const std::filesystem::path &dir, const AppConfig &config);

// CMake refuses a build folder configured from another project: when the
// app has gained or lost its own CMakeLists.txt since build_dir was
// configured, its cache is removed (the objects stay; CMake rebuilds what
// changed).
void forget_other_project(const std::filesystem::path &dir, const std::string &port,
                          const std::filesystem::path &build_dir);

// A ConfigError naming both files when the app's own CMakeLists.txt builds
// its firmware under a name other than openswarm.json's (the image would
// not be where the tool looks).
void check_app_project_name(const std::filesystem::path &dir, const AppConfig &config);

}  // namespace openswarm
