#include "epuck2_programmer.hpp"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <vector>

#include <poll.h>
#include <unistd.h>

#include "commands/commands.hpp"
#include "paths.hpp"
#include "process.hpp"
#include "regular_file.hpp"
#include "serial_port.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

// The symbol of the image's vector table (ports/cortex_m4): its first two
// words are the stack pointer and the reset handler, which the detached
// CPU starts from, as after a reset, wherever the image is linked.
const char *const VECTORS = "stm32f407_vectors";

// A GDB server answers at once; a loaded machine may take a while to run it.
constexpr double GDB_ANSWER_SECONDS = 5;

// What gdb's output says went wrong; "" when every step went through.
std::string gdb_failure(const std::vector<std::string> &lines, const std::string &device) {
    auto said = [&](const char *text) {
        for (const auto &l : lines)
            if (l.find(text) != std::string::npos) return true;
        return false;
    };
    if (said("Ignoring packet error") || said("Remote communication error") || said("Timed out") ||
        said("Remote replied unexpectedly") || said("Remote connection closed"))
        return "no GDB server answered on " + device +
               ": give the programmer's GDB port (the first of the two the e-puck2 shows, "
               "e.g. /dev/ttyACM0), check that the robot is plugged in, then retry";
    if (said("SW-DP scan failed") || said("No usable targets") || said("Don't know how to attach") ||
        said("Attaching to Remote target failed"))
        return "the programmer on " + device +
               " found no microcontroller on its SWD lines: switch the e-puck2 on (the programmer "
               "alone answers on USB power), then retry";
    if (said(std::string("No symbol \"").append(VECTORS).c_str()))
        return std::string("the image has no ") + VECTORS +
               ": give an e-puck2 image `openswarm build --port epuck2` made";
    if (said("MIS-MATCHED")) return "the flash read back differs from the image: upload again; if it "
                                    "persists, the flash may be write-protected";
    if (!said("Transfer rate")) return "loading the image failed (gdb's words are above); fix what they "
                                       "name, then retry";
    if (!said("detached")) return "the robot was not started (gdb's words are above); retry";
    return "";
}

// Asks the server on port why the target stopped ("?", which changes
// nothing) and reads its whole reply, so gdb finds the line quiet: gdb
// itself retries a silent port for ever.
bool gdb_server_answers(SerialPort &port, double seconds) {
    static const char query[] = "$?#3f";
    port.write_all((const uint8_t *)query, sizeof query - 1, seconds);
    std::string reply;
    auto started = std::chrono::steady_clock::now();
    while (std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() < seconds) {
        pollfd p{port.fd(), POLLIN, 0};
        if (::poll(&p, 1, 50) <= 0) continue;
        char buffer[256];
        ssize_t n = ::read(port.fd(), buffer, sizeof buffer);
        if (n > 0) reply.append(buffer, (size_t)n);
        size_t start = reply.find('$'), end = reply.find('#', start == std::string::npos ? 0 : start);
        if (start != std::string::npos && end != std::string::npos && reply.size() >= end + 3) {
            port.write_all((const uint8_t *)"+", 1, seconds); // acknowledged: the server sends it once
            return true;
        }
    }
    return false;
}

}  // namespace

std::string epuck2_gdb_script(const std::string &device) {
    return "set confirm off\n"
           "set remotetimeout 5\n"
           "target extended-remote " + device + "\n"
           // A Black Magic Probe connects to nothing until told; QEMU has a thread.
           "if $_thread == 0\n"
           "  monitor swdp_scan\n"
           "  attach 1\n"
           "end\n"
           "load\n"
           // -r: .data's bytes in flash are the CPU's to copy; a started image changes RAM
           "compare-sections -r\n"
           "set $sp = *(unsigned int *)&" + std::string(VECTORS) + "\n"
           "set $pc = *(unsigned int *)((char *)&" + VECTORS + " + 4)\n"
           "detach\n";
}

int program_epuck2(const fs::path &elf, const std::string &device, double timeout_seconds) {
    std::string what = not_a_regular_file(elf);
    if (!what.empty() || !fs::exists(elf)) {
        report(elf.string() + (what.empty() ? " does not exist" : " is " + what) +
               "; give the e-puck2 image `openswarm build --port epuck2` made (build/epuck2/APP-robot.elf)");
        return EXIT_USAGE;
    }
    if (!find_program("gdb-multiarch")) {
        report("gdb-multiarch is not installed; it talks to the e-puck2's programmer: sudo apt-get install "
               "gdb-multiarch (or run OpenSwarm's ./setup.sh), then retry");
        return EXIT_USAGE;
    }
    {
        SerialPort port(device, 115200); // its errors name the port; gdb's would not
        if (!gdb_server_answers(port, GDB_ANSWER_SECONDS)) {
            report("no GDB server answered on " + device + " within " + std::to_string((int)GDB_ANSWER_SECONDS) +
                   " s: give the programmer's GDB port (the first of the two the e-puck2 shows, e.g. "
                   "/dev/ttyACM0), check that the robot is plugged in, then retry");
            return EXIT_FAILED;
        }
    }
    char script_name[] = "/tmp/openswarm-upload-XXXXXX";
    int fd = ::mkstemp(script_name);
    if (fd < 0) {
        report("cannot write a gdb script in /tmp; check that it is writable, then retry");
        return EXIT_FAILED;
    }
    ::close(fd);
    std::ofstream(script_name) << epuck2_gdb_script(device);
    std::printf("Uploading %s through the GDB server on %s\n", elf.string().c_str(), device.c_str());
    std::fflush(stdout);
    std::vector<std::string> lines;
    int status = run_program_lines({"gdb-multiarch", "-nx", "-batch", "-x", script_name, elf.string()},
                                   [&](const std::string &line) {
                                       lines.push_back(line);
                                       std::printf("  %s\n", line.c_str());
                                       std::fflush(stdout);
                                   },
                                   timeout_seconds, true);
    ::unlink(script_name);
    // gdb retries a silent port for ever: what it said before it was
    // stopped tells a port without a server from a slow upload.
    std::string why = gdb_failure(lines, device);
    if (status == 124 && (why.empty() || why.rfind("loading", 0) == 0))
        why = "gdb-multiarch took more than " + std::to_string((int)timeout_seconds) +
              " s and was stopped while loading through " + device + "; give a longer --timeout";
    if (!why.empty()) {
        report(why);
        return EXIT_FAILED;
    }
    std::printf("Uploaded and checked (compare-sections); the robot runs it from its reset vector\n");
    return EXIT_OK;
}

}  // namespace openswarm
