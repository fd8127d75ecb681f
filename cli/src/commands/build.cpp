// openswarm build: configure and build the app's firmware with CMake.
#include "build.hpp"

#include <sstream>

#include "../app_config.hpp"
#include "../app_project.hpp"
#include "../app_sources.hpp"
#include "../attribution.hpp"
#include "../generate.hpp"
#include "../link_errors.hpp"
#include "../ports.hpp"
#include "../process.hpp"
#include "build_report.hpp"
#include "commands.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

bool toolchain_present(const PortInfo &port) {
    if (find_program(port.compiler)) return true;
    report(port.compiler + " was not found, and the " + port.name + " port needs it: " + port.install);
    return false;
}

// Flash (.text + .data, and the ARM unwind index) and RAM (.data + .bss +
// .noinit) of an image, by section: avr-size's totals would count the
// .mmcu record, which the simulator reads and the robot never gets.
bool image_size(const PortInfo &port, const fs::path &image, unsigned &flash, unsigned &ram) {
    std::string out;
    if (capture_program({port.size_tool, "-A", image.string()}, out) != 0) return false;
    std::istringstream lines(out);
    std::string line;
    unsigned text = 0, data = 0, bss = 0;
    bool found = false;
    while (std::getline(lines, line)) {
        std::istringstream fields(line);
        std::string section;
        unsigned size = 0;
        if (!(fields >> section >> size)) continue;
        if (section == ".text") text += size, found = true;
        if (section == ".ARM.exidx") text += size;
        if (section == ".data") data = size;
        if (section == ".bss" || section == ".noinit") bss += size;
    }
    flash = text + data;
    ram = data + bss;
    return found;
}

// The linker checks the RAM the image reserves, not the main stack above
// it, where main(), the interrupts and the event handlers run: an image
// that leaves it too little builds and then crashes.
void warn_main_stack(const PortInfo &info, const BuildResult &r, const AppConfig &config) {
    if (!info.main_stack_minimum || r.ram >= info.ram_bytes) return;
    unsigned room = info.ram_bytes - r.ram;
    if (room >= info.main_stack_minimum) return;
    report("warning: RAM leaves the main stack " + std::to_string(room) +
           " bytes, less than the " + std::to_string(info.main_stack_minimum) +
           " a small app needs (main, the interrupts and the event handlers run there): lower "
           "the threads' \"stack\" in " + config.file.string() +
           "; `openswarm size` measures this app's worst use in the simulator");
}

// Editors (clangd, VS Code) look for compile_commands.json in a build/
// folder above the sources: the last exact build's (release or debug; the
// native one compiles for the host) is copied to the app's build/.
void publish_compile_commands(const fs::path &build_dir) {
    std::error_code error;
    fs::path to = build_dir.parent_path() / "compile_commands.json";
    fs::copy_file(build_dir / "compile_commands.json", to, fs::copy_options::overwrite_existing, error);
    if (error)
        report("warning: could not copy " + (build_dir / "compile_commands.json").string() + " to " + to.string() +
               " (" + error.message() + "); editors may read the one in " + build_dir.string());
}

struct BuildOptions {
    std::string dir = ".";
    std::string port;
    bool json = false;
    bool debug = false;
    bool werror = false;
    bool native = false;
    bool qemu = false;
    std::vector<std::string> parameters; // -D NAME=VALUE
};

// The kernel's and the app's shares of the image, from a second build
// without link-time optimisation (the image's own map cannot say: LTO
// merges the files). Empty, with why, if they cannot be measured; the
// image is built all the same.
std::vector<Share> measure_shares(const Paths &paths, const fs::path &dir, const BuildResult &r,
                                  Progress progress, std::string &why) {
    std::fprintf(
        progress == Progress::on_stdout ? stdout : stderr,
        "Measuring the kernel's and the app's shares: building once more, without link-time "
        "optimisation, in %s\n",
        attribution_dir(dir, r.port, r.parameters).string().c_str());
    auto a = attribute_app(paths, dir, r.name, r.port, r.parameters, why);
    return a ? shares_of(*a) : std::vector<Share>{};
}

// build, once its options are parsed: exit_code says how it went.
void build_command(const BuildOptions &o, const Paths &paths) {
    Progress progress = o.json ? Progress::on_stderr : Progress::on_stdout;
    std::string given; // the variants asked for, of which one may be
    for (const auto &[flag, on] : {std::pair{"--debug", o.debug}, {"--native", o.native}, {"--qemu", o.qemu}})
        if (on) given += (given.empty() ? "" : " and ") + std::string(flag);
    if (o.debug + o.native + o.qemu > 1) {
        report(given + ": give one (a debug image runs in the exact mode)");
        exit_code = EXIT_USAGE;
        return;
    }
    Variant variant = o.debug ? Variant::debug : o.native ? Variant::native : o.qemu ? Variant::qemu : Variant::release;
    auto parameters = parameter_options(o.parameters);
    if (!parameters) return;
    auto r = build_app(paths, o.dir, o.port, progress, variant, o.werror, *parameters);
    if (!r) return;
    std::string why = "not measured for a debug image (it has no link-time optimisation "
                      "to see through)";
    const bool host = port_info(r->port).flash_bytes == 0;
    if (host) why = "a host program has no robot's memory to share";
    if (r->native) why = "the native mode's build has no robot's memory to share";
    if (r->qemu) why = "not measured for the world's e-puck2 image (`openswarm build --port epuck2` measures the robot's)";
    auto shares = o.debug || host || r->native || r->qemu ? std::vector<Share>{}
                                   : measure_shares(paths, o.dir, *r, progress, why);
    if (o.json)
        print_build_json(*r, shares, why);
    else
        print_build_summary(*r, shares, why);
    exit_code = EXIT_OK;
}

}  // namespace

std::vector<std::string> configure_command(const Paths &paths, const fs::path &dir, const std::string &name,
                                           const fs::path &build_dir, const std::string &port, bool native) {
    // compile_commands.json: what clangd and editors read (copied beside
    // the app's build folders by build_app).
    std::vector<std::string> configure = {"cmake",
                                          "-S",
                                          app_project_dir(dir, port).string(),
                                          "-B",
                                          build_dir.string(),
                                          "--log-level=WARNING",
                                          "-DOpenSwarm_DIR=" + paths.sdk_cmake().string(),
                                          "-DOPENSWARM_PORT=" + port,
                                          "-DOPENSWARM_APP_NAME=" + name,
                                          "-DOPENSWARM_APP_DIR=" + fs::weakly_canonical(fs::absolute(dir)).string(),
                                          "-DCMAKE_EXPORT_COMPILE_COMMANDS=ON",
                                          "-DOPENSWARM_GENERATED_DIR=" +
                                              fs::absolute(generated_dir(dir, port)).lexically_normal().string()};
    if (find_program("ninja")) configure.insert(configure.begin() + 1, {"-G", "Ninja"});
    const std::string &toolchain = port_info(port).toolchain;
    if (native)
        configure.push_back("-DOPENSWARM_NATIVE=ON");
    else if (!toolchain.empty())
        configure.push_back("-DCMAKE_TOOLCHAIN_FILE=" + (paths.root / toolchain).string());
    return configure;
}

fs::path generated_dir(const fs::path &dir, const std::string &port) {
    return dir / "build" / port / "openswarm";
}

std::optional<BuildResult> build_app(const Paths &paths, const fs::path &dir,
                                     const std::string &port_option, Progress progress,
                                     Variant variant, bool werror, const ParameterValues &parameters) {
    FILE *out = progress == Progress::on_stdout ? stdout : stderr;
    const bool brief = progress == Progress::brief;
    std::string log; // brief: what CMake said, shown if it fails
    auto run = [&](const std::vector<std::string> &argv) {
        if (!brief) return progress == Progress::on_stdout ? run_program(argv) : run_program_to_stderr(argv);
        std::string said;
        int status = capture_program_and_errors(argv, said);
        log += said;
        return status;
    };
    auto say = [&](const std::string &line) {
        if (!brief) std::fprintf(out, "%s\n", line.c_str());
    };
    auto failed_log = [&] {
        if (brief) std::fprintf(stderr, "%s", log.c_str());
    };
    if (!port_option.empty() && !is_port(port_option)) {
        report(unknown_port_message(port_option));
        exit_code = EXIT_USAGE;
        return std::nullopt;
    }
    AppConfig config;
    try {
        config = load_app_config(dir, port_option);
        check_app_project_name(dir, config);
    } catch (const ConfigError &e) {
        report(e.what());
        exit_code = EXIT_USAGE;
        return std::nullopt;
    }
    for (const auto &[name, value] : parameters) {
        std::string why = parameter_problem(config, name, value);
        if (why.empty()) continue;
        report("-D " + name + "=" + std::to_string(value) + ": " + why);
        exit_code = EXIT_USAGE;
        return std::nullopt;
    }
    const ParameterValues changed = changed_parameters(config, parameters);
    const std::string port = config.port;
    const bool debug = variant == Variant::debug, native = variant == Variant::native;
    const bool qemu = variant == Variant::qemu;
    if (native && port != "kilobot" && port != "epuck_world") {
        report("--native: the native mode runs Kilobot apps and the world's e-pucks (--port epuck_world) "
               "so far, and this one is for " + port + "; run it without --native (the exact mode)");
        exit_code = EXIT_USAGE;
        return std::nullopt;
    }
    if (qemu && port != "epuck_world") {
        report("--qemu (or a world's \"fidelity\": \"qemu\"): the e-puck2 image for the world under QEMU is built "
               "from an e-puck app of the world (--port epuck_world), and this one is for " + port +
               ": build it without --qemu, in a world without \"fidelity\": \"qemu\"");
        exit_code = EXIT_USAGE;
        return std::nullopt;
    }
    bool have_cmake = find_program("cmake").has_value();
    if (!have_cmake) report("cmake was not found: sudo apt-get install cmake");
    // The QEMU image is the e-puck2's, built by its toolchain.
    bool have_compiler = native ? find_program("cc").has_value() : toolchain_present(port_info(qemu ? "epuck2" : port));
    if (native && !have_compiler) report("cc was not found, and --native builds with it: sudo apt-get install gcc");
    if (!have_cmake || !have_compiler) {
        exit_code = EXIT_FAILED;
        return std::nullopt;
    }
    fs::path build_dir = dir / "build" / ((debug ? port + "-debug" : native ? port + "-native" : qemu ? port + "-qemu" : port) +
                                          parameters_folder_suffix(changed));
    fs::path generated = generated_dir(dir, port);
    const PortInfo &info = port_info(port);
    try {
        generate_app_files(config, libraries_used(dir, info), generated);
        write_app_project(dir, config);
    } catch (const ConfigError &e) {
        report(e.what());
        exit_code = EXIT_USAGE;
        return std::nullopt;
    } catch (const std::exception &e) {
        report(std::string(e.what()) + "; check that " + build_dir.string() + " is writable");
        exit_code = EXIT_FAILED;
        return std::nullopt;
    }
    forget_other_project(dir, port, build_dir);
    std::vector<std::string> configure = configure_command(paths, dir, config.name, build_dir, port, native);
    configure.push_back(std::string("-DOPENSWARM_DEBUG=") + (debug ? "ON" : "OFF"));
    configure.push_back(std::string("-DOPENSWARM_WERROR=") + (werror ? "ON" : "OFF"));
    configure.push_back("-DOPENSWARM_PARAMETERS=" + parameters_cmake_list(changed));
    // Where the e-puck2's robot image is linked (cmake/OpenSwarmKernel.cmake).
    if (port == "epuck2")
        configure.push_back("-DOPENSWARM_EPUCK2_BOOTLOADER=" + robot_placement(config).bootloader);
    if (qemu)
        configure.insert(configure.end(), {"-DCMAKE_TOOLCHAIN_FILE=" + (paths.root / port_info("epuck2").toolchain).string(),
                                           "-DOPENSWARM_EPUCK2_WORLD=ON"});
    say("Configuring " + config.name + " for " + port +
        (debug ? " (debug: -Og, no link-time optimisation)"
               : native ? " (native: for the host, the simulator's native mode)"
               : qemu   ? " (qemu: the e-puck2's image for the world under QEMU)" : ""));
    if (run(configure) != 0) {
        failed_log();
        report("configuring failed (CMake's messages are above); check " +
               (dir / "CMakeLists.txt").string());
        exit_code = EXIT_FAILED;
        return std::nullopt;
    }
    say("Building " + config.name);
    LinkOverflows overflows;
    auto show = [&](const std::string &line) {
        if (brief) {
            log += line + "\n";
            if (line.find(": warning:") != std::string::npos) std::fprintf(stderr, "%s\n", line.c_str());
        } else {
            std::fprintf(out, "%s\n", line.c_str());
        }
        overflows.scan(line);
    };
    if (run_program_lines({"cmake", "--build", build_dir.string()}, show, 0, true) != 0) {
        failed_log();
        auto why = overflows.explain(config, generated / "openswarm_config.h");
        report(why ? *why : "the build failed (the compiler's messages are above)");
        exit_code = EXIT_FAILED;
        return std::nullopt;
    }
    if (!native && !qemu) publish_compile_commands(build_dir);
    BuildResult result;
    result.name = config.name;
    result.port = port;
    result.parameters = changed;
    if (native || qemu) {
        result.native = native;
        result.qemu = qemu;
        result.image = build_dir / (config.name + (native ? ".so" : ".elf"));
        if (brief) std::printf("Built %s (%s)\n", result.image.string().c_str(), native ? "native" : "e-puck2 image for QEMU");
        return result;
    }
    result.image = build_dir / (config.name + info.image_suffix);
    result.flash_total = flash_budget(config);
    if (!image_size(info, result.image, result.flash, result.ram)) {
        report("cannot read the size of " + result.image.string() + " with " + info.size_tool);
        exit_code = EXIT_FAILED;
        return std::nullopt;
    }
    warn_main_stack(info, result, config);
    if (!info.robot_image_suffix.empty()) {
        RobotImage robot;
        robot.placement = robot_placement(config);
        robot.image = build_dir / (config.name + info.robot_image_suffix);
        if (!image_size(info, robot.image, robot.flash, robot.ram)) {
            report("cannot read the size of " + robot.image.string() + " with " + info.size_tool);
            exit_code = EXIT_FAILED;
            return std::nullopt;
        }
        result.robot = robot;
    }
    if (brief && info.flash_bytes)
        std::printf("Built %s (flash %u of %u bytes, RAM %u of %u)\n", result.image.string().c_str(),
                    result.flash, result.flash_total, result.ram, info.ram_bytes);
    else if (brief)
        std::printf("Built %s\n", result.image.string().c_str());
    return result;
}

std::optional<ParameterValues> parameter_options(const std::vector<std::string> &settings) {
    ParameterValues values;
    std::string why;
    for (const auto &text : settings) {
        if (parse_parameter_setting(text, values, why)) continue;
        report(why);
        exit_code = EXIT_USAGE;
        return std::nullopt;
    }
    return values;
}

bool refuse_unrunnable(const std::string &port, const std::string &command) {
    const PortInfo &info = port_info(port);
    if (info.runner != Runner::none) return false;
    std::string message = "`openswarm " + command + "`: nothing here runs " + port +
                          " images (no simulator): `openswarm build --port " + port +
                          "` builds one for the robot";
    if (!find_program(info.compiler))
        message += ", and needs " + info.compiler + ", which was not found: " + info.install;
    report(message);
    return true;
}

void add_build_command(CLI::App &app, const Paths &paths) {
    auto o = std::make_shared<BuildOptions>();
    CLI::App *cmd = app.add_subcommand("build", "Build the app's firmware image for its robot");
    cmd->add_option("-p,--port", o->port, "robot to build for (default: the app's port)");
    cmd->add_option("-C,--directory", o->dir, "the app's folder")->capture_default_str();
    cmd->add_flag("--json", o->json, "print the result as JSON (progress goes to standard error)");
    cmd->add_flag("--werror", o->werror, "the app's compiler warnings are errors (they are on: -Wall -Wextra)");
    cmd->add_flag("--native", o->native,
                  "the app for the host, in build/<port>-native/<app>.so: a robot of the "
                  "simulator's native mode, which runs thousands (docs/world.md, \"Native mode\")");
    cmd->add_flag("--qemu", o->qemu,
                  "an e-puck app of the world (port epuck_world) as the e-puck2's image, in "
                  "build/epuck_world-qemu/<app>.elf: a robot of a world with \"fidelity\": \"qemu\", "
                  "run by QEMU instruction by instruction (docs/world.md)");
    cmd->add_flag("--debug", o->debug,
                  "a debug image in build/<port>-debug: -Og -g, no link-time optimisation, so "
                  "the debugger (openswarm run --debug --gdb PORT) knows every line and variable");
    cmd->add_option("-D,--param", o->parameters,
                    "a value for a parameter openswarm.json declares (\"parameters\"); each set of "
                    "values is built in a folder of its own, build/<port>-p<fingerprint>")
        ->type_name("NAME=VALUE")
        ->allow_extra_args(false);
    cmd->callback([o, &paths] {
        build_command(*o, paths);
        if (o->json && exit_code != EXIT_OK) print_build_json_failure();
    });
}

}  // namespace openswarm
