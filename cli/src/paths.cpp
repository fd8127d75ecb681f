#include "paths.hpp"

#include <cstdlib>
#include <stdexcept>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace openswarm {

static fs::path executable_dir(const char *argv0) {
    std::error_code ec;
    fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) self = fs::absolute(argv0);
    return self.parent_path();
}

static bool looks_like_root(const fs::path &p) {
    return fs::exists(p / "templates") && fs::exists(p / "sdk" / "cmake" / "OpenSwarmConfig.cmake");
}

Paths locate_paths(const char *argv0) {
    Paths paths;
    fs::path exe = executable_dir(argv0);
    std::vector<fs::path> roots;
    if (const char *env = std::getenv("OPENSWARM_ROOT")) roots.emplace_back(env);
    roots.push_back(exe / ".." / "share" / "openswarm"); // installed
    roots.emplace_back(OPENSWARM_SOURCE_ROOT);            // build tree
    for (const auto &r : roots) {
        if (looks_like_root(r)) {
            paths.root = fs::weakly_canonical(r);
            break;
        }
    }
    if (paths.root.empty())
        throw std::runtime_error("cannot find OpenSwarm's templates and SDK next to " + exe.string() +
                                 "; set OPENSWARM_ROOT to the OpenSwarm folder");
    for (const auto &s : {exe / "openswarm-sim", exe / ".." / "sim" / "openswarm-sim"}) {
        if (fs::exists(s)) {
            paths.simulator = fs::weakly_canonical(s);
            break;
        }
    }
    return paths;
}

std::optional<fs::path> find_program(const std::string &name) {
    const char *path = std::getenv("PATH");
    if (path == nullptr) return std::nullopt;
    std::string all = path;
    size_t start = 0;
    while (start <= all.size()) {
        size_t end = all.find(':', start);
        if (end == std::string::npos) end = all.size();
        fs::path candidate = fs::path(all.substr(start, end - start)) / name;
        if (!candidate.empty() && access(candidate.c_str(), X_OK) == 0) return candidate;
        start = end + 1;
    }
    return std::nullopt;
}

std::string simulator_problem(const Paths &paths) {
    if (!paths.simulator.empty()) return "";
    return "openswarm-sim was not found next to this tool; build it with "
           "`cmake --build <openswarm>/build --target openswarm-sim`";
}

}  // namespace openswarm
