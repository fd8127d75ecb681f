#include "app_limits.hpp"

#include <map>

#include "json_checks.hpp"
#include "names.hpp"

namespace openswarm {

namespace {

// The most threads and events config.h accepts (pids keep a slot in 4
// bits; event ids are 8 bits, 255 itself marks "none").
constexpr size_t max_threads = 16, max_events = 255;

std::string at(const std::string &list, size_t i, const std::string &key) {
    return list + "[" + std::to_string(i) + "]." + key;
}

void refuse_if(const AppConfig &c, const std::string &path, const std::string &name, const char *what,
               const std::string &why) {
    if (!why.empty())
        fail(c.file, path, "\"" + name + "\" cannot name " + what + ": " + why + "; choose another name");
}

// An event is a macro EV_<NAME> and, in C++, openswarm::events::<name>.
void check_event_names(const AppConfig &c) {
    for (size_t i = 0; i < c.events.size(); i++)
        refuse_if(c, at("events", i, "name"), c.events[i].name, "an event", reserved_identifier(c.events[i].name));
}

// Each entry is a function of the app's and start_<entry> a static of the
// generated start-up code, next to <device>_params and <device>_points.
void check_thread_names(const AppConfig &c) {
    std::map<std::string, std::string> generated;
    for (size_t i = 0; i < c.threads.size(); i++)
        generated["start_" + c.threads[i].entry] = "thread " + c.threads[i].entry + "'s start-up";
    for (const auto &d : c.devices) {
        generated[d.device + "_params"] = "the " + d.device + " device's parameters";
        generated[d.device + "_points"] = "the " + d.device + " device's table";
    }
    for (size_t i = 0; i < c.threads.size(); i++) {
        const std::string &entry = c.threads[i].entry;
        refuse_if(c, at("threads", i, "entry"), entry, "a thread's entry function", taken_identifier(entry));
        auto clash = generated.find(entry);
        if (clash != generated.end())
            fail(c.file, at("threads", i, "entry"), "\"" + entry + "\" is the generated code's name for " +
                 clash->second + "; choose another name");
    }
}

void check_counts(const AppConfig &c, const PortInfo &port, const Libraries &libraries) {
    size_t library_threads = 0;
    for (const PortLibrary *library : libraries) library_threads += library->threads.size();
    if (c.threads.size() + library_threads + 1 > max_threads)
        fail(c.file, "threads", std::to_string(c.threads.size()) + " threads" +
             (library_threads ? " (and " + std::to_string(library_threads) + " the app's libraries start)" : "") +
             " and the system thread are more than the kernel's " + std::to_string(max_threads) +
             "; join some threads' work, or turn some into event handlers");
    if (port.device_events + c.events.size() > max_events)
        fail(c.file, "events", std::to_string(c.events.size()) + " events and the " + port.name + "'s " +
             std::to_string(port.device_events) + " are more than the kernel's " + std::to_string(max_events) +
             "; at most " + std::to_string(max_events - port.device_events) + " events (one event with data "
             "telling its cases apart can replace several)");
}

}  // namespace

void check_stack_pool_blocks(const AppConfig &c, const PortInfo &port) {
    auto pool = c.kernel.find("stack_pool");
    if (pool != c.kernel.end() && pool->second % port.stack_block != 0)
        fail(c.file, "kernel.stack_pool", std::to_string(pool->second) + " is not a multiple of the " + port.name +
             "'s " + std::to_string(port.stack_block) + "-byte stack blocks; give " +
             std::to_string((pool->second / port.stack_block + 1) * port.stack_block) +
             ", or leave it out and the build sizes it");
}

void check_app_limits(const AppConfig &config, const PortInfo &port, const Libraries &libraries) {
    check_event_names(config);
    check_thread_names(config);
    check_counts(config, port, libraries);
}

// A pool as the build sizes it: the generated value, else the port's.
static unsigned pool_of(const std::map<std::string, long> &pools, const PortInfo &port, const PortCosts &costs,
                 const std::string &key) {
    auto given = pools.find(key);
    if (given != pools.end()) return (unsigned)given->second;
    if (key == "max_threads") return port.default_max_threads;
    if (key == "max_events") return port.default_max_events;
    if (key == "event_data") return port.device_event_bytes;
    if (costs.default_stack_pool) return costs.default_stack_pool; // stack_pool
    unsigned block = port.stack_block, stack = (port.default_stack + stack_guard_bytes + block - 1) / block * block;
    return (pool_of(pools, port, costs, "max_threads") - 1) * stack;
}

// Equation (1) of docs/benchmarks.md for the pools the build generates,
// the port's devices and the main stack's minimum (the app's own
// variables come on top): past the RAM, the link fails or the main stack
// has no room and the robot crashes.
void check_declared_ram(const AppConfig &c, const PortInfo &port, const std::map<std::string, long> &pools) {
    const PortCosts *costs = costs_for(port.name);
    if (costs == nullptr || port.ram_bytes == 0) return;
    auto pool = [&](const char *key) { return pool_of(pools, port, *costs, key); };
    unsigned threads = pool("max_threads") - 1, events = pool("max_events");
    unsigned stacks = pool("stack_pool") + threads * costs->stack_extra;
    unsigned kernel = costs->fixed + costs->per_thread * threads + costs->per_event * (events > 6 ? events - 6 : 0) +
                      costs->devices;
    unsigned needed = kernel + stacks + pool("event_data") + port.main_stack_minimum;
    if (needed <= port.ram_bytes) return;
    std::string sum = "the stacks (" + std::to_string(stacks) + " bytes with the kernel's " +
                      std::to_string(costs->stack_extra) + " per thread), the kernel and the devices (" +
                      std::to_string(kernel) + "), the events' data (" + std::to_string(pool("event_data")) +
                      ") and the main stack's minimum (" + std::to_string(port.main_stack_minimum) + ") need about " +
                      std::to_string(needed) + " bytes, more than the " + port.name + "'s " +
                      std::to_string(port.ram_bytes) + " of RAM, by " + std::to_string(needed - port.ram_bytes);
    // Blame what holds the most: the events' data, or the stacks.
    if (!c.events.empty() && pool("event_data") >= stacks) {
        size_t biggest = 0;
        for (size_t i = 0; i < c.events.size(); i++)
            if (c.events[i].size > c.events[biggest].size) biggest = i;
        const std::string where = "events[" + std::to_string(biggest) + "]";
        fail(c.file, c.events[biggest].type.empty() ? where + ".size" : where,
             sum + "; the kernel keeps every event's last data: make the biggest events' data smaller (this one's " +
                 std::to_string(c.events[biggest].size) + " bytes), or use fewer events" +
                 (c.threads.empty() && stacks > 0
                      ? "; with no threads, \"kernel\": {\"max_threads\": 1, \"stack_pool\": 0} frees the stacks' " +
                            std::to_string(stacks) + " bytes"
                      : ""));
    }
    size_t biggest = 0;
    for (size_t i = 0; i < c.threads.size(); i++)
        if (c.threads[i].stack > c.threads[biggest].stack) biggest = i;
    fail(c.file, c.threads.empty() ? "kernel" : at("threads", biggest, "stack"),
         sum + "; make the biggest stacks smaller, or use fewer threads" +
             (c.threads.empty() ? " (\"kernel\": {\"max_threads\", \"stack_pool\"} in openswarm.json)" : ""));
}

}  // namespace openswarm
