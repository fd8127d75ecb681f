// What openswarm.json turns into: a configuration header for the kernel's
// pools, and the app's event ids and start-up code (static tables; nothing
// is allocated at run time).
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "app_config.hpp"
#include "ports.hpp"

namespace openswarm {

// Write out_dir/openswarm_config.h, openswarm_app.h, openswarm_app.c and
// openswarm_parameters.h
// (only the files whose content changed, so builds stay incremental), with
// room in the pools for the threads the libraries start as well. A
// max_threads the file gives that leaves them no slot is a ConfigError.
void generate_app_files(const AppConfig &config, const Libraries &libraries,
                        const std::filesystem::path &out_dir);

// Everything generate_app_files checks, without writing: `config check`.
void check_app_files(const AppConfig &config, const Libraries &libraries);

// Write content to file unless it holds it already: a file rewritten
// unchanged would make CMake configure or compile again. Throws
// std::runtime_error if it cannot.
void write_if_changed(const std::filesystem::path &file, const std::string &content);

// The OS_CFG_* values a generated openswarm_config.h sets (empty if it
// cannot be read); the port's defaults hold for the others.
std::map<std::string, unsigned> generated_config_values(const std::filesystem::path &header);

}  // namespace openswarm
