// openswarm build: configure and build the app's firmware with CMake.
#include "build.hpp"

#include <sstream>

#include "../app_config.hpp"
#include "../generate.hpp"
#include "../ports.hpp"
#include "../process.hpp"
#include "commands.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

bool toolchain_present(const std::string &port) {
    if (port != "kilobot") return true;
    if (find_program("avr-gcc")) return true;
    report("avr-gcc was not found, and the kilobot port needs it: install it with\n"
           "    sudo apt-get install gcc-avr avr-libc binutils-avr\n"
           "(or run OpenSwarm's ./setup.sh)");
    return false;
}

// Flash (.text + .data) and RAM (.data + .bss + .noinit) of an AVR image,
// by section: avr-size's totals would count the .mmcu record, which the
// simulator reads and the robot never gets.
bool image_size(const fs::path &image, unsigned &flash, unsigned &ram) {
    std::string out;
    if (capture_program({"avr-size", "-A", image.string()}, out) != 0) return false;
    std::istringstream lines(out);
    std::string line;
    unsigned text = 0, data = 0, bss = 0;
    bool found = false;
    while (std::getline(lines, line)) {
        std::istringstream fields(line);
        std::string section;
        unsigned size = 0;
        if (!(fields >> section >> size)) continue;
        if (section == ".text") text = size, found = true;
        if (section == ".data") data = size;
        if (section == ".bss" || section == ".noinit") bss += size;
    }
    flash = text + data;
    ram = data + bss;
    return found;
}

std::string bar(unsigned used, unsigned total) {
    const int width = 20;
    int filled = total ? (int)((unsigned long)used * width / total) : 0;
    if (filled > width) filled = width;
    char percent[16];
    std::snprintf(percent, sizeof percent, "%5.1f%%", total ? 100.0 * used / total : 0.0);
    return "[" + std::string(filled, '=') + std::string(width - filled, ' ') + "] " + percent +
           " (" + std::to_string(used) + " of " + std::to_string(total) + " bytes)";
}

struct BuildOptions {
    std::string dir = ".";
    std::string port;
    bool json = false;
};

}  // namespace

std::vector<std::string> configure_command(const Paths &paths, const fs::path &dir,
                                           const fs::path &build_dir, const std::string &port) {
    std::vector<std::string> configure = {
        "cmake", "-S", dir.string(), "-B", build_dir.string(), "--log-level=WARNING",
        "-DOpenSwarm_DIR=" + paths.sdk_cmake().string(), "-DOPENSWARM_PORT=" + port,
        "-DOPENSWARM_GENERATED_DIR=" + fs::absolute(generated_dir(dir, port)).string()};
    if (find_program("ninja")) configure.insert(configure.begin() + 1, {"-G", "Ninja"});
    if (port == "kilobot") configure.push_back("-DCMAKE_TOOLCHAIN_FILE=" + paths.toolchain(port).string());
    return configure;
}

fs::path generated_dir(const fs::path &dir, const std::string &port) {
    return dir / "build" / port / "openswarm";
}

std::optional<BuildResult> build_app(const Paths &paths, const fs::path &dir, const std::string &port_option) {
    AppConfig config;
    try {
        config = load_app_config(dir);
    } catch (const ConfigError &e) {
        report(e.what());
        exit_code = EXIT_USAGE;
        return std::nullopt;
    }
    std::string port = port_option.empty() ? config.port : port_option;
    if (!is_port(port)) {
        report("unknown port '" + port + "'; `openswarm ports` lists them");
        exit_code = EXIT_USAGE;
        return std::nullopt;
    }
    bool have_cmake = find_program("cmake").has_value();
    if (!have_cmake) report("cmake was not found: sudo apt-get install cmake");
    if (!have_cmake || !toolchain_present(port)) {
        exit_code = EXIT_FAILED;
        return std::nullopt;
    }
    fs::path build_dir = dir / "build" / port;
    fs::path generated = generated_dir(dir, port);
    config.port = port;
    try {
        generate_app_files(config, generated);
    } catch (const std::exception &e) {
        report(std::string(e.what()) + "; check that " + build_dir.string() + " is writable");
        exit_code = EXIT_FAILED;
        return std::nullopt;
    }
    std::vector<std::string> configure = configure_command(paths, dir, build_dir, port);
    std::printf("Configuring %s for %s\n", config.name.c_str(), port.c_str());
    if (run_program(configure) != 0) {
        report("configuring failed (CMake's messages are above); check " +
               (dir / "CMakeLists.txt").string());
        exit_code = EXIT_FAILED;
        return std::nullopt;
    }
    std::printf("Building %s\n", config.name.c_str());
    if (run_program({"cmake", "--build", build_dir.string()}) != 0) {
        report("the build failed (the compiler's messages are above)");
        exit_code = EXIT_FAILED;
        return std::nullopt;
    }
    BuildResult result;
    result.port = port;
    result.image = build_dir / (config.name + (port == "kilobot" ? ".elf" : ""));
    if (port == "kilobot" && !image_size(result.image, result.flash, result.ram)) {
        report("cannot read the size of " + result.image.string() + " with avr-size");
        exit_code = EXIT_FAILED;
        return std::nullopt;
    }
    return result;
}

void add_build_command(CLI::App &app, const Paths &paths) {
    auto o = std::make_shared<BuildOptions>();
    CLI::App *cmd = app.add_subcommand("build", "Build the app's firmware image for its robot");
    cmd->add_option("-p,--port", o->port, "robot to build for (default: the app's port)");
    cmd->add_option("-C,--directory", o->dir, "the app's folder")->capture_default_str();
    cmd->add_flag("--json", o->json, "print the result as JSON");
    cmd->callback([o, &paths] {
        auto r = build_app(paths, o->dir, o->port);
        if (!r) return;
        const PortInfo &info = port_info(r->port);
        if (o->json) {
            std::printf("{\"image\": \"%s\", \"port\": \"%s\", \"flash\": %u, \"flash_total\": %u, "
                        "\"ram\": %u, \"ram_total\": %u}\n",
                        r->image.string().c_str(), r->port.c_str(), r->flash, info.flash_bytes, r->ram,
                        info.ram_bytes);
        } else {
            std::printf("Flash %s\nRAM   %s\n", bar(r->flash, info.flash_bytes).c_str(),
                        bar(r->ram, info.ram_bytes).c_str());
            std::printf("Built %s for %s\n", r->image.string().c_str(), r->port.c_str());
        }
        exit_code = EXIT_OK;
    });
}

}  // namespace openswarm
