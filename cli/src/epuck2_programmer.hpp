// Programming an e-puck2 through its on-board programmer, a Black Magic
// Probe GDB server on a serial port: gdb-multiarch finds the F407 on the
// programmer's SWD lines (monitor swdp_scan), attaches, loads the ELF,
// checks the flash against it, starts it from its vector table and
// detaches, leaving it running. A GDB server that is already attached to
// its target (QEMU's, the tests' stand-in) skips the scan.
#pragma once

#include <filesystem>
#include <string>

namespace openswarm {

// A whole programming session's limit: 1 MB through the programmer's
// serial link at some 20-60 KB/s, with room for a loaded machine.
constexpr double EPUCK2_PROGRAMMING_SECONDS = 120;

// The gdb script for elf through the GDB server on device.
std::string epuck2_gdb_script(const std::string &device);

// Programs elf through device; prints what happened, reports why it
// failed; the tool's exit code.
int program_epuck2(const std::filesystem::path &elf, const std::string &device, double timeout_seconds);

}  // namespace openswarm
