// Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: runs the simulator, which links libsimavr.
// A fault plan, any text given to --faults, on three robots of a fixed
// firmware in IR range of each other for 50 ms of simulated time (resets,
// brown-outs, bit flips and cuts, blank calibrations, drifted clocks as
// the text asks): the simulator refuses the plan with a message or runs
// it, its fault log written, and never crashes or hangs; the known-good
// firmware ends the run with status 0 (faults are allowed).
#include "fuzz_run_parts.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    std::string plan(reinterpret_cast<const char *>(data), size);
    if (plan.find('\0') != std::string::npos) return -1; // a command line holds no NUL
    const std::string &firmware = fixed_firmware();
    auto log = fuzz_dir() / "faults.log";
    SimulatorRun run = run_simulator({"--robots", "3", "--distance", "40", "--time", "0.05", "--quiet",
                                      "--allow-faults", "--faults", plan, "--fault-log", log.string(), firmware});
    check_refusal_told(run);
    if (run.status != 0 && run.status != 2)
        simulator_finding("ended the known-good firmware's run with status " + std::to_string(run.status), run);
    return 0;
}
