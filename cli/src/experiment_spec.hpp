// An experiment file (`openswarm experiment FILE`, docs/case-study.md):
// the world every trial starts from - an arena, robots and objects placed
// at random on a grid of marks, as in the paper's case study - the
// controllers to compare, how many trials of each, how long, from which
// seed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace openswarm {

// A controller's name names its trials' folders (a file name holds at most
// 255 bytes): at most this long.
constexpr size_t max_controller_name = 100;

struct ExperimentController {
    std::string name;              // as results.csv and the plot name it
    std::filesystem::path program; // the controller built for the world
};

struct Experiment {
    std::filesystem::path file;
    double width_mm = 0, height_mm = 0;
    int columns = 0, rows = 0;   // the grid of marks, centred in the arena
    double spacing_mm = 0;
    int robots = 0;
    int objects = 0;
    double object_radius_mm = 50, object_mass_g = 50, object_friction = 0.5;
    double duration_s = 0, sample_period_s = 1;
    int trials = 0;
    uint32_t seed = 1;
    std::vector<ExperimentController> controllers;
    // "fidelity": "native" (or openswarm experiment --native): each
    // controller runs in the simulator's process, the build of
    // native_program (docs/case-study.md).
    bool native = false;
    // A real-robot result to mark on the plot: this fraction at this time.
    double reference_fraction = -1, reference_time_s = -1;
    std::string reference_label;
};

// What a controller's trial folders are named after (trial-01-<this>):
// its ASCII letters lower-cased, its digits, and a '-' for every other
// byte. Two controllers whose names give the same are refused.
std::string controller_folder(const std::string &name);

// openswarm-sim writes at most this many rows of trajectories.csv and
// objects.csv in a run (robots and objects x samples; OUTPUT_MAX_ROWS in
// sim/src/output/output.h, docs/world.md).
constexpr double max_trial_rows = 50000000.0;

// Every trial's samples within max_trial_rows; a message naming the file,
// the numbers and the fix if not, else "". duration_given: --duration set
// the duration, not the file.
std::string trial_rows_problem(const Experiment &e, bool duration_given);

// Read and check file; throws ConfigError naming the file, the key and the fix.
Experiment load_experiment(const std::filesystem::path &file);

// Where `openswarm build --native` puts the controller whose pipe-mode
// build is program: <app>/build/<port>/<name> becomes
// <app>/build/<port>-native/<name>.so; a program that is a .so already
// stays as it is.
std::filesystem::path native_program(const std::filesystem::path &program);

// The world.json of one trial: robots and objects on distinct marks,
// drawn from seed alone (every controller of a trial gets the same one).
std::string trial_world(const Experiment &e, uint32_t seed, const std::filesystem::path &program);

}  // namespace openswarm
