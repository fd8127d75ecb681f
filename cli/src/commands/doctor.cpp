// openswarm doctor: is every tool OpenSwarm needs here? Prints the command
// that installs what is missing.
#include <filesystem>

#include "../suggest.hpp"
#include "commands.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

struct Check {
    std::string what;
    bool ok;
    std::string package; // Debian package that provides it
};

// Tools only some features use: missing, they are reported but the check
// still passes.
std::vector<Check> optional_checks() {
    return {
        {"ffmpeg (openswarm run --world --video)", find_program("ffmpeg").has_value(), "ffmpeg"},
        {"avr-gdb (openswarm run --gdb, kilobot)", find_program("avr-gdb").has_value(), "gdb-avr"},
        {"gdb-multiarch (openswarm run --gdb, epuck2)", find_program("gdb-multiarch").has_value(),
         "gdb-multiarch"},
        {"xc16-gcc (e-puck firmware: Microchip XC16, not in Debian, from "
         "https://www.microchip.com/xc16)",
         find_program("xc16-gcc").has_value(), ""},
        {"chromium (the world viewer's browser test)",
         find_program("chromium").has_value() || find_program("chromium-browser").has_value(),
         "chromium"},
    };
}

std::vector<Check> checks(const Paths &paths) {
    return {
        {"cmake", find_program("cmake").has_value(), "cmake"},
        {"ninja (faster builds)", find_program("ninja").has_value(), "ninja-build"},
        {"avr-gcc (Kilobot firmware)", find_program("avr-gcc").has_value(), "gcc-avr"},
        {"avr-size", find_program("avr-size").has_value(), "binutils-avr"},
        {"avr-libc headers", fs::exists("/usr/lib/avr/include/avr/io.h"), "avr-libc"},
        {"arm-none-eabi-gcc (e-puck2 firmware)", find_program("arm-none-eabi-gcc").has_value(),
         "gcc-arm-none-eabi"},
        {"newlib for arm-none-eabi", fs::exists("/usr/lib/arm-none-eabi/include/string.h"),
         "libnewlib-arm-none-eabi"},
        {"qemu-system-arm (running e-puck2 firmware)", find_program("qemu-system-arm").has_value(),
         "qemu-system-arm"},
        {"openswarm-sim (the simulator)", !paths.simulator.empty(), ""},
        {"OpenSwarm SDK and templates at " + paths.root.string(),
         fs::exists(paths.sdk_cmake() / "OpenSwarmConfig.cmake"), ""},
    };
}

}  // namespace

void add_doctor_command(CLI::App &app, const Paths &paths) {
    CLI::App *cmd = app.add_subcommand("doctor", "Check the tools OpenSwarm needs");
    cmd->callback([&paths] {
        std::vector<std::string> missing_packages;
        bool all_ok = true;
        for (const auto &c : checks(paths)) {
            std::printf("%s %s\n", c.ok ? "ok     " : "MISSING", c.what.c_str());
            if (c.ok) continue;
            all_ok = false;
            if (!c.package.empty()) missing_packages.push_back(c.package);
        }
        std::vector<std::string> optional_packages;
        for (const auto &c : optional_checks()) {
            std::printf("%s %s\n", c.ok ? "ok     " : "absent ", c.what.c_str());
            if (!c.ok && !c.package.empty()) optional_packages.push_back(c.package);
        }
        if (!optional_packages.empty())
            std::printf("Optional, only for what they are named after:\n    sudo apt-get install %s\n",
                        join(optional_packages, " ").c_str());
        if (all_ok) {
            std::printf("Everything is in place.\n");
            exit_code = EXIT_OK;
            return;
        }
        if (!missing_packages.empty())
            std::printf("Install what is missing with:\n    sudo apt-get install %s\n",
                        join(missing_packages, " ").c_str());
        if (paths.simulator.empty())
            std::printf("Build the simulator with: cmake --build <openswarm>/build --target openswarm-sim\n");
        exit_code = EXIT_FAILED;
    });
}

}  // namespace openswarm
