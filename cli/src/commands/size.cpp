// openswarm size: where the app's flash and RAM go - the kernel and port,
// the thread stacks, the events' data, the event queue, the app - and the
// OpenSwarm paper's equation (1) evaluated for this app.
//
// The image is built with link-time optimisation, which merges functions
// across files; the attribution comes from a second build without it, whose
// link map names the file of every function and variable.
#include <fstream>
#include <map>
#include <sstream>

#include "../app_config.hpp"
#include "../process.hpp"
#include "build.hpp"
#include "commands.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

using Tally = std::map<std::string, unsigned>;

// Who owns an input section of the link map.
std::string owner_of(const std::string &file, const std::string &section) {
    if (file.find("_openswarm.a(") != std::string::npos) {
        if (section == ".bss.pool") return "thread stacks (pool)";
        if (section == ".bss.arena") return "event data (d_i)";
        if (section == ".bss.ring") return "event queue";
        return "kernel and port";
    }
    if (file.find("CMakeFiles/") != std::string::npos) return "app";
    return "C runtime and library";
}

// Sum the input sections of the map's .text, .data and .bss by owner.
bool read_map(const fs::path &map, Tally &flash, Tally &ram) {
    std::ifstream in(map);
    if (!in) return false;
    std::string line, output, pending;
    bool in_memory_map = false;
    while (std::getline(in, line)) {
        if (line.rfind("Linker script and memory map", 0) == 0) in_memory_map = true;
        if (!in_memory_map || line.empty()) continue;
        if (line[0] == '.') { // an output section
            output = line.substr(0, line.find_first_of(" \t"));
            continue;
        }
        std::istringstream fields(line);
        std::string first, address, size, file;
        fields >> first;
        bool named = first.rfind(".", 0) == 0 || first == "COMMON"; // COMMON: tentative globals
        if (named && !(fields >> address)) { // a long name, the rest below
            pending = first;
            continue;
        }
        std::string section = first;
        if (first.rfind("0x", 0) == 0) { // continuation of a long name
            section = pending;
            address = first;
        }
        pending.clear();
        if (!(fields >> size >> file) || size.rfind("0x", 0) != 0) continue;
        if (section.rfind(".", 0) != 0 && section != "COMMON") continue;
        unsigned bytes = (unsigned)std::stoul(size, nullptr, 16);
        if (bytes == 0) continue;
        std::string owner = owner_of(file, section);
        if (output == ".text") flash[owner] += bytes;
        if (output == ".data") {
            flash[owner] += bytes; // initial values live in flash too
            ram[owner] += bytes;
        }
        if (output == ".bss") ram[owner] += bytes;
    }
    return true;
}

int run_size(const std::string &dir, const Paths &paths) {
    auto built = build_app(paths, dir, "");
    if (!built) return exit_code;
    fs::path attribution = fs::path(dir) / "build" / (built->port + "-size");
    fs::path map = fs::absolute(attribution / "link.map");
    std::printf("Building once more without link-time optimisation, to attribute every byte\n");
    std::vector<std::string> configure = configure_command(paths, dir, attribution, built->port);
    configure.insert(configure.end(), {"-DOPENSWARM_LTO=OFF", "-DCMAKE_EXE_LINKER_FLAGS=-Wl,-Map=" + map.string()});
    std::string quiet;
    if (capture_program(configure, quiet) != 0 || capture_program({"cmake", "--build", attribution.string()}, quiet) != 0) {
        report("the attribution build failed:\n" + quiet);
        return EXIT_FAILED;
    }
    Tally flash, ram;
    if (!read_map(map, flash, ram)) {
        report("cannot read the link map " + map.string());
        return EXIT_FAILED;
    }
    unsigned flash_total = 0, ram_total = 0;
    for (const auto &[what, bytes] : flash) flash_total += bytes;
    for (const auto &[what, bytes] : ram) ram_total += bytes;
    std::printf("\nImage %s: flash %u bytes, RAM %u bytes (plus the main stack).\n",
                built->image.string().c_str(), built->flash, built->ram);
    std::printf("Without link-time optimisation it would take %u and %u; by owner:\n", flash_total, ram_total);
    std::printf("  %-24s %7s %7s\n", "", "flash", "RAM");
    std::map<std::string, bool> owners;
    for (const auto &[what, bytes] : flash) owners[what] = true;
    for (const auto &[what, bytes] : ram) owners[what] = true;
    for (const auto &[what, unused] : owners)
        std::printf("  %-24s %7u %7u\n", what.c_str(), flash[what], ram[what]);
    std::printf("Equation (1) for this app: RAM = kernel %u + stacks %u + event data %u + queue %u"
                " + app %u bytes\n(the paper's form, C + 12 n + 4 m + sum d_i + stacks: docs/benchmarks.md)\n",
                ram["kernel and port"], ram["thread stacks (pool)"], ram["event data (d_i)"],
                ram["event queue"], ram["app"]);
    return EXIT_OK;
}

}  // namespace

void add_size_command(CLI::App &app, const Paths &paths) {
    auto dir = std::make_shared<std::string>(".");
    CLI::App *cmd = app.add_subcommand("size", "Show where the app's flash and RAM go");
    cmd->add_option("-C,--directory", *dir, "the app's folder")->capture_default_str();
    cmd->callback([dir, &paths] { exit_code = run_size(*dir, paths); });
}

}  // namespace openswarm
