// openswarm.json: what an application is, validated with errors that name
// the file, the place and the fix.
#pragma once

#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app_parameters.hpp"
#include "ports.hpp"

namespace openswarm {

// A bad openswarm.json: the message is ready to print.
struct ConfigError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct EventConfig {
    std::string name;  // C identifier; the app uses EV_<NAME>
    unsigned size = 0; // bytes of data
    std::string type;  // "uint16", ...: openswarm.json's "type"; "" when it gave "size"
};

struct ThreadConfig {
    std::string entry; // void entry(void) in the app's sources
    unsigned stack = 0; // bytes; 0 = the kernel's default
    unsigned priority = 0;
};

struct DeviceConfig {
    std::string device;    // "motors"
    std::string processor; // "spinup-limited"
    std::map<std::string, long> params;
    std::vector<std::pair<long, long>> points; // [raw, value], for a processor that takes a table
};

struct AppConfig {
    std::filesystem::path file;
    std::string name;
    std::string port;
    std::map<std::string, long> kernel; // "max_threads" -> 4, ... (only what the file sets)
    std::string scheduler;              // "" = the kernel's default (round-robin)
    long time_slice_ms = 0;             // 0 = the kernel's default
    std::vector<EventConfig> events;
    std::vector<ThreadConfig> threads;
    std::vector<DeviceConfig> devices; // processors chosen in openswarm.json
    // "kilobot": {"overhead_controller": ...}: "port", "events", "off";
    // "" = not given (the port's default, "port").
    std::string overhead_controller;
    // "epuck2": {"bootloader": ...}: "none" or "aseba" (epuck2_placements);
    // "" = not given (the default, "none").
    std::string epuck2_bootloader;
    std::vector<AppParameter> parameters; // "parameters", by name
};

// Where this app's e-puck2 robot image goes: its "epuck2.bootloader"'s
// placement, or the default's.
const FlashPlacement &robot_placement(const AppConfig &c);

// The flash an image of the app may fill on c.port: the port's, or for the
// e-puck2 what its placement leaves; and why it is less than the MCU's
// ("" when it is not).
unsigned flash_budget(const AppConfig &c);
std::string flash_budget_note(const AppConfig &c);

// The KILOBOT_OVERHEAD_CONTROL value of each overhead_controller choice
// (ports/kilobot/include/openswarm/robot.h).
const std::map<std::string, int> &overhead_controller_choices();

// The guard pattern at the bottom of every thread stack while the kernel's
// stack check is on (OS_STACK_GUARD_BYTES, kernel/src/kernel_internal.h):
// the same on every port.
constexpr unsigned stack_guard_bytes = 4;

// (key, config.h macro) of every kernel setting openswarm.json may give.
const std::vector<std::pair<std::string, std::string>> &kernel_setting_macros();

// Is key one of the kernel's on/off features ("stack_check": true/false in
// openswarm.json, kept as 1/0)?
bool is_kernel_switch(const std::string &key);

// Read and validate dir/openswarm.json; for port (a known port's name, ""
// for the file's own) if given: what `--port` builds.
AppConfig load_app_config(const std::filesystem::path &dir, const std::string &port = "");

// The port a command will use, when it can be told before a build: port
// if given, else the app's in dir; "" when dir's openswarm.json is missing
// or broken (the build reports that itself).
std::string port_given_or_app(const std::string &port, const std::filesystem::path &dir);

// "file:line:column: message" plus the line and a caret, for a byte offset.
std::string located_message(const std::filesystem::path &file, const std::string &text,
                            size_t byte, const std::string &message);

}  // namespace openswarm
