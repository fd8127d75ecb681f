// Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: runs the simulator, which links libsimavr.
// world.json, any text the world reader accepts, run by openswarm-sim with
// a fixed firmware for at most 50 ms of simulated time, its outputs
// written: the simulator ends (no crash, no hang, no sanitizer report),
// refuses with a message, or runs the known-good firmware without a crash;
// and no robot or object has left the arena (a physics blow-up: a body
// through a wall, a position not a number).
#include <cmath>
#include <fstream>
#include <sstream>

#include "fuzz_run_parts.hpp"
#include "world/world_spec.h"

// Bounds that keep one input to milliseconds: up to 8 robots for up to
// 50 ms each (a few hundred ms under the sanitizers at worst).
static constexpr int MAX_ROBOTS = 8;
static constexpr double MAX_SECONDS = 0.05;

// Every x_mm, y_mm column of an output CSV lies in the arena.
static void check_inside(const std::filesystem::path &csv, double width, double height, const SimulatorRun &run) {
    std::ifstream in(csv);
    std::string line;
    if (!std::getline(in, line)) return; // not written: no such things
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::string time, index, x, y;
        std::getline(fields, time, ',');
        std::getline(fields, index, ',');
        std::getline(fields, x, ',');
        std::getline(fields, y, ',');
        double px = std::strtod(x.c_str(), nullptr), py = std::strtod(y.c_str(), nullptr);
        if (!(px >= 0 && px <= width && py >= 0 && py <= height))
            simulator_finding("wrote a position outside the " + seconds_text(width) + " x " +
                                  seconds_text(height) + " mm arena in " + csv.filename().string() + ": " + line,
                              run);
    }
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    const std::string &firmware = fixed_firmware();
    auto path = write_input("world.json", data, size);
    world_spec w{};
    if (world_spec_load(path.c_str(), &w) != 0) return -1; // the reader's refusals: fuzz_world_file
    bool runnable = w.robot_kind == WORLD_ROBOT_KILOBOT && w.fidelity == WORLD_FIDELITY_EXACT &&
                    w.n_robots <= MAX_ROBOTS;
    double seconds = w.duration_s > 0 && w.duration_s < MAX_SECONDS ? w.duration_s : MAX_SECONDS;
    double width = w.width_mm, height = w.height_mm;
    world_spec_free(&w);
    if (!runnable) return -1; // e-pucks need controllers, native mode a host build
    auto out = fuzz_dir() / "out";
    std::filesystem::remove_all(out);
    SimulatorRun run = run_simulator({"--world", path.string(), "--time", seconds_text(seconds), "--out",
                                      out.string(), "--quiet", "--allow-faults", firmware});
    check_refusal_told(run);
    if (run.status != 0 && run.status != 2)
        simulator_finding("ended the known-good firmware's run with status " + std::to_string(run.status), run);
    if (run.status == 0) {
        check_inside(out / "trajectories.csv", width, height, run);
        check_inside(out / "objects.csv", width, height, run);
    }
    return 0;
}
