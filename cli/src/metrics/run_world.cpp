#include "run_world.hpp"

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "metrics_error.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace openswarm {

namespace {

// The world was checked by the simulator before it ran: what is read here
// is what the metrics need, each mistake named by the key's path.
class WorldReader {
public:
    explicit WorldReader(const fs::path &file) : file_(file) {}

    [[noreturn]] void fail(const std::string &path, const std::string &what) const {
        throw MetricsError(file_.string() + ": \"" + path + "\": " + what +
                           " (docs/world.md; --world FILE gives the world the run was in)");
    }

    double number(const json &parent, const std::string &key, const std::string &path) const {
        if (!parent.is_object() || !parent.contains(key)) fail(path, "missing");
        const json &v = parent.at(key);
        if (!v.is_number()) fail(path, std::string("expected a number, found ") + v.type_name());
        return v.get<double>();
    }

private:
    fs::path file_;
};

}  // namespace

RunWorld read_run_world(const fs::path &file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    if (!in)
        throw MetricsError(file.string() + ": cannot be read; give the world the run was in with --world FILE");
    json doc;
    try {
        doc = json::parse(text.str());
    } catch (const json::exception &e) {
        throw MetricsError(file.string() + ": not a JSON world: " + e.what() +
                           "; give the world the run was in with --world FILE");
    }
    WorldReader read(file);
    if (!doc.is_object()) read.fail("", "expected a world, an object");
    RunWorld w;
    w.file = file;
    if (!doc.contains("arena")) read.fail("arena", "missing");
    w.arena_width_mm = read.number(doc["arena"], "width_mm", "arena.width_mm");
    w.arena_height_mm = read.number(doc["arena"], "height_mm", "arena.height_mm");
    if (doc.contains("ir") && doc["ir"].contains("range_mm")) w.ir_range_mm = read.number(doc["ir"], "range_mm", "ir.range_mm");
    if (doc.contains("light") && doc["light"].contains("sources")) {
        const json &sources = doc["light"]["sources"];
        if (!sources.is_array()) read.fail("light.sources", "expected a list");
        for (size_t k = 0; k < sources.size(); k++) {
            std::string at = "light.sources[" + std::to_string(k) + "].";
            w.lights.push_back({read.number(sources[k], "x_mm", at + "x_mm"), read.number(sources[k], "y_mm", at + "y_mm"),
                                read.number(sources[k], "intensity_mv", at + "intensity_mv")});
        }
    }
    if (doc.contains("objects")) {
        const json &objects = doc["objects"];
        if (!objects.is_array()) read.fail("objects", "expected a list");
        for (size_t k = 0; k < objects.size(); k++)
            w.object_radii_mm.push_back(
                read.number(objects[k], "radius_mm", "objects[" + std::to_string(k) + "].radius_mm"));
    }
    return w;
}

}  // namespace openswarm
