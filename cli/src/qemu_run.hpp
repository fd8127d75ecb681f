// Running an e-puck2 image in QEMU (netduinoplus2): the board's console
// on our standard output, its records (board_record.h) shown as trace
// lines, the run ended by the board itself after the simulated time.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace openswarm {

struct QemuRun {
    std::filesystem::path image;
    double seconds = 10;
    int gdb_port = 0; // 0: no debugger; else QEMU waits for gdb-multiarch there
    bool strict = false; // the warnings at the end fail the run
};

// The command that runs it (for the user to see and for tests).
std::vector<std::string> qemu_command(const QemuRun &r);

// A record line of the board ("\x1e" "led 252004 0 3 0") as a trace line
// like a simulated Kilobot's ("[  0.252004 s] led    red 0 green 3 blue 0");
// other lines as they are.
std::string shown_line(const std::string &line);

// A record of the board's, decoded: "led" at t seconds with r, g, b.
struct QemuRecord {
    double t;
    std::string name;
    std::vector<int> values;
};

struct QemuOutcome {
    int status;          // QEMU's exit status: the firmware's; 124: killed, it hung
    double wall_seconds; // how long it took
    bool fault_reported; // a "kernel fault:" or "CPU fault:" line on the console
    bool reached_end;    // the board's "stop" record: the run lasted its time
    std::vector<QemuRecord> records;
    std::vector<std::string> console; // the lines that were not records
    // What the kernel lost or was refused (the board's "losses" record at
    // the end), each with its fix, as openswarm-sim warns of a Kilobot's.
    std::vector<std::string> warnings;
};

// Runs it, each console line (records shown as trace lines) to on_line.
QemuOutcome run_qemu(const QemuRun &r, const std::function<void(const std::string &)> &on_line);

// Why the run failed, for a person (empty if it did not): a hang, a
// fault, a status; warnings with r.strict.
std::string qemu_failure(const QemuRun &r, const QemuOutcome &outcome);

// The outcome's warnings on standard error ("openswarm: warning: ...").
void show_warnings(const QemuOutcome &outcome);

// Runs it with its console on our standard output and reports how it
// ended; the tool's exit code.
int run_in_qemu(const QemuRun &r);

}  // namespace openswarm
