#include "builtin_metrics.hpp"

#include <cmath>
#include <cstdlib>

#include "../suggest.hpp"
#include "ir_measures.hpp"
#include "metrics_error.hpp"
#include "swarm_measures.hpp"

namespace openswarm {

namespace {

// A metric that is a function of one sample.
class SampleMetric : public Metric {
public:
    explicit SampleMetric(std::function<double(const Snapshot &)> f) : f_(std::move(f)) {}
    double value(const Snapshot &s) override { return f_(s); }

private:
    std::function<double(const Snapshot &)> f_;
};

class CoverageMetric : public Metric {
public:
    CoverageMetric(double width_mm, double height_mm, double cell_mm) : grid_(width_mm, height_mm, cell_mm) {}
    void see(const Snapshot &s) override { grid_.visit(s.robots); }
    double value(const Snapshot &) override { return grid_.fraction(); }

private:
    CoverageGrid grid_;
};

std::unique_ptr<Metric> per_sample(std::function<double(const Snapshot &)> f) {
    return std::make_unique<SampleMetric>(std::move(f));
}

// The objects' radius: the one they share, or the request's radius_mm.
double object_radius(const RunWorld &w, const MetricArguments &a, const std::string &name) {
    if (a.count("radius_mm")) return a.at("radius_mm");
    for (double r : w.object_radii_mm)
        if (r != w.object_radii_mm[0])
            throw MetricsError(name + ": the objects of " + w.file.string() +
                               " differ in size; give the radius to measure with, e.g. --metric " + name +
                               ":radius_mm=" + std::to_string((int)w.object_radii_mm[0]));
    return w.object_radii_mm[0];
}

// The mean over robots of one of ir.csv's counts.
BuiltinMetric ir_metric(const std::string &name, const std::string &doc, IrCount what) {
    return {name, "frames", doc, {}, MetricNeeds::ir, [what](const RunWorld &, const MetricArguments &) {
                return per_sample([what](const Snapshot &s) { return mean_ir_count(s.ir, what); });
            }};
}

std::vector<BuiltinMetric> make_catalogue() {
    const MetricArgument radius{"radius_mm", "the objects' radius (default: the world's objects')", 0, 0.001, 1e6};
    return {
        {"nearest_neighbour_mm", "mm",
         "mean over robots of the distance to the nearest other robot (centre to centre)",
         {}, MetricNeeds::robots,
         [](const RunWorld &, const MetricArguments &) {
             return per_sample([](const Snapshot &s) { return mean_nearest_neighbour_mm(s.robots); });
         }},
        {"largest_group", "share of robots",
         "share of robots in the largest group linked by neighbours at most range_mm apart",
         {{"range_mm", "link distance, centre to centre (default: the world's ir.range_mm, else 100)", 100, 1, 1e6}},
         MetricNeeds::robots,
         [](const RunWorld &w, const MetricArguments &a) {
             double range = a.count("range_mm") ? a.at("range_mm") : w.ir_range_mm;
             return per_sample([range](const Snapshot &s) { return largest_group_fraction(s.robots, range); });
         }},
        {"coverage", "share of cells",
         "share of the arena's cell_mm square cells a robot's centre has been in so far",
         {{"cell_mm", "the cells' side (default 50)", 50, 1, 1e6}}, MetricNeeds::arena,
         [](const RunWorld &w, const MetricArguments &a) -> std::unique_ptr<Metric> {
             double cell = a.count("cell_mm") ? a.at("cell_mm") : 50;
             double cells = std::ceil(w.arena_width_mm / cell) * std::ceil(w.arena_height_mm / cell);
             if (cells > 1e8)
                 throw MetricsError("coverage:cell_mm=" + std::to_string((int)cell) + ": " +
                                    std::to_string((long long)cells) + " cells in the arena, too many to keep; "
                                    "give larger cells, e.g. coverage:cell_mm=" +
                                    std::to_string((int)std::ceil(cell * std::sqrt(cells / 1e8))));
             return std::make_unique<CoverageMetric>(w.arena_width_mm, w.arena_height_mm, cell);
         }},
        {"light_distance_mm", "mm", "mean over robots of the distance to the nearest light source",
         {}, MetricNeeds::lights,
         [](const RunWorld &w, const MetricArguments &) {
             auto lights = w.lights;
             return per_sample([lights](const Snapshot &s) { return mean_light_distance_mm(s.robots, lights); });
         }},
        {"led_agreement", "share of robots",
         "share of robots showing the most common LED colour (off is a colour too)", {}, MetricNeeds::robots,
         [](const RunWorld &, const MetricArguments &) {
             return per_sample([](const Snapshot &s) { return led_agreement(s.robots); });
         }},
        {"largest_cluster", "share of objects",
         "share of objects in the largest cluster: objects whose rims are at most 10 mm apart "
         "(no e-puck passes between) are linked",
         {radius}, MetricNeeds::objects,
         [](const RunWorld &w, const MetricArguments &a) {
             double r = object_radius(w, a, "largest_cluster");
             return per_sample([r](const Snapshot &s) {
                 return s.objects.empty() ? NAN : largest_cluster_fraction(s.objects, r);
             });
         }},
        {"compactness", "",
         "the objects' sum of squared distances to their centroid over 4 r^2, lower is more compact "
         "(the OpenSwarm paper's eq. (2))",
         {radius}, MetricNeeds::objects,
         [](const RunWorld &w, const MetricArguments &a) {
             double r = object_radius(w, a, "compactness");
             return per_sample([r](const Snapshot &s) { return s.objects.empty() ? NAN : compactness(s.objects, r); });
         }},
        ir_metric("ir_sent", "mean over robots of the IR frames its firmware sent so far (its own counter)",
                  IrCount::sent),
        ir_metric("ir_received",
                  "mean over robots of the IR frames its firmware received so far (delivered to the app)",
                  IrCount::received),
        ir_metric("ir_lost",
                  "mean over robots of the frames robots in range sent so far that it did not receive "
                  "(lost on the way, in a collision, with a bad CRC, while it was sending...)",
                  IrCount::lost),
        ir_metric("ir_lost_channel",
                  "mean over robots of the frames robots in range sent so far that the channel lost on the way "
                  "(ir.loss_pct)",
                  IrCount::lost_channel),
    };
}

std::string number_text(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

}  // namespace

const std::vector<BuiltinMetric> &builtin_metrics() {
    static const std::vector<BuiltinMetric> catalogue = make_catalogue();
    return catalogue;
}

const BuiltinMetric *find_builtin_metric(const std::string &name) {
    for (const auto &m : builtin_metrics())
        if (m.name == name) return &m;
    return nullptr;
}

MetricRequest parse_metric_request(const std::string &text) {
    MetricRequest r;
    r.text = text;
    size_t colon = text.find(':');
    r.name = text.substr(0, colon);
    if (r.name.empty())
        throw MetricsError("--metric \"" + text + "\": no name; give NAME or NAME:key=value, e.g. "
                           "--metric largest_group:range_mm=80 (`openswarm metrics --list` lists them)");
    if (colon == std::string::npos) return r;
    std::string rest = text.substr(colon + 1);
    for (size_t start = 0; start <= rest.size();) {
        size_t comma = rest.find(',', start);
        std::string pair = rest.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        size_t eq = pair.find('=');
        char *end = nullptr;
        double v = eq == std::string::npos ? 0 : std::strtod(pair.c_str() + eq + 1, &end);
        if (eq == std::string::npos || eq == 0 || end == pair.c_str() + eq + 1 || *end != '\0' || !std::isfinite(v))
            throw MetricsError("--metric " + text + ": \"" + pair + "\" is not key=number; give e.g. --metric " +
                               r.name + ":range_mm=80");
        r.arguments[pair.substr(0, eq)] = v;
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return r;
}

std::unique_ptr<Metric> make_builtin_metric(const BuiltinMetric &m, const MetricRequest &request,
                                            const RunWorld &world, const std::filesystem::path &run_dir) {
    std::vector<std::string> keys;
    for (const auto &a : m.arguments) keys.push_back(a.key);
    for (const auto &[key, v] : request.arguments) {
        const MetricArgument *arg = nullptr;
        for (const auto &a : m.arguments)
            if (a.key == key) arg = &a;
        if (arg == nullptr)
            throw MetricsError("--metric " + request.text + ": " + m.name +
                               (keys.empty() ? " takes no arguments" : " takes " + join(keys) + ", not \"" + key +
                                                                           "\"" + did_you_mean(key, keys)));
        if (!(v >= arg->min && v <= arg->max))
            throw MetricsError("--metric " + request.text + ": " + key + " " + number_text(v) + " is out of range; give " +
                               number_text(arg->min) + ".." + number_text(arg->max));
    }
    // The objects' size given: objects.csv has the rest.
    bool sized = m.needs == MetricNeeds::objects && request.arguments.count("radius_mm");
    std::string why = sized ? "" : builtin_metric_unavailable(m, world, run_dir);
    if (!why.empty()) throw MetricsError(m.name + ": " + why);
    return m.make(world, request.arguments);
}

std::string builtin_metric_unavailable(const BuiltinMetric &m, const RunWorld &world,
                                       const std::filesystem::path &run_dir) {
    std::error_code ec;
    switch (m.needs) {
    case MetricNeeds::robots: return "";
    case MetricNeeds::ir:
        return std::filesystem::is_regular_file(run_dir / "ir.csv", ec)
                   ? ""
                   : "needs " + (run_dir / "ir.csv").string() +
                         ", which is not there: openswarm-sim --out writes it for a world of Kilobots (e-pucks "
                         "have no IR channel); run the world again";
    case MetricNeeds::arena:
        return world.known() ? "" : "needs the arena's size, and the run's folder has no world.json; give the "
                                    "world the run was in with --world FILE";
    case MetricNeeds::lights:
        if (!world.known())
            return "needs the lights, and the run's folder has no world.json; give the world the run was "
                   "in with --world FILE";
        return world.lights.empty() ? "the world " + world.file.string() + " has no light sources (light.sources)" : "";
    case MetricNeeds::objects:
        if (!world.known())
            return "needs the objects' size, and the run's folder has no world.json; give the world the run "
                   "was in with --world FILE";
        return world.object_radii_mm.empty() ? "the world " + world.file.string() + " has no objects" : "";
    }
    return "";
}

}  // namespace openswarm
