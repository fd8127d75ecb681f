// The kernel's RAM for one app, thread by thread and event by event, and
// the OpenSwarm paper's equation (1) evaluated for it (`openswarm size`).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app_config.hpp"
#include "attribution.hpp"

namespace openswarm {

struct Bytes {
    std::string what;
    long bytes;
};

struct ThreadStack {
    std::string name;
    unsigned requested, carved; // carved: what the stack pool really gives it
};

// Equation (1) in the paper's form: RAM = C + per_thread n + per_event m
// + sum d_i + sum stacks, with C and the per-item costs measured.
struct Equation {
    unsigned fixed, per_thread, per_event;
    unsigned n, m, data, stacks;
    unsigned total() const { return fixed + per_thread * n + per_event * m + data + stacks; }
};

struct Footprint {
    unsigned stack_extra, stack_guard, stack_block; // the carving rule's terms
    std::vector<ThreadStack> threads; // openswarm.json's, then those the port's libraries start
    std::vector<Bytes> events;        // each of openswarm.json's events' data (d_i)
    unsigned port_events, port_event_bytes;   // the kernel's and the port's own events
    unsigned pool, event_data, queue, kernel; // what the build reserves (from the attribution)
    unsigned max_threads;
    Equation equation;
    std::vector<Bytes> beyond; // what the build reserves beyond equation (1), summing to the gap
    std::vector<std::string> warnings; // a pool too small for what is listed
    unsigned reserved() const { return kernel + pool + event_data + queue; }
    unsigned listed_stacks() const;
    unsigned listed_data() const;
};

// The footprint of the app config describes, built for config.port with
// the generated pool sizes in generated_config, as attributed in a.
Footprint footprint_of(const AppConfig &config, const Attribution &a,
                       const std::filesystem::path &generated_config);

}  // namespace openswarm
