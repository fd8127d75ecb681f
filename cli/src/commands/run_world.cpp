// openswarm run --world: the world file, read for the first line and the
// mode, looked for, and kept beside the run's outputs.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "run_options.hpp"
#include "../suggest.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

// The world files an app ships (<dir>/worlds/*.json), to suggest when the
// one asked for is not there.
std::vector<std::string> app_worlds(const fs::path &dir) {
    std::vector<std::string> found;
    std::error_code ec;
    for (const auto &entry : fs::directory_iterator(dir / "worlds", ec))
        if (entry.path().extension() == ".json") found.push_back(entry.path().string());
    std::sort(found.begin(), found.end());
    return found;
}

}  // namespace

// How long the world runs, for the first line: its duration_s, or the
// simulator's default. The simulator checks the file and reports its
// mistakes; here an unreadable file just says less.
std::string world_duration(const std::string &path) {
    try {
        std::ifstream in(path);
        auto world = nlohmann::json::parse(in);
        auto d = world.find("duration_s");
        if (d == world.end()) return "for 10 s (the world gives no duration_s)";
        if (d->is_number()) {
            std::ostringstream text;
            text << "for " << d->get<double>() << " s (its duration_s)";
            return text.str();
        }
    } catch (const std::exception &) {
    }
    return "for its duration_s";
}

// The world's "fidelity": "native" asks for the native mode, "qemu" for
// the e-puck2 image (the simulator checks the file; an unreadable one
// says exact here).
std::string world_fidelity(const std::string &path) {
    try {
        std::ifstream in(path);
        auto world = nlohmann::json::parse(in);
        auto f = world.find("fidelity");
        return f != world.end() && f->is_string() ? f->get<std::string>() : "exact";
    } catch (const std::exception &) {
        return "exact";
    }
}

// A --world that names no file: say which file, where it was looked for,
// and what to give instead. False after reporting.
bool world_file_usable(const RunOptions &o) {
    std::error_code ec;
    if (fs::is_regular_file(o.world, ec)) return true;
    std::string message = "--world " + o.world + ": ";
    if (fs::exists(o.world, ec)) {
        message += "not a file; give a world.json (docs/world.md describes them)";
    } else {
        message += "no such file (looked for " +
                   fs::absolute(o.world).lexically_normal().string() + ")";
        if (o.dir != ".") message += "; the path is from the current folder, not from -C " + o.dir;
    }
    auto worlds = app_worlds(o.dir);
    if (!worlds.empty()) message += "; the app has: " + join(worlds);
    else message += "; write one as docs/world.md describes, or start from the disperse "
                    "template's worlds/packed.json";
    report(message);
    return false;
}

// The run's folder, with a copy of the world it ran in (world.json) for the
// metrics that need the arena or the lights; false after saying why not.
bool keep_world_beside_run(const std::string &world_path, const std::string &out) {
    std::error_code ec, same;
    fs::path copy = fs::path(out) / "world.json";
    if (fs::exists(copy, same) && fs::equivalent(world_path, copy, same)) return true;
    fs::create_directories(out, ec);
    if (!ec) fs::copy_file(world_path, copy, fs::copy_options::overwrite_existing, ec);
    if (!ec) return true;
    report("cannot keep the world in " + copy.string() + ": " + ec.message() +
           "; choose another --out folder or fix its permissions");
    return false;
}

}  // namespace openswarm
