#include "sweep_spec.hpp"

#include <fstream>
#include <optional>
#include <sstream>

#include "../app_config.hpp"
#include "../json_checks.hpp"
#include "../metrics/builtin_metrics.hpp"
#include "../metrics/metrics_error.hpp"
#include "../regular_file.hpp"
#include "world_paths.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace openswarm {

namespace {

const char *example = "docs/experiments.md, \"Sweeps\", has one";

std::string read_text(const fs::path &file, const std::string &what) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
        throw ConfigError(file.string() + ": " + (fs::exists(file, ec) ? "not a file" : "no such file") +
                          "; give " + what);
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    if (!in) throw ConfigError(file.string() + ": cannot read it; give " + what);
    return text.str();
}

// The app: "app" (a folder, from the file's), else the nearest folder at
// or above the file's that holds an openswarm.json.
fs::path app_of(const fs::path &f, const json &doc) {
    fs::path from = fs::absolute(f).parent_path();
    std::error_code ec;
    if (doc.contains("app")) {
        fs::path app = (from / string_at(f, "app", doc["app"], "the app's folder")).lexically_normal();
        if (!fs::is_regular_file(app / "openswarm.json", ec))
            fail(f, "app", app.string() + " holds no openswarm.json: give the folder of the app to run");
        return app;
    }
    for (fs::path d = from; !d.empty(); d = d.parent_path()) {
        if (fs::is_regular_file(d / "openswarm.json", ec)) return d;
        if (d == d.parent_path()) break;
    }
    fail(f, "", "no openswarm.json in its folder or above it: add \"app\": the folder of the app to run");
}

std::vector<json> values_at(const fs::path &f, const std::string &where, const json &v) {
    if (!v.is_array() || v.empty() || v.size() > 1000)
        fail(f, where, "expected a list of 1..1000 values to try, e.g. [5, 10, 20], found " + found(v));
    for (size_t i = 0; i < v.size(); i++)
        for (size_t k = 0; k < i; k++)
            if (v[i] == v[k])
                fail(f, where, found(v[i]) + " is listed twice (items " + std::to_string(k) + " and " +
                                   std::to_string(i) + "): keep one");
    return std::vector<json>(v.begin(), v.end());
}

// A parameter's place, checked against the world: the world gives the
// trials' seeds and durations its own way.
void check_parameter(const Sweep &s, const std::string &where, const std::string &path) {
    if (is_app_place(path) || path == program_place) return; // their values are checked once known
    if (path == "seed")
        fail(s.file, where, "the seed is not swept: each trial t of a point runs with \"seed\" + t; "
                            "give \"trials\" and \"seed\" instead");
    if (path == "duration_s" && s.duration_s > 0)
        fail(s.file, where, "\"duration_s\" is given for every trial too: drop one of them");
    std::string why = world_path_problem(s.base_world, path);
    if (!why.empty()) fail(s.file, where, why + " (in " + s.world.string() + ")");
}

void load_grid(Sweep &s, const json &grid) {
    if (!grid.is_object() || grid.empty())
        fail(s.file, "grid", "expected {\"PLACE IN THE WORLD\": [values], ...}, e.g. "
                             "{\"robots[0].count\": [5, 10]}, found " + found(grid));
    size_t points = 1;
    for (const auto &[path, values] : grid.items()) {
        check_parameter(s, "grid." + path, path);
        s.parameters.push_back({path, values_at(s.file, "grid." + path, values)});
        points *= s.parameters.back().values.size();
        if (points * (size_t)s.trials > max_sweep_trials)
            fail(s.file, "grid", "more than " + std::to_string(max_sweep_trials) +
                                     " trials (points x trials): fewer values, or fewer trials");
    }
    // Every combination, the last parameter changing fastest.
    std::vector<size_t> at(s.parameters.size(), 0);
    for (size_t n = 0; n < points; n++) {
        std::vector<json> point;
        for (size_t p = 0; p < at.size(); p++) point.push_back(s.parameters[p].values[at[p]]);
        s.points.push_back(point);
        for (size_t p = at.size(); p-- > 0;) {
            if (++at[p] < s.parameters[p].values.size()) break;
            at[p] = 0;
        }
    }
}

void load_points(Sweep &s, const json &list) {
    if (!list.is_array() || list.empty() || list.size() * (size_t)s.trials > max_sweep_trials)
        fail(s.file, "points", "expected a list of {\"PLACE IN THE WORLD\": value, ...}, at most " +
                                   std::to_string(max_sweep_trials) + " trials in all, found " + found(list));
    const json &first = list[0];
    if (!first.is_object() || first.empty())
        fail(s.file, "points[0]", "expected {\"PLACE IN THE WORLD\": value, ...}, found " + found(first));
    for (const auto &[path, value] : first.items()) {
        (void)value;
        check_parameter(s, "points[0]." + path, path);
        s.parameters.push_back({path, {}});
    }
    for (size_t i = 0; i < list.size(); i++) {
        std::string where = "points[" + std::to_string(i) + "]";
        const json &p = list[i];
        if (!p.is_object()) fail(s.file, where, "expected {\"PLACE IN THE WORLD\": value, ...}, found " + found(p));
        std::vector<std::string> keys;
        for (const auto &parameter : s.parameters) keys.push_back(parameter.path);
        check_keys(s.file, where, p, keys);
        std::vector<json> point;
        for (const auto &parameter : s.parameters)
            point.push_back(require(s.file, p, parameter.path, where));
        for (size_t k = 0; k < s.points.size(); k++)
            if (s.points[k] == point)
                fail(s.file, where, "the same point as points[" + std::to_string(k) + "]: drop one");
        s.points.push_back(point);
    }
}

// The values of "app.NAME" places, against the app's openswarm.json: a
// parameter it declares, a whole number in its range; those it reads
// from the EEPROM noted.
void check_app_values(Sweep &s, bool grid) {
    std::optional<AppConfig> app;
    for (size_t p = 0; p < s.parameters.size(); p++) {
        if (!is_app_place(s.parameters[p].path)) continue;
        if (!app) app = load_app_config(s.app);
        const std::string name = s.parameters[p].path.substr(4);
        for (size_t i = 0; i < s.points.size(); i++) {
            std::string why = parameter_problem(*app, name, s.points[i][p]);
            if (!why.empty())
                fail(s.file, (grid ? "grid." : "points[" + std::to_string(i) + "].") + s.parameters[p].path, why);
        }
        if (find_parameter(*app, name)->in_eeprom) s.eeprom_parameters[name] = *find_parameter(*app, name);
    }
}

// The base world with the places in it a point sets, the app's EEPROM
// values as bytes of the world's "eeprom" (docs/world.md).
json with_world_places(const Sweep &s, size_t point) {
    json world = s.base_world;
    for (size_t p = 0; p < s.parameters.size(); p++) {
        const std::string &path = s.parameters[p].path;
        auto eeprom = is_app_place(path) ? s.eeprom_parameters.find(path.substr(4)) : s.eeprom_parameters.end();
        if (eeprom != s.eeprom_parameters.end())
            world["eeprom"].push_back(
                {{"address", eeprom->second.eeprom_address},
                 {"bytes", eeprom_parameter_bytes_of(eeprom->second, s.points[point][p].get<long>())}});
        else if (!is_app_place(path) && path != program_place)
            set_world_path(world, path, s.points[point][p]);
    }
    return world;
}

// The values of the "program" place: names of files in the app's build
// folder (whether each was built is known once the app is).
void check_program_values(const Sweep &s, bool grid) {
    for (size_t p = 0; p < s.parameters.size(); p++) {
        if (s.parameters[p].path != program_place) continue;
        for (size_t i = 0; i < s.points.size(); i++) {
            const json &v = s.points[i][p];
            if (!v.is_string() || v.get<std::string>().empty() ||
                v.get<std::string>().find_first_of("/\\") != std::string::npos)
                fail(s.file, grid ? "grid.program" : "points[" + std::to_string(i) + "].program",
                     "expected the name of a program the app's build makes (a file name, e.g. \"clusters-plain\"), "
                     "found " + found(v));
        }
    }
}

// "marks": every point's world places its robots and objects on them.
void load_marks(Sweep &s, const json &doc) {
    if (!doc.contains("marks")) return;
    const fs::path &f = s.file;
    const json &marks = doc["marks"];
    if (!marks.is_object()) fail(f, "marks", "expected {\"columns\", \"rows\", \"spacing_mm\"}, found " + found(marks));
    check_keys(f, "marks", marks, {"columns", "rows", "spacing_mm"});
    Marks m;
    m.columns = (int)number_at(f, "marks.columns", require(f, marks, "columns", "marks"), 1, 1000);
    m.rows = (int)number_at(f, "marks.rows", require(f, marks, "rows", "marks"), 1, 1000);
    m.spacing_mm = real_at(f, "marks.spacing_mm", require(f, marks, "spacing_mm", "marks"), 80, 10000);
    s.marks = m;
    for (size_t p = 0; p < s.points.size(); p++) {
        std::string why = marks_problem(with_world_places(s, p), m);
        if (!why.empty())
            fail(f, "marks", why + " (in " + s.world.string() +
                                 (s.parameters.empty() ? "" : ", at the point " + point_label(s, p)) + ")");
    }
}

void load_metrics(Sweep &s, const json &doc) {
    if (doc.contains("metrics")) {
        const json &list = doc["metrics"];
        if (!list.is_array())
            fail(s.file, "metrics", "expected a list of metric names, e.g. [\"nearest_neighbour_mm\"], found " +
                                        found(list));
        for (size_t i = 0; i < list.size(); i++) {
            std::string where = "metrics[" + std::to_string(i) + "]";
            std::string text = string_at(s.file, where, list[i], "a metric, NAME or NAME:key=value,...");
            try {
                parse_metric_request(text);
            } catch (const MetricsError &e) {
                fail(s.file, where, std::string(e.what()) + " (`openswarm metrics --list` shows the built-ins)");
            }
            s.metrics.push_back(text);
        }
    }
    if (doc.contains("scripts")) {
        const json &list = doc["scripts"];
        if (!list.is_array()) fail(s.file, "scripts", "expected a list of script paths, found " + found(list));
        for (size_t i = 0; i < list.size(); i++) {
            std::string where = "scripts[" + std::to_string(i) + "]";
            fs::path script = fs::absolute(s.file).parent_path() / string_at(s.file, where, list[i], "a script's path");
            std::error_code ec;
            if (!fs::is_regular_file(script, ec))
                fail(s.file, where, script.lexically_normal().string() +
                                        " does not exist: give the path of an executable script, from the file's folder");
            s.scripts.push_back(script.lexically_normal());
        }
    }
    if (doc.contains("every_s")) s.every_s = real_at(s.file, "every_s", doc["every_s"], 0, 1e6);
}

}  // namespace

bool is_sweep_file(const fs::path &file) {
    // Not opened unless a regular file: a FIFO would block (issue 30); the
    // clustering experiment's reader refuses it with what it is.
    if (!not_a_regular_file(file).empty()) return false;
    std::ifstream in(file);
    json doc = json::parse(in, nullptr, false);
    return !doc.is_discarded() && doc.is_object() && doc.contains("world");
}

Sweep load_sweep(const fs::path &file) {
    json doc = parse_json_file(file, read_text(file, std::string("a sweep file (") + example + ")"));
    Sweep s;
    s.file = file;
    if (!doc.is_object()) fail(file, "", std::string("expected a JSON object { ... }; ") + example);
    check_keys(file, "", doc, {"description", "app", "world", "trials", "seed", "duration_s", "grid",
                               "points", "marks", "metrics", "scripts", "every_s"});
    if (doc.contains("description")) s.description = string_at(file, "description", doc["description"], "a text");
    s.app = app_of(file, doc);
    s.world = (fs::absolute(file).parent_path() /
               string_at(file, "world", doc["world"], "the path of a world.json, from this file's folder"))
                  .lexically_normal();
    s.base_world = parse_json_file(s.world, read_text(s.world, "a world.json (docs/world.md)"));
    if (!s.base_world.is_object()) fail(s.world, "", "expected a world, a JSON object { ... } (docs/world.md)");
    if (doc.contains("trials")) s.trials = (int)number_at(file, "trials", doc["trials"], 1, 10000);
    if (doc.contains("seed")) s.seed = (uint32_t)number_at(file, "seed", doc["seed"], 0, 4294967295L);
    if ((uint64_t)s.seed + (uint64_t)s.trials - 1 > 4294967295ull)
        fail(file, "seed", "seed + trials - 1 passes 4294967295, the largest seed a world takes: a lower seed");
    if (doc.contains("duration_s")) s.duration_s = real_at(file, "duration_s", doc["duration_s"], 0.001, 86400);
    if (doc.contains("grid") && doc.contains("points"))
        fail(file, "points", "a sweep has a \"grid\" (every combination) or a list of \"points\", not both: drop one");
    if (doc.contains("grid")) load_grid(s, doc["grid"]);
    else if (doc.contains("points")) load_points(s, doc["points"]);
    else s.points.push_back({}); // the world as it is, trials times
    check_app_values(s, doc.contains("grid"));
    check_program_values(s, doc.contains("grid"));
    load_marks(s, doc);
    load_metrics(s, doc);
    return s;
}

json point_world(const Sweep &s, size_t point, int trial) {
    json world = with_world_places(s, point);
    world["seed"] = (uint64_t)s.seed + (uint64_t)trial;
    if (s.duration_s > 0) world["duration_s"] = s.duration_s;
    if (s.native) world["fidelity"] = "native";
    if (s.marks) place_on_marks(world, *s.marks, world["seed"].get<uint32_t>());
    return world;
}

bool is_app_place(const std::string &path) { return path.rfind("app.", 0) == 0; }

ParameterValues point_parameters(const Sweep &s, size_t point) {
    ParameterValues values;
    for (size_t p = 0; p < s.parameters.size(); p++)
        if (is_app_place(s.parameters[p].path) && !s.eeprom_parameters.count(s.parameters[p].path.substr(4)))
            values[s.parameters[p].path.substr(4)] = s.points[point][p].get<long>();
    return values;
}

std::string point_program(const Sweep &s, size_t point) {
    for (size_t p = 0; p < s.parameters.size(); p++)
        if (s.parameters[p].path == program_place) return s.points[point][p].get<std::string>();
    return "";
}

std::string point_label(const Sweep &s, size_t point) {
    if (s.parameters.empty()) return "the world as it is";
    std::string label;
    for (size_t p = 0; p < s.parameters.size(); p++)
        label += (p ? ", " : "") + s.parameters[p].path + "=" + s.points[point][p].dump();
    return label;
}

}  // namespace openswarm
