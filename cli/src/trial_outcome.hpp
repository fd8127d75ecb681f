// A trial's outcome.json, shared by sweeps and the clustering experiment:
// written last, through a temporary name, so a trial's folder that holds
// one is whole (done, or failed and why). A folder without one was never
// run, or was stopped half-way (Ctrl-C): the same command runs it again.
// Fingerprints of what a trial ran with tell whether its outcome still
// stands for the trial asked for now.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace openswarm {

// A short fingerprint of a file's bytes (fingerprint.hpp's; "" when it
// cannot be read).
std::string file_fingerprint(const std::filesystem::path &file);

// The file's bytes, replaced; false when they could not all be written.
bool write_text(const std::filesystem::path &file, const std::string &text);

// dir/outcome.json, whole or absent.
void write_outcome(const std::filesystem::path &dir, const nlohmann::json &outcome);
// dir/outcome.json, or an empty object when there is none (or it is not
// one: never written whole).
nlohmann::json read_outcome(const std::filesystem::path &dir);
// A trial stopped before its end: its outcome gone, so it is pending.
void forget_outcome(const std::filesystem::path &dir);

}  // namespace openswarm
