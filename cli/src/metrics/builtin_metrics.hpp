// The built-in metrics: each a name, a one-line doc, its unit, the
// arguments it takes (NAME:key=value,...) and what of the run it reads;
// measured sample by sample from the run's folder (run_snapshots.hpp).
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "run_snapshots.hpp"
#include "run_world.hpp"

namespace openswarm {

// One metric over one run, fed its samples in time order.
class Metric {
public:
    virtual ~Metric() = default;
    // Every sample, whether or not its value is asked for (coverage
    // remembers where robots have been).
    virtual void see(const Snapshot &) {}
    // The value at this sample (after see()); NaN when it has none.
    virtual double value(const Snapshot &s) = 0;
};

struct MetricArgument {
    std::string key, doc;
    double fallback; // used when neither the request nor the world gives one
    double min, max;
};

// What a metric reads besides trajectories.csv (ir: the run's ir.csv).
enum class MetricNeeds { robots, objects, lights, arena, ir };

using MetricArguments = std::map<std::string, double>;

struct BuiltinMetric {
    std::string name, unit, doc;
    std::vector<MetricArgument> arguments;
    MetricNeeds needs;
    // Throws MetricsError when the world does not allow it (no lights...).
    std::function<std::unique_ptr<Metric>(const RunWorld &, const MetricArguments &)> make;
};

const std::vector<BuiltinMetric> &builtin_metrics();
const BuiltinMetric *find_builtin_metric(const std::string &name);

// "NAME" or "NAME:key=value,key=value", as --metric takes it.
struct MetricRequest {
    std::string name;
    MetricArguments arguments;
    std::string text; // as given, for messages
};
// Throws MetricsError on a malformed request (not on an unknown name).
MetricRequest parse_metric_request(const std::string &text);

// The request's arguments checked against the metric's (unknown keys,
// ranges), then the metric made for this world. Throws MetricsError.
std::unique_ptr<Metric> make_builtin_metric(const BuiltinMetric &m, const MetricRequest &request,
                                            const RunWorld &world, const std::filesystem::path &run_dir);

// Why the run in run_dir cannot give the metric ("" if it can): no world
// known, no lights in it, no objects, no ir.csv.
std::string builtin_metric_unavailable(const BuiltinMetric &m, const RunWorld &world,
                                       const std::filesystem::path &run_dir);

}  // namespace openswarm
