#include "attribution.hpp"

#include "app_project.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "app_project.hpp"
#include "commands/build.hpp"
#include "process.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

// Who owns an input section of the link map.
std::string owner_of(const std::string &file, const std::string &section) {
    if (file.find("_openswarm.a(") != std::string::npos) {
        if (section == ".bss.os_stack_pool") return owner::stacks;
        if (section == ".bss.arena") return owner::event_data;
        if (section == ".bss.ring") return owner::event_queue;
        return owner::kernel;
    }
    if (file.find("CMakeFiles/") != std::string::npos) return owner::app;
    return owner::runtime;
}

// "kilolib.c.obj" of "libapp_openswarm.a(kilolib.c.obj)".
std::string archive_member(const std::string &file) {
    size_t open = file.find('(');
    if (open == std::string::npos || file.back() != ')') return file;
    return file.substr(open + 1, file.size() - open - 2);
}

// Sum the input sections of the map's .text, .data and .bss by owner.
bool read_map(const fs::path &map, Attribution &a) {
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
        if (named && !(fields >> address)) {                        // a long name, the rest below
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
        std::string who = owner_of(file, section);
        if (who != owner::app && who != owner::runtime)
            a.kernel_objects.insert(archive_member(file));
        if (output == ".text") a.flash[who] += bytes;
        if (output == ".data") {
            a.flash[who] += bytes; // initial values live in flash too
            a.ram[who] += bytes;
        }
        if (output == ".bss") a.ram[who] += bytes;
    }
    return true;
}

// The line of a failed step's output that says why (a compiler's or
// CMake's error, with CMake's message on the line after it), else its last.
std::string reason_in(const std::string &output) {
    std::istringstream lines(output);
    std::string line, last, error;
    while (std::getline(lines, line)) {
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        if (!error.empty() && error.back() == ':' && error.find('\n') == std::string::npos) {
            error += "\n" + line;
            continue;
        }
        std::string lower = line;
        std::transform(lower.begin(), lower.end(), lower.begin(),
                       [](unsigned char c) { return (char)std::tolower(c); });
        if (error.empty() && lower.find("error") != std::string::npos) error = line;
        last = line;
    }
    return error.empty() ? last : error;
}

unsigned sum(const std::map<std::string, unsigned> &tally) {
    unsigned total = 0;
    for (const auto &[who, bytes] : tally) total += bytes;
    return total;
}

unsigned get(const std::map<std::string, unsigned> &tally, const std::string &who) {
    auto it = tally.find(who);
    return it == tally.end() ? 0 : it->second;
}

double percent(unsigned part, unsigned whole) { return whole ? 100.0 * part / whole : 0.0; }

}  // namespace

unsigned Attribution::flash_of(const std::string &who) const { return get(flash, who); }
unsigned Attribution::ram_of(const std::string &who) const { return get(ram, who); }
unsigned Attribution::flash_total() const { return sum(flash); }
unsigned Attribution::ram_total() const { return sum(ram); }

std::vector<Share> shares_of(const Attribution &a) {
    unsigned pools =
        a.ram_of(owner::stacks) + a.ram_of(owner::event_data) + a.ram_of(owner::event_queue);
    std::vector<Share> shares = {
        {"kernel and port", "kernel_and_port", a.flash_of(owner::kernel), a.ram_of(owner::kernel),
         0, 0},
        {"its pools: stacks, event data, queue", "kernel_pools", 0, pools, 0, 0},
        {"app", "app", a.flash_of(owner::app), a.ram_of(owner::app), 0, 0},
        {"C runtime and library", "c_runtime", a.flash_of(owner::runtime), a.ram_of(owner::runtime),
         0, 0},
    };
    for (Share &s : shares) {
        s.flash_percent = percent(s.flash, a.flash_total());
        s.ram_percent = percent(s.ram, a.ram_total());
    }
    return shares;
}

fs::path attribution_dir(const fs::path &dir, const std::string &port, const ParameterValues &parameters) {
    return dir / "build" / (port + "-size" + parameters_folder_suffix(parameters));
}

// A path as one word of the shell command the build tool runs the link
// with: CMAKE_EXE_LINKER_FLAGS goes in as it is, split at spaces. In
// single quotes when it holds anything but the characters no shell reads.
static std::string shell_word(const std::string &path) {
    bool plain = !path.empty() && path.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                         "0123456789_./+-=,:@%") == std::string::npos;
    if (plain) return path;
    std::string quoted = "'";
    for (char c : path) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

std::optional<Attribution> attribute_app(const Paths &paths, const fs::path &dir, const std::string &name,
                                         const std::string &port, const ParameterValues &parameters,
                                         std::string &why) {
    fs::path build_dir = attribution_dir(dir, port, parameters);
    fs::path map = fs::absolute(build_dir / "link.map");
    forget_other_project(dir, port, build_dir);
    std::vector<std::string> configure = configure_command(paths, dir, name, build_dir, port);
    // One image, one map: the e-puck2's robot image would write its own
    // over it.
    configure.insert(configure.end(), {"-DOPENSWARM_LTO=OFF", "-DOPENSWARM_ROBOT_IMAGE=OFF",
                                       "-DOPENSWARM_PARAMETERS=" + parameters_cmake_list(parameters),
                                       "-DCMAKE_EXE_LINKER_FLAGS=-Wl,-Map=" + shell_word(map.string())});
    std::vector<std::string> build = {"cmake", "--build", build_dir.string()};
    std::string output;
    bool configured = capture_program_and_errors(configure, output) == 0;
    if (!configured || capture_program_and_errors(build, output) != 0) {
        why = std::string(configured ? "building" : "configuring") +
              " the app without link-time optimisation in " + build_dir.string() +
              " failed: " + reason_in(output);
        if (configured)
            why += "\n(`cmake --build " + build_dir.string() + "` shows all its messages)";
        return std::nullopt;
    }
    Attribution a;
    if (!read_map(map, a)) {
        why = "the link map " + map.string() +
              " of the build without link-time optimisation is missing";
        return std::nullopt;
    }
    return a;
}

}  // namespace openswarm
