// Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: runs the simulator, which links libsimavr.
// What the fuzzers that run the simulator share: the fixed firmware they
// run, beside the inputs, and the checks every run's end must pass.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

#include "fuzz_input_file.hpp"
#include "simulator_child.hpp"

// A known-good program (the disperse template: it moves, sends and
// receives), copied once into this process's folder as robot.elf, where a
// world file can name it; FIXED_FIRMWARE is its path in the tree
// (sim/fuzz/CMakeLists.txt).
inline const std::string &fixed_firmware() {
    static const std::string path = [] {
        std::filesystem::path copy = fuzz_dir() / "robot.elf";
        std::filesystem::copy_file(FIXED_FIRMWARE, copy, std::filesystem::copy_options::overwrite_existing);
        return copy.string();
    }();
    return path;
}

inline std::string seconds_text(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", s);
    return text;
}

// openswarm-sim's exit status 2 is bad input: it must have said why, in
// a line of its own naming itself.
inline void check_refusal_told(const SimulatorRun &run) {
    if (run.status == 2 && run.output.find("openswarm-sim: ") == std::string::npos)
        simulator_finding("refused the input (exit 2) without a message", run);
}
