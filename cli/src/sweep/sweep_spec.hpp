// A sweep file (`openswarm experiment FILE` when FILE names a "world";
// docs/experiments.md, "Sweeps"): an app, the world its robots run in,
// parameters of that world to vary as a grid or a list of points, how
// many trials (seeds) of each point, and the metrics to measure.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../app_parameters.hpp"
#include "../trial_video.hpp"
#include "mark_placement.hpp"

namespace openswarm {

// A value a sweep varies: a world field, named by its place in
// world.json ("arena.width_mm", "robots[0].count", "ir.loss_percent"), or
// a parameter of the app, "app.NAME" (openswarm.json's "parameters": each
// set of them is a build of its own), or "program": which program of the
// app's build the robots run (the case study's two controllers).
struct SweepParameter {
    std::string path;
    std::vector<nlohmann::json> values; // as the grid lists them (empty for a list of points)
};

struct Sweep {
    std::filesystem::path file;
    std::filesystem::path app;   // the folder holding openswarm.json
    std::filesystem::path world; // the world every point starts from
    nlohmann::json base_world;
    std::string description;
    int trials = 1;
    uint32_t seed = 1;           // trial t (from 0) runs with seed + t
    double duration_s = 0;       // 0: the world's
    std::optional<Marks> marks;  // each trial's robots and objects on marks drawn from its seed
    std::vector<SweepParameter> parameters;
    // The "app.NAME" places the firmware reads from the EEPROM ("at":
    // "eeprom"): set in each point's world, one build for all, by name.
    std::map<std::string, AppParameter> eeprom_parameters;
    std::vector<std::vector<nlohmann::json>> points; // a value for each parameter
    std::vector<std::string> metrics;                // as `openswarm metrics --metric` takes them
    std::vector<std::filesystem::path> scripts;
    double every_s = 0;
    bool native = false; // every point's world in "fidelity": "native" (--native)
    TrialVideo video;    // the trials filmed (--video)
};

// Whether the experiment file at path is a sweep (it names a "world"),
// not the case study's clustering experiment (docs/case-study.md). False
// when it cannot be read: the loader that follows says why.
bool is_sweep_file(const std::filesystem::path &file);

// Reads and checks the file and its world; throws ConfigError naming the
// file, the key and the fix.
Sweep load_sweep(const std::filesystem::path &file);

// The world of one point (parameters set) and trial (seed, duration).
nlohmann::json point_world(const Sweep &s, size_t point, int trial);

// The app's parameters a point builds in ("app.NAME" places but those
// read from the EEPROM), by name.
ParameterValues point_parameters(const Sweep &s, size_t point);

// Whether a sweep's place names an app parameter ("app.NAME"), not a world field.
bool is_app_place(const std::string &path);

// The place naming the program of the app's build a point runs.
constexpr const char *program_place = "program";

// The program a point runs, a file of the app's build folder ("" for the
// app's own image).
std::string point_program(const Sweep &s, size_t point);

// "robots[0].count=10, ir.loss_percent=20" (the base world for no parameters).
std::string point_label(const Sweep &s, size_t point);

// The most trials at once a sweep may hold.
constexpr size_t max_sweep_trials = 100000;

}  // namespace openswarm
