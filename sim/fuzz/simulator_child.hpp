// Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: runs the simulator, which links libsimavr.
// One run of openswarm-sim's own main, in a child process, for a fuzzer.
//
// Why a child: the simulator keeps its state in file-scope globals (the
// robots, the channel, the fault plan, the world, getopt's) and frees
// little at exit, as a program may. Resetting it all between inputs would
// touch every room of sim/src for the fuzzer's sake, and whatever a reset
// missed would leak one input's state into the next: findings that do not
// reproduce. A fork gives each input a fresh simulator for about a
// millisecond, and the child hands its coverage counters back to the
// parent (count_child_coverage), so libFuzzer is still guided by what the
// simulator ran. (Its edges in simavr itself are not counted: libsimavr is
// Debian's, uninstrumented.)
#pragma once

#include <string>
#include <vector>

struct SimulatorRun {
    int status;         // what openswarm-sim's main returned
    std::string output; // what it printed, standard output and error
};

// Run `openswarm-sim ARGS...` in a child process and wait for it. A
// crash (a signal, a sanitizer's report, exit() from inside the run) or
// no end within the wall-time limit is a finding: its output is printed
// and the fuzzer aborts, which keeps the input.
SimulatorRun run_simulator(const std::vector<std::string> &args);

// A finding the fuzzer keeps: what failed, the run's output, abort().
[[noreturn]] void simulator_finding(const std::string &what, const SimulatorRun &run);
