// Building an app's firmware image (shared by build and run).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "../app_parameters.hpp"
#include "../paths.hpp"
#include "../ports.hpp"

namespace openswarm {

// An image and the bytes it uses.
struct ImageSize {
    std::filesystem::path image;
    unsigned flash = 0, ram = 0;
};

// The e-puck2's robot image: its size, and where in flash it goes.
struct RobotImage : ImageSize {
    FlashPlacement placement;
};

struct BuildResult {
    std::filesystem::path image; // what `run` runs
    unsigned flash = 0, ram = 0; // bytes used
    // The flash the app may fill: the port's, or for the e-puck2 what the
    // app's "epuck2.bootloader" leaves the robot image (flash_budget).
    unsigned flash_total = 0;
    std::string name; // the app's, from openswarm.json
    std::string port;
    // The port's image for the real robot, when it is not the one `run`
    // runs (the e-puck2's: <app>-robot.elf, and .bin beside it).
    std::optional<RobotImage> robot;
    bool native = false; // the app built for the host (Variant::native): no robot's memory
    bool qemu = false;   // the e-puck2 image for the world (Variant::qemu): not measured
    ParameterValues parameters; // those that differ from openswarm.json's defaults
};

// Where `build` writes the files generated from openswarm.json.
std::filesystem::path generated_dir(const std::filesystem::path &dir, const std::string &port);

// The CMake configure command line for the app in dir, named name (its
// openswarm.json's), built in build_dir.
// With native, for the native mode: the host's compiler, no toolchain.
std::vector<std::string> configure_command(const Paths &paths, const std::filesystem::path &dir,
                                           const std::string &name, const std::filesystem::path &build_dir,
                                           const std::string &port, bool native = false);

// Where a command's progress (and CMake's) goes: standard error when
// standard output carries a result (--json); brief: one line when it
// builds (the compiler's warnings kept), all of it when it fails - for
// run and test, whose own output follows.
enum class Progress { on_stdout, on_stderr, brief };

// A release image (-Os, link-time optimisation: what goes to the robot),
// a debug one (-Og, no LTO: every line and variable for the debugger),
// the app built for the host as a native-mode robot (ports/native: a
// shared object openswarm-sim runs by the thousand), or an epuck_world
// app as the e-puck2's image the world runs under QEMU (<app>.elf), built
// in build/<port>, build/<port>-debug, build/<port>-native or
// build/<port>-qemu.
enum class Variant { release, debug, native, qemu };

// Configure and build the app in dir for port ("" = the app's own);
// prints progress, and errors ending with what to do. nullopt on failure,
// with exit_code set. parameters: values for openswarm.json's
// "parameters" (checked here: a bad one is exit 2); a set that differs
// from the defaults is built in a folder of its own (build/<port>-p<its
// fingerprint>), kept for the next build of the same set.
std::optional<BuildResult> build_app(const Paths &paths, const std::filesystem::path &dir,
                                     const std::string &port,
                                     Progress progress = Progress::on_stdout,
                                     Variant variant = Variant::release, bool werror = false,
                                     const ParameterValues &parameters = {});

// -D NAME=VALUE options into values; nullopt after reporting a malformed
// one (exit_code 2). build_app checks them against the app.
std::optional<ParameterValues> parameter_options(const std::vector<std::string> &settings);

// For a port nothing here runs (Runner::none): report that command cannot
// run its images, and what building them needs if it is missing; true then.
// False, silently, for a port that runs.
bool refuse_unrunnable(const std::string &port, const std::string &command);

}  // namespace openswarm
