// openswarm run's options, and the checks made on them before the build.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace openswarm {

struct RunOptions {
    std::string dir = ".";
    std::string port;
    std::string time = "10";
    bool time_given = false;
    int robots = 1;
    int distance = 50;
    std::string line;      // --line SPACING: robots on a line
    std::string positions; // --positions FILE: one "x y" per robot
    std::vector<std::string> parameters; // -D NAME=VALUE
    int ir_range = 0;      // 0: the simulator's default
    bool robots_given = false;
    int gdb = 0;
    bool debug = false; // the debug image (build --debug)
    bool timestamps = false; // console lines begin with their time
    std::string vcd;
    std::vector<std::string> ohc; // overhead-controller messages, MSG@SECONDS
    bool profile = false;
    bool ir_log = false;
    std::string clock_spread; // percent; empty: the simulator's default (none)
    std::string ir_loss;      // percent at the range's edge; empty: none
    std::vector<std::string> first; // firmware robots 0, 1, ... run instead of the app
    std::vector<std::string> simulator_options; // after --, passed as they are
    std::string world; // --world FILE, relative to where the tool was started
    std::string out;   // --out DIR; empty: <app dir>/out/<world file's stem>
    bool video = false;
    bool ids = false;
    std::string video_fps;   // --video-fps; empty: the simulator's default
    std::string video_speed; // --video-speed; empty: likewise
    bool trace = false; // with --world; without it the trace is always on
    bool native = false; // --native, or the world's "fidelity": "native"
    bool strict = false; // the simulator's warnings at the end fail the run
    std::vector<std::string> simavr_only; // such options given, for a port QEMU runs
};

// "2.5", "2.5s" or "20%" (suffix): the number, if it is one in [lo, hi].
std::optional<double> number_in(std::string text, char suffix, double lo, double hi);

// Each check below reports what is wrong and returns false.
// (run_checks.cpp)
bool run_options_usable(const RunOptions &o);
bool world_options_usable(const RunOptions &o, const std::string &port);
bool native_options_usable(const RunOptions &o);

// The world file of --world (run_world.cpp).
bool world_file_usable(const RunOptions &o);
std::string world_duration(const std::string &path);
std::string world_fidelity(const std::string &path); // "exact", "native" or "qemu"
bool keep_world_beside_run(const std::string &world_path, const std::string &out);

}  // namespace openswarm
