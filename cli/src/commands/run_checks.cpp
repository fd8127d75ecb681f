// openswarm run: the options' mistakes caught before the build, as bad usage.
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "commands.hpp"
#include "run_options.hpp"
#include "../suggest.hpp"

namespace openswarm {

std::optional<double> number_in(std::string text, char suffix, double lo, double hi) {
    if (!text.empty() && text.back() == suffix) text.pop_back();
    char *end = nullptr;
    double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi) return std::nullopt;
    return v;
}

// The options whose mistakes the simulator would catch only after the
// build: caught before it, as bad usage. False after reporting.
bool run_options_usable(const RunOptions &o) {
    auto time = number_in(o.time, 's', 0, 86400);
    if (!time || *time <= 0) {
        report("--time " + o.time + ": give the simulated time in seconds, more than 0 and at most "
               "86400 (e.g. 10 or 2.5s)");
        return false;
    }
    if (!o.clock_spread.empty() && !number_in(o.clock_spread, '%', 0, 5)) {
        report("--clock-spread " + o.clock_spread + ": give a percentage from 0 to 5 (e.g. 1)");
        return false;
    }
    if (!o.ir_loss.empty() && !number_in(o.ir_loss, '%', 0, 100)) {
        report("--ir-loss " + o.ir_loss + ": give a percentage from 0 to 100 (e.g. 20)");
        return false;
    }
    for (const auto &m : o.ohc) {
        auto at = m.rfind('@');
        if (at == std::string::npos || at == 0 || !number_in(m.substr(at + 1), 's', 0, 86400)) {
            report("--ohc " + m + ": give MESSAGE@SECONDS, e.g. --ohc sleep@2 or "
                   "--ohc calib-left:70@1");
            return false;
        }
    }
    return true;
}

// A port whose robots live in a world (epuck_world): a world file places
// them; the Kilobot simulator's own options do not apply. False after
// reporting.
bool world_options_usable(const RunOptions &o, const std::string &port) {
    if (o.world.empty()) {
        report("the " + port + " port's robots run in a world: give --world FILE, a world.json with "
               "\"robot\": \"epuck\" (docs/world.md; the object-clustering template's experiment "
               "makes them)");
        return false;
    }
    // The options of a world's outputs, which any robot's world writes.
    static const std::vector<std::string> world_outputs = {"--world", "--out", "--video", "--video-fps",
                                                           "--video-speed", "--ids", "--trace"};
    std::vector<std::string> refused;
    for (const auto &name : o.simavr_only)
        if (std::find(world_outputs.begin(), world_outputs.end(), name) == world_outputs.end())
            refused.push_back(name);
    if (refused.empty()) return true;
    report(join(refused) + ": not for the " + port + " port, whose robots the world file places; "
           "those are for Kilobot apps (--port kilobot)");
    return false;
}

// The options that look inside the simulated MCU, which the native mode
// does not simulate. False after reporting.
bool native_options_usable(const RunOptions &o) {
    std::vector<std::string> refused;
    if (o.gdb != 0) refused.push_back("--gdb");
    if (o.debug) refused.push_back("--debug");
    if (!o.vcd.empty()) refused.push_back("--vcd");
    if (o.profile) refused.push_back("--profile");
    if (o.ir_log) refused.push_back("--ir-log");
    if (!o.first.empty()) refused.push_back("--first");
    if (o.trace) refused.push_back("--trace");
    if (refused.empty()) return true;
    report(join(refused) + ": the native mode runs the app on the host, with no simulated MCU to look "
           "into; run it in the exact mode (without --native, or \"fidelity\": \"exact\")");
    return false;
}

}  // namespace openswarm
