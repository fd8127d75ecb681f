#include "app_sources.hpp"

#include <fstream>
#include <set>
#include <string>

namespace fs = std::filesystem;

namespace openswarm {

namespace {

bool is_source(const fs::path &file) {
    static const std::set<std::string> extensions = {".c", ".h", ".cc", ".cpp", ".cxx", ".hh",
                                                     ".hpp", ".hxx", ".ino", ".S"};
    return extensions.count(file.extension().string()) != 0;
}

// The file named by an #include line ("" if it is not one), scanned by
// hand: std::regex recursed once per character of a 30 000-character line.
std::string included_name(const std::string &line) {
    size_t i = line.find_first_not_of(" \t");
    if (i == std::string::npos || line[i] != '#') return "";
    i = line.find_first_not_of(" \t", i + 1);
    if (i == std::string::npos || line.compare(i, 7, "include") != 0) return "";
    i = line.find_first_not_of(" \t", i + 7);
    if (i == std::string::npos || (line[i] != '<' && line[i] != '"')) return "";
    size_t end = line.find(line[i] == '<' ? '>' : '"', i + 1);
    if (end == std::string::npos || end == i + 1) return "";
    return line.substr(i + 1, end - i - 1);
}

// The file names (without their folders) that file's #include lines name.
std::set<std::string> included_names(const fs::path &file) {
    std::set<std::string> names;
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        std::string name = included_name(line);
        if (!name.empty()) names.insert(fs::path(name).filename().string());
    }
    return names;
}

// Build output (the generated sources, CMake's own test files) and hidden
// folders (.git) are not the app's code.
bool skipped(const fs::path &folder, const fs::path &app_dir) {
    return folder == app_dir / "build" || folder.filename().string().rfind('.', 0) == 0;
}

}  // namespace

Libraries libraries_used(const fs::path &dir, const PortInfo &port) {
    std::set<std::string> names;
    std::error_code error;
    fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, error), end;
    for (; !error && it != end; it.increment(error)) {
        if (it->is_directory() && skipped(it->path(), dir)) {
            it.disable_recursion_pending();
        } else if (it->is_regular_file() && is_source(it->path())) {
            auto found = included_names(it->path());
            names.insert(found.begin(), found.end());
        }
    }
    Libraries used;
    for (const auto &library : port.libraries)
        if (names.count(library.header)) used.push_back(&library);
    return used;
}

}  // namespace openswarm
