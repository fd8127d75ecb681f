// The robots OpenSwarm builds for.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace openswarm {

// A thread one of the port's libraries starts by itself: the pools must
// make room for it besides the threads openswarm.json declares.
struct LibraryThread {
    std::string name;   // as `openswarm size` lists it
    unsigned stack;     // bytes requested (the library's own #define)
    std::string object; // the object file that starts it, as a link map names it
};

// A library of the port whose use the tool finds in the app's sources
// (app_sources.hpp): an app that includes header uses it.
struct PortLibrary {
    std::string name, header;
    std::vector<LibraryThread> threads;
    // The kernel settings (openswarm.json's "kernel" names) a program of
    // the library alone needs, when the app asks nothing of the kernel
    // itself (no threads, events or devices in openswarm.json); where the
    // file sets none, the build uses these rather than the port's defaults.
    std::map<std::string, long> classic_pools = {};
    // The object file whose presence in a link map says the library is in
    // the image (classic_pools' event_data is then the port's own events').
    std::string object = "";
};
// Those of a port's libraries that one app uses.
using Libraries = std::vector<const PortLibrary *>;

// What runs a port's images: openswarm-sim (simavr, cycle-exact), QEMU, or
// nothing here (none: build only; run and test refuse the port).
enum class Runner { simavr, qemu, world, none };

struct PortInfo {
    std::string name;
    std::string description;
    unsigned flash_bytes; // of the MCU, 0 for the host
    unsigned ram_bytes;
    // What the port's own configuration (port_config.h) reserves, so the
    // tool can size pools for an app's declared threads and events.
    unsigned device_events;      // event ids before the app's (kernel's 2 + port's)
    unsigned device_event_bytes; // their data
    unsigned default_max_threads, default_max_events, default_stack, stack_block;
    std::vector<PortLibrary> libraries;
    // How its images are built and run.
    std::string compiler;  // the program its CMake toolchain file needs on PATH
    std::string install;   // how to get the compiler, for errors and doctor
    std::string toolchain; // the CMake toolchain file, relative to OpenSwarm's root
    std::string size_tool; // reads an image's section sizes (-A)
    Runner runner;
    std::string flash_note = {}; // why flash_bytes is less than the MCU has
    // Below this much RAM left for the main stack (main, interrupts, event
    // handlers), the build warns; 0: the port reserves it at link time.
    unsigned main_stack_minimum = 0;
    // The image's file name after the app's: a robot's ELF, or a host
    // program (no suffix, no toolchain file, no flash or RAM to fill).
    std::string image_suffix = ".elf";
    // A second image built for the real robot when the first is for an
    // emulator (the e-puck2: "-robot.elf"); empty if there is none.
    std::string robot_image_suffix = "";
};

// A processor a device can use, as openswarm.json names it, and what the
// generated code installs.
struct ProcessorParam {
    std::string name, c_field;
    long min, max;
};
// A list of [raw, value] points, such as a sensor's linearisation table;
// the generated code puts them in a const array of c_point_type and points
// the parameters' c_points_field (and c_count_field) at it.
struct PointsParam {
    std::string name;
    unsigned min_count, max_count;
    long raw_min, raw_max, value_min, value_max;
    std::string c_point_type, c_points_field, c_count_field;
};
struct ProcessorInfo {
    std::string name;
    std::string c_function;          // the sys_processor to install
    std::string c_params_type;       // "" if it takes no parameters
    std::vector<ProcessorParam> params;
    std::string description;
    std::optional<PointsParam> points = {};
};
struct DeviceInfo {
    std::string name;     // "motors"
    std::string c_device; // "kilobot_motor_pair"
    std::vector<ProcessorInfo> processors; // the first is the default
};
const std::vector<DeviceInfo> &devices_of(const std::string &port);

// Where the e-puck2's robot image goes in its 1 MB of flash, by what the
// robot keeps at 0x08000000 (openswarm.json's "epuck2": {"bootloader"}):
// "none", GCtronic's standard firmware's way (its Makefile's default,
// USE_ASEBA_BOOTLOADER=no), the image at the flash's start; "aseba", after
// the 128 KB of the Aseba bootloader (USE_ASEBA_BOOTLOADER=yes). The first
// is the default.
struct FlashPlacement {
    std::string bootloader; // as openswarm.json names it
    unsigned origin;        // where the image is linked, its vector table first
    unsigned bytes;         // the flash from there to the end
    std::string what;       // for the build's summary and errors
};
const std::vector<FlashPlacement> &epuck2_placements();
// The placement of that name; std::out_of_range for another.
const FlashPlacement &epuck2_placement(const std::string &bootloader);
// "0x08020000": an address as the docs and the linker scripts write it.
std::string hex_address(unsigned address);

const std::vector<PortInfo> &ports();
std::vector<std::string> port_names();

// What a --port that names no port is told: the ports, and the nearest.
std::string unknown_port_message(const std::string &port);
bool is_port(const std::string &name);
const PortInfo &port_info(const std::string &name);

// What the RAM accounting (openswarm size, the configuration's RAM check)
// needs to know of a port: measured costs.
struct PortCosts {
    const char *port;
    unsigned stack_extra; // PORT_STACK_EXTRA, added to every stack (port_arch.h)
    // Equation (1)'s measured terms (bench/avr_bench.py, docs/benchmarks.md):
    // the minimal kernel (the system thread, 6 event slots, 1 subscription,
    // a 16-byte queue), a thread's control block, an event slot.
    unsigned fixed, per_thread, per_event;
    // Beyond equation (1) in an app with the port's default pools: the
    // devices' state, the port's longer queue and its subscriptions
    // (openswarm size's "the rest" on the blinky template).
    unsigned devices;
    // The stack pool when openswarm.json declares no threads (port_config.h's
    // OS_CFG_STACK_POOL_BYTES); 0: config.h's default, a default stack for
    // every thread slot but the system thread's.
    unsigned default_stack_pool;
};

// A port's costs: nullptr for a port without them (the host's, XC16's).
const PortCosts *costs_for(const std::string &port);
// The same, a logic_error for a port without them.
const PortCosts &costs_of(const std::string &port);

}  // namespace openswarm
