#include "experiment_spec.hpp"

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "json_checks.hpp"
#include "regular_file.hpp"
#include "sweep/mark_placement.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace openswarm {

namespace {

const char *example = "docs/case-study.md has a whole one";

void load_world(const fs::path &f, const json &doc, Experiment &e) {
    const json &arena = require(f, doc, "arena");
    check_keys(f, "arena", arena, {"width_mm", "height_mm"});
    e.width_mm = real_at(f, "arena.width_mm", require(f, arena, "width_mm", "arena"), 100, 100000);
    e.height_mm = real_at(f, "arena.height_mm", require(f, arena, "height_mm", "arena"), 100, 100000);
    const json &marks = require(f, doc, "marks");
    check_keys(f, "marks", marks, {"columns", "rows", "spacing_mm"});
    e.columns = (int)number_at(f, "marks.columns", require(f, marks, "columns", "marks"), 1, 1000);
    e.rows = (int)number_at(f, "marks.rows", require(f, marks, "rows", "marks"), 1, 1000);
    e.spacing_mm = real_at(f, "marks.spacing_mm", require(f, marks, "spacing_mm", "marks"), 80, 10000);
    if ((e.columns - 1) * e.spacing_mm + 2 * 50 > e.width_mm ||
        (e.rows - 1) * e.spacing_mm + 2 * 50 > e.height_mm)
        fail(f, "marks", "a grid of " + std::to_string(e.columns) + " x " + std::to_string(e.rows) +
                             " marks this far apart does not fit the arena: fewer marks, or closer");
    e.robots = (int)number_at(f, "robots", require(f, doc, "robots"), 1, 100);
    const json &objects = require(f, doc, "objects");
    check_keys(f, "objects", objects, {"count", "radius_mm", "mass_g", "friction"});
    e.objects = (int)number_at(f, "objects.count", require(f, objects, "count", "objects"), 1, 1000);
    if (objects.contains("radius_mm"))
        e.object_radius_mm = real_at(f, "objects.radius_mm", objects["radius_mm"], 5, e.spacing_mm / 2 - 1);
    if (objects.contains("mass_g")) e.object_mass_g = real_at(f, "objects.mass_g", objects["mass_g"], 0.1, 10000);
    if (objects.contains("friction")) e.object_friction = real_at(f, "objects.friction", objects["friction"], 0, 2);
    if (e.robots + e.objects > e.columns * e.rows)
        fail(f, "objects.count", std::to_string(e.robots) + " robots and " + std::to_string(e.objects) +
                                     " objects need as many marks, and the grid has " +
                                     std::to_string(e.columns * e.rows) + ": fewer, or more marks");
}

void load_controllers(const fs::path &f, const json &doc, Experiment &e) {
    const json &list = require(f, doc, "controllers");
    if (!list.is_array() || list.empty())
        fail(f, "controllers", "expected a list of {\"name\", \"program\"}, found " + found(list));
    for (size_t i = 0; i < list.size(); i++) {
        std::string path = "controllers[" + std::to_string(i) + "]";
        const json &c = list[i];
        if (!c.is_object()) fail(f, path, "expected {\"name\": ..., \"program\": ...}, found " + found(c));
        check_keys(f, path, c, {"name", "program"});
        ExperimentController ctl;
        ctl.name = string_at(f, path + ".name", require(f, c, "name", path), "a name");
        if (ctl.name.empty() || ctl.name.size() > max_controller_name)
            fail(f, path + ".name",
                 quoted_start(ctl.name) + " is " + std::to_string(ctl.name.size()) +
                     " bytes long; each trial's folder is named after it (trial-01-<name>): give a "
                     "name of 1.." + std::to_string(max_controller_name) + " bytes");
        for (size_t k = 0; k < e.controllers.size(); k++) {
            const std::string &other = e.controllers[k].name;
            if (other == ctl.name) fail(f, path + ".name", "\"" + ctl.name + "\" is named twice");
            if (controller_folder(other) == controller_folder(ctl.name))
                fail(f, path + ".name",
                     quoted_start(ctl.name) + " and controllers[" + std::to_string(k) + "].name " +
                         quoted_start(other) + " would share their trials' folders (trial-01-" +
                         controller_folder(ctl.name) +
                         ", ...): a folder's name keeps only letters and digits, lower-cased; "
                         "rename one so that they differ in a letter or digit");
        }
        ctl.program = f.parent_path() / string_at(f, path + ".program", require(f, c, "program", path),
                                                  "a controller program's path");
        e.controllers.push_back(ctl);
    }
}

void load_reference(const fs::path &f, const json &doc, Experiment &e) {
    if (!doc.contains("reference")) return;
    const json &r = doc["reference"];
    check_keys(f, "reference", r, {"label", "time_s", "largest_cluster"});
    e.reference_label = string_at(f, "reference.label", require(f, r, "label", "reference"), "a text");
    e.reference_time_s = real_at(f, "reference.time_s", require(f, r, "time_s", "reference"), 0, e.duration_s);
    e.reference_fraction =
        real_at(f, "reference.largest_cluster", require(f, r, "largest_cluster", "reference"), 0, 1);
}

}  // namespace

std::string controller_folder(const std::string &name) {
    std::string s;
    for (char c : name) s += std::isalnum((unsigned char)c) ? (char)std::tolower((unsigned char)c) : '-';
    return s;
}

std::string trial_rows_problem(const Experiment &e, bool duration_given) {
    double things = e.robots + e.objects;
    double samples = std::floor(e.duration_s / e.sample_period_s + 1e-9) + 1, rows = things * samples;
    if (rows <= max_trial_rows) return "";
    // the shortest period that fits, rounded up to 3 significant digits
    double least = e.duration_s / (std::floor(max_trial_rows / things) - 1);
    double unit = std::pow(10, std::floor(std::log10(least)) - 2);
    least = std::ceil(least / unit - 1e-9) * unit;
    char text[512];
    std::snprintf(text, sizeof text,
                  "%s: \"sample_period_s\": %d robot%s and %d object%s sampled every %g s for %g s%s make "
                  "%.3g rows of each trial's trajectories.csv and objects.csv; openswarm-sim writes at "
                  "most %.0f: a sample_period_s of at least %g s, a shorter %s, or fewer robots and objects",
                  e.file.string().c_str(), e.robots, e.robots == 1 ? "" : "s", e.objects,
                  e.objects == 1 ? "" : "s", e.sample_period_s, e.duration_s,
                  duration_given ? " (--duration)" : "", rows, max_trial_rows, least,
                  duration_given ? "--duration" : "duration_s");
    return text;
}

Experiment load_experiment(const fs::path &file) {
    std::string kind = not_a_regular_file(file);
    if (!kind.empty())
        throw ConfigError(file.string() + ": " + kind + ", not a regular file; give an experiment file (" +
                          example + ")");
    std::ifstream in(file);
    if (!in) throw ConfigError(file.string() + ": cannot read it; give an experiment file (" + example + ")");
    std::stringstream text;
    text << in.rdbuf();
    json doc = parse_json_file(file, text.str());
    Experiment e;
    e.file = file;
    if (!doc.is_object()) fail(file, "", "expected a JSON object { ... }; " + std::string(example));
    check_keys(file, "", doc, {"description", "arena", "marks", "robots", "objects", "duration_s",
                               "sample_period_s", "trials", "seed", "controllers", "reference", "fidelity"});
    load_world(file, doc, e);
    e.duration_s = real_at(file, "duration_s", require(file, doc, "duration_s"), 1, 86400);
    if (doc.contains("sample_period_s"))
        e.sample_period_s = real_at(file, "sample_period_s", doc["sample_period_s"], 0.1, e.duration_s);
    e.trials = (int)number_at(file, "trials", require(file, doc, "trials"), 1, 10000);
    if (doc.contains("seed")) e.seed = (uint32_t)number_at(file, "seed", doc["seed"], 0, 4294967295L);
    load_controllers(file, doc, e);
    load_reference(file, doc, e);
    if (doc.contains("fidelity")) {
        std::string f = string_at(file, "fidelity", doc["fidelity"], "\"exact\" or \"native\"");
        if (f != "exact" && f != "native")
            fail(file, "fidelity", "unknown fidelity \"" + f + "\"; known: exact (each controller a process "
                 "over a pipe), native (the controllers in the simulator's process, built with "
                 "`openswarm build --native --port epuck_world`)");
        e.native = f == "native";
    }
    return e;
}

fs::path native_program(const fs::path &program) {
    if (program.extension() == ".so") return program;
    fs::path folder = program.parent_path();
    return folder.parent_path() / (folder.filename().string() + "-native") / (program.filename().string() + ".so");
}

std::string trial_world(const Experiment &e, uint32_t seed, const fs::path &program) {
    json world = {{"robot", "epuck"},
                  {"arena", {{"width_mm", e.width_mm}, {"height_mm", e.height_mm}}},
                  {"seed", seed},
                  {"duration_s", e.duration_s},
                  {"sample_period_s", e.sample_period_s}};
    if (e.native) world["fidelity"] = "native";
    json objects = json::array();
    for (int k = 0; k < e.objects; k++)
        objects.push_back({{"radius_mm", e.object_radius_mm}, {"mass_g", e.object_mass_g}, {"friction", e.object_friction}});
    world["objects"] = objects;
    world["robots"] = json::array({{{"count", e.robots}, {"firmware", fs::absolute(program).string()}}});
    place_on_marks(world, {e.columns, e.rows, e.spacing_mm}, seed);
    return world.dump(2) + "\n";
}

}  // namespace openswarm
