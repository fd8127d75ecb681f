#include "app_project.hpp"

#include <fstream>
#include <sstream>

#include "commands/build.hpp"
#include "generate.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

bool is_cpp(const fs::path &file) {
    std::string e = file.extension().string();
    return e == ".cpp" || e == ".cc" || e == ".cxx";
}

// The same files OpenSwarmApp.cmake builds: the app's folder, and src/
// with its subfolders.
bool has_cpp_sources(const fs::path &dir) {
    std::error_code error;
    for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error))
        if (it->is_regular_file() && is_cpp(it->path())) return true;
    if (!fs::is_directory(dir / "src", error)) return false;
    for (fs::recursive_directory_iterator it(dir / "src", error), end; !error && it != end; it.increment(error))
        if (it->is_regular_file() && is_cpp(it->path())) return true;
    return false;
}

fs::path own_project(const fs::path &dir) { return dir / "CMakeLists.txt"; }

}  // namespace

fs::path app_project_dir(const fs::path &dir, const std::string &port) {
    if (fs::exists(own_project(dir))) return dir;
    return generated_dir(dir, port) / "project";
}

void write_app_project(const fs::path &dir, const AppConfig &config) {
    if (fs::exists(own_project(dir))) return;
    fs::path folder = app_project_dir(dir, config.port);
    fs::create_directories(folder);
    std::string languages = has_cpp_sources(dir) ? "C CXX ASM" : "C ASM";
    write_if_changed(folder / "CMakeLists.txt",
                     "# Written by `openswarm build` for an app without a CMakeLists.txt of its own;\n"
                     "# rewritten at every build. openswarm_app() builds every .c and .cpp file of\n"
                     "# the app's folder and of its src/ folder, named as openswarm.json says.\n"
                     "cmake_minimum_required(VERSION 3.20)\n"
                     "project(" + config.name + " " + languages + ")\n"
                     "find_package(OpenSwarm REQUIRED)\n"
                     "openswarm_app()\n");
}

void forget_other_project(const fs::path &dir, const std::string &port, const fs::path &build_dir) {
    std::ifstream cache(build_dir / "CMakeCache.txt");
    const std::string key = "CMAKE_HOME_DIRECTORY:INTERNAL=";
    std::string line;
    while (std::getline(cache, line)) {
        if (line.rfind(key, 0) != 0) continue;
        std::error_code error;
        fs::path cached = fs::weakly_canonical(line.substr(key.size()), error);
        if (cached == fs::weakly_canonical(app_project_dir(dir, port), error)) return;
        cache.close();
        fs::remove(build_dir / "CMakeCache.txt", error);
        fs::remove_all(build_dir / "CMakeFiles", error);
        return;
    }
}

void check_app_project_name(const fs::path &dir, const AppConfig &config) {
    std::ifstream in(own_project(dir));
    std::string line;
    const std::string call = "openswarm_add_firmware(";
    for (int number = 1; std::getline(in, line); number++) {
        size_t at = line.find(call);
        if (at == std::string::npos || line.find('#') < at) continue;
        std::istringstream rest(line.substr(at + call.size()));
        std::string name;
        rest >> name;
        name = name.substr(0, name.find(')'));
        // A name from a variable is CMake's to check (OpenSwarmApp.cmake).
        if (name.empty() || name.find('$') != std::string::npos || name == config.name) continue;
        throw ConfigError("the app is named \"" + config.name + "\" in " + config.file.string() + " but \"" +
                          name + "\" in " + own_project(dir).string() + ":" + std::to_string(number) +
                          ": give it one name, openswarm.json's (write openswarm_app() in CMakeLists.txt "
                          "instead of openswarm_add_firmware(" + name + " ...): it takes the name from "
                          "openswarm.json; or delete CMakeLists.txt, and openswarm build makes one)");
    }
}

}  // namespace openswarm
