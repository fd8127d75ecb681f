#include "footprint.hpp"

#include <map>

#include "generate.hpp"
#include "ports.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

unsigned value_or(const std::map<std::string, unsigned> &values, const std::string &macro,
                  unsigned port_default) {
    auto it = values.find(macro);
    return it == values.end() ? port_default : it->second;
}

unsigned round_up(unsigned n, unsigned block) { return (n + block - 1) / block * block; }

// The gap between what the build reserves and equation (1), item by item;
// the last item is the rest, so the items always add up to the gap.
void explain_gap(Footprint &f) {
    const Equation &e = f.equation;
    long gap = (long)f.reserved() - (long)e.total();
    unsigned slots = f.max_threads - 1; // the system thread has the first
    if (e.n <= slots)
        f.beyond.push_back({std::to_string(slots - e.n) +
                                (slots - e.n == 1 ? " spare thread slot" : " spare thread slots") +
                                " (max_threads " + std::to_string(f.max_threads) +
                                ": the system thread, " + std::to_string(e.n) + " listed, " +
                                std::to_string(slots - e.n) + " spare)",
                            (long)((slots - e.n) * e.per_thread)});
    else
        f.warnings.push_back(
            std::to_string(e.n) + " threads are listed but the kernel has slots for " +
            std::to_string(slots) + ": raise \"kernel\": {\"max_threads\"} in openswarm.json");
    f.beyond.push_back({"stack pool no listed thread takes (spare, or threads the code starts)",
                        (long)f.pool - (long)e.stacks});
    f.beyond.push_back({"event data of the kernel's and port's own events, and spare",
                        (long)f.event_data - (long)e.data});
    long explained = 0;
    for (const auto &b : f.beyond) explained += b.bytes;
    f.beyond.push_back(
        {"the rest: the kernel and port beyond C's minimal configuration (more event\n"
         "slots and subscriptions, a longer queue, the devices' table and state)",
         gap - explained});
}

void check_pools(Footprint &f) {
    if (f.pool < f.listed_stacks())
        f.warnings.push_back(
            "the stack pool (" + std::to_string(f.pool) + " bytes) is " +
            std::to_string(f.listed_stacks() - f.pool) +
            " bytes short of the listed threads' stacks: one will not start; raise "
            "\"kernel\": {\"stack_pool\"} in openswarm.json");
    unsigned data = f.listed_data() + f.port_event_bytes;
    if (f.event_data < data)
        f.warnings.push_back("the event data pool (" + std::to_string(f.event_data) +
                             " bytes) is " + std::to_string(data - f.event_data) +
                             " bytes short of the events' data: an event will not register; raise "
                             "\"kernel\": {\"event_data\"} in openswarm.json");
}

}  // namespace

unsigned Footprint::listed_stacks() const {
    unsigned total = 0;
    for (const auto &t : threads) total += t.carved;
    return total;
}

unsigned Footprint::listed_data() const {
    long total = 0;
    for (const auto &e : events) total += e.bytes;
    return (unsigned)total;
}

Footprint footprint_of(const AppConfig &config, const Attribution &a,
                       const fs::path &generated_config) {
    const PortInfo &port = port_info(config.port);
    const PortCosts &costs = costs_of(config.port);
    auto values = generated_config_values(generated_config);
    Footprint f{};
    f.stack_extra = costs.stack_extra;
    f.stack_guard = value_or(values, "OS_CFG_STACK_CHECK", 1) ? stack_guard_bytes : 0;
    f.stack_block = value_or(values, "OS_CFG_STACK_BLOCK_BYTES", port.stack_block);
    f.max_threads = value_or(values, "OS_CFG_MAX_THREADS", port.default_max_threads);
    unsigned default_stack = value_or(values, "OS_CFG_DEFAULT_STACK_BYTES", port.default_stack);
    // os_stack_alloc (kernel/src/stack_pool.c): whole blocks for the bytes
    // asked, the port's extra and the guard; 0 asks for the default.
    auto carve = [&](const std::string &name, unsigned asked) {
        unsigned requested = asked ? asked : default_stack;
        f.threads.push_back(
            {name, requested, round_up(requested + f.stack_extra + f.stack_guard, f.stack_block)});
    };
    for (const auto &t : config.threads) carve(t.entry, t.stack);
    for (const auto &e : config.events) f.events.push_back({e.name, (long)e.size});
    // The libraries' threads are in the image when the object file that
    // starts them is linked: the link map knows better than the sources.
    for (const auto &library : port.libraries)
        for (const auto &t : library.threads)
            if (a.kernel_objects.count(t.object)) carve(t.name, t.stack);
    f.port_events = port.device_events;
    f.port_event_bytes = port.device_event_bytes;
    // A classic program of a library registers what the library's pools
    // hold (kilolib's: no clock event, no sensors).
    const bool classic = config.threads.empty() && config.events.empty() && config.devices.empty();
    for (const auto &library : port.libraries) {
        auto data = library.classic_pools.find("event_data");
        if (classic && data != library.classic_pools.end() && a.kernel_objects.count(library.object))
            f.port_event_bytes = (unsigned)data->second;
    }
    f.pool = a.ram_of(owner::stacks);
    f.event_data = a.ram_of(owner::event_data);
    f.queue = a.ram_of(owner::event_queue);
    f.kernel = a.ram_of(owner::kernel);
    f.equation = Equation{costs.fixed, costs.per_thread, costs.per_event, (unsigned)f.threads.size(),
                          (unsigned)f.events.size(), f.listed_data(), f.listed_stacks()};
    explain_gap(f);
    check_pools(f);
    return f;
}

}  // namespace openswarm
