// openswarm.json: what an application is, validated with errors that name
// the file, the place and the fix.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace openswarm {

// A bad openswarm.json: the message is ready to print.
struct ConfigError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct AppConfig {
    std::filesystem::path file;
    std::string name;
    std::string port;
};

// Read and validate dir/openswarm.json.
AppConfig load_app_config(const std::filesystem::path &dir);

// "file:line:column: message" plus the line and a caret, for a byte offset.
std::string located_message(const std::filesystem::path &file, const std::string &text,
                            size_t byte, const std::string &message);

}  // namespace openswarm
