// Reading a checked JSON file (openswarm.json, an experiment): each
// check names the file, the key's path, what was expected and what was
// found, as a ConfigError ready to print.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app_config.hpp"

namespace openswarm {

// The JSON document in text (read from file); a ConfigError at the
// place of a syntax error, or naming a number too large to hold.
nlohmann::json parse_json_file(const std::filesystem::path &file, const std::string &text);

[[noreturn]] void fail(const std::filesystem::path &file, const std::string &path,
                       const std::string &message);
// JSON nested deeper is refused before it is parsed.
constexpr size_t max_json_depth = 64;

// At most bytes of text, cut between UTF-8 characters, "..." if cut.
std::string text_start(const std::string &text, size_t bytes);
// A user's string in a message: quoted, at most 40 bytes of it.
std::string quoted_start(const std::string &text);
// A value as the message shows it: its type and (the start of) its text.
std::string found(const nlohmann::json &v);
// Only these keys; another gets "did you mean".
void check_keys(const std::filesystem::path &file, const std::string &path,
                const nlohmann::json &object, const std::vector<std::string> &allowed);
const nlohmann::json &require(const std::filesystem::path &file, const nlohmann::json &doc,
                              const std::string &key, const std::string &parent = "");
std::string string_at(const std::filesystem::path &file, const std::string &path,
                      const nlohmann::json &v, const char *what);
long number_at(const std::filesystem::path &file, const std::string &path, const nlohmann::json &v,
               long min, long max);
// A number (whole or not) in [min, max].
double real_at(const std::filesystem::path &file, const std::string &path, const nlohmann::json &v,
               double min, double max);

}  // namespace openswarm
