// Where an image's flash and RAM go, by owner: the kernel and port, the
// pools it reserves, the app, the C runtime. Link-time optimisation merges
// functions across files, so the image's own link map cannot say; a second
// build without it (build/<port>-size) has a map that names the file of
// every byte. Used by `build` (the shares) and `size` (the details).
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "app_parameters.hpp"
#include "paths.hpp"

namespace openswarm {

// The owners the attribution names.
namespace owner {
constexpr const char *kernel = "kernel and port";
constexpr const char *stacks = "thread stacks (pool)";
constexpr const char *event_data = "event data (d_i)";
constexpr const char *event_queue = "event queue";
constexpr const char *app = "app";
constexpr const char *runtime = "C runtime and library";
}  // namespace owner

struct Attribution {
    std::map<std::string, unsigned> flash, ram; // bytes by owner (missing: 0)
    std::set<std::string>
        kernel_objects; // the kernel's and port's object files linked: "kilolib.c.obj"
    unsigned flash_of(const std::string &who) const;
    unsigned ram_of(const std::string &who) const;
    unsigned flash_total() const;
    unsigned ram_total() const;
};

// One line of the shares `build` prints: owners grouped, bytes in the
// attribution build, and their percentage of its total (0 when no bytes).
struct Share {
    std::string name;    // "kernel and port"
    std::string key;     // for --json: "kernel_and_port"
    unsigned flash, ram; // bytes without link-time optimisation
    double flash_percent, ram_percent;
};

// The kernel and port, the pools it reserves for the app's threads and
// events, the app's own code and variables, the C runtime.
std::vector<Share> shares_of(const Attribution &a);

// Where the attribution build goes: build/<port>-size, and for a set of
// the app's parameters other than the defaults build/<port>-size-p<its
// fingerprint> (as build_app's folders).
std::filesystem::path attribution_dir(const std::filesystem::path &dir, const std::string &port,
                                      const ParameterValues &parameters = {});

// Build the app in dir (named name) for port once more, without link-time optimisation,
// and read its link map; after the first time the build is incremental.
// The app's own build must have run (it writes the generated files both
// use). parameters: the values that differ from openswarm.json's defaults
// (BuildResult::parameters). On failure nullopt, and why says what failed
// and what to do.
std::optional<Attribution> attribute_app(const Paths &paths, const std::filesystem::path &dir,
                                         const std::string &name, const std::string &port,
                                         const ParameterValues &parameters, std::string &why);

}  // namespace openswarm
