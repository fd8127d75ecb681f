#include "app_sources.hpp"

#include <fstream>
#include <regex>
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

// The file names (without their folders) that file's #include lines name.
std::set<std::string> included_names(const fs::path &file) {
    static const std::regex include(R"(^\s*#\s*include\s*[<"]([^">]+)[">])");
    std::set<std::string> names;
    std::ifstream in(file);
    std::string line;
    std::smatch m;
    while (std::getline(in, line))
        if (std::regex_search(line, m, include)) names.insert(fs::path(m[1].str()).filename().string());
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
