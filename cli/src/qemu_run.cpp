#include "qemu_run.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "commands/commands.hpp"
#include "kernel_losses.h"
#include "paths.hpp"
#include "process.hpp"

namespace openswarm {

// -icount: every instruction takes 8 ns of virtual time (a 125 MIPS CPU),
// whatever the host is doing, so a run is the same run every time; sleep=off
// lets idle time (WFI) pass at once.
static const char *const QEMU_CLOCK = "shift=3,align=off,sleep=off";

std::vector<std::string> qemu_command(const QemuRun &r) {
    long stop_ms = std::lround(r.seconds * 1000.0);
    std::vector<std::string> argv = {
        "qemu-system-arm", "-M", "netduinoplus2", "-display", "none", "-monitor", "none",
        "-serial", "stdio", "-semihosting-config",
        "enable=on,target=native,arg=" + r.image.filename().string() +
            ",arg=--stop-ms=" + std::to_string(stop_ms),
        "-icount", QEMU_CLOCK, "-kernel", r.image.string()};
    if (r.gdb_port != 0)
        argv.insert(argv.end(), {"-gdb", "tcp::" + std::to_string(r.gdb_port), "-S"});
    return argv;
}

static bool decode_record(const std::string &line, QemuRecord &record);

std::string shown_line(const std::string &line) {
    QemuRecord record;
    if (!decode_record(line, record)) return line;
    char text[96];
    int n = std::snprintf(text, sizeof text, "[%11.6f s] ", record.t);
    if (record.name == "led" && record.values.size() == 3) {
        std::snprintf(text + n, sizeof text - (size_t)n, "led    red %d green %d blue %d",
                      record.values[0], record.values[1], record.values[2]);
        return text;
    }
    std::string shown = text + record.name;
    for (int v : record.values) shown += " " + std::to_string(v);
    return shown;
}

// A firmware that hangs with interrupts masked never reaches its end:
// QEMU runs a busy image at about real time or faster on one core, so 20x
// the simulated time (and 10 s for QEMU to start on a loaded machine) is
// far past any honest run.
static double wall_clock_limit(const QemuRun &r) {
    return r.gdb_port != 0 ? 0 : 10.0 + 20.0 * r.seconds;
}

static bool decode_record(const std::string &line, QemuRecord &record) {
    if (line.empty() || line[0] != '\x1e') return false;
    std::istringstream fields(line.substr(1));
    unsigned long us = 0;
    if (!(fields >> record.name >> us)) return false;
    record.t = us / 1e6;
    for (int v; fields >> v;) record.values.push_back(v);
    return true;
}

// The kernel's counters (sys_stats, in order) as warnings with the fix,
// an e-puck's.
static std::vector<std::string> loss_warnings(const std::vector<int> &counters) {
    std::vector<std::string> warnings;
    for (const kernel_loss &l : kernel_losses) {
        if (l.index >= counters.size() || counters[l.index] <= 0) continue;
        warnings.push_back(std::to_string(counters[l.index]) + " " + l.what + l.what_on[KERNEL_LOSS_EPUCK] +
                           "; " + l.fix + l.fix_on[KERNEL_LOSS_EPUCK]);
    }
    return warnings;
}

QemuOutcome run_qemu(const QemuRun &r, const std::function<void(const std::string &)> &on_line) {
    QemuOutcome outcome{0, 0, false, false, {}, {}, {}};
    auto started = std::chrono::steady_clock::now();
    outcome.status = run_program_lines(
        qemu_command(r),
        [&](const std::string &line) {
            if (line.rfind("kernel fault:", 0) == 0 || line.rfind("CPU fault:", 0) == 0)
                outcome.fault_reported = true;
            QemuRecord record;
            if (decode_record(line, record)) {
                if (record.name == "stop") {
                    outcome.reached_end = true;
                    return; // not something the robot did
                }
                if (record.name == "losses") {
                    outcome.warnings = loss_warnings(record.values);
                    return; // said at the end, as warnings
                }
                outcome.records.push_back(record);
            } else {
                outcome.console.push_back(line);
            }
            on_line(shown_line(line));
        },
        wall_clock_limit(r));
    outcome.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return outcome;
}

std::string qemu_failure(const QemuRun &r, const QemuOutcome &outcome) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", r.seconds);
    if (outcome.status == 124)
        return std::string("the firmware did not reach ") + seconds + " s of simulated time within " +
               std::to_string((int)wall_clock_limit(r)) +
               " s: it hangs with interrupts masked, or never starts the kernel's tick "
               "(Sys_Start_Kernel); `openswarm run --gdb 1234` lets you look";
    if (outcome.status == 3)
        return "the firmware stopped on a CPU fault (above): arm-none-eabi-addr2line -e " +
               r.image.string() + " <pc> names the line";
    if (outcome.status != 0)
        return "the firmware ended with status " + std::to_string(outcome.status) +
               " (main returned it, or QEMU could not run the image)";
    if (outcome.fault_reported) return "the firmware reported a fault (above)";
    if (!outcome.reached_end)
        return std::string("the run ended before ") + seconds +
               " s of simulated time: main returned 0 (a firmware should not return), or the "
               "debugger ended it";
    if (r.strict && !outcome.warnings.empty())
        return "the run ended with warnings (above: each with its fix), and --strict makes them errors";
    return "";
}

void show_warnings(const QemuOutcome &outcome) {
    for (const auto &warning : outcome.warnings) std::fprintf(stderr, "openswarm: warning: %s\n", warning.c_str());
}

int run_in_qemu(const QemuRun &r) {
    if (!find_program("qemu-system-arm")) {
        report("qemu-system-arm was not found, and running e-puck2 images needs it: sudo apt-get "
               "install qemu-system-arm (or run OpenSwarm's ./setup.sh)");
        return EXIT_FAILED;
    }
    if (r.gdb_port != 0)
        std::printf("QEMU waits for the debugger: in another terminal,\n"
                    "    gdb-multiarch %s -ex 'target remote :%d'\n",
                    r.image.string().c_str(), r.gdb_port);
    QemuOutcome outcome = run_qemu(r, [](const std::string &line) {
        std::printf("%s\n", line.c_str());
        std::fflush(stdout);
    });
    show_warnings(outcome);
    if (outcome.status == 0 && outcome.reached_end)
        std::printf("openswarm: ran %.3f s of simulated time in QEMU in %.1f s, %.1fx real time\n",
                    r.seconds, outcome.wall_seconds,
                    outcome.wall_seconds > 0 ? r.seconds / outcome.wall_seconds : 0.0);
    std::string failure = qemu_failure(r, outcome);
    if (failure.empty()) return EXIT_OK;
    report(failure);
    return EXIT_FAILED;
}

}  // namespace openswarm
