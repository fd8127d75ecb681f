#include "run_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>

#include "../suggest.hpp"
#include "builtin_metrics.hpp"
#include "firmware_metrics.hpp"
#include "metrics_error.hpp"
#include "run_world.hpp"
#include "script_metrics.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

struct Measuring {
    std::unique_ptr<Metric> metric;
    size_t result; // its index in the outcome's results
};

RunWorld world_of(const MetricsRequest &r) {
    std::error_code ec;
    if (!r.world.empty()) {
        if (!fs::is_regular_file(r.world, ec))
            throw MetricsError("--world " + r.world.string() + ": no such file; give the world.json the run was in");
        return read_run_world(r.world);
    }
    fs::path own = r.run_dir / "world.json";
    return fs::is_regular_file(own, ec) ? read_run_world(own) : RunWorld{};
}

MetricResult result_of(const BuiltinMetric &m) { return {m.name, m.unit, m.doc, "built-in", {}, {}}; }

// An unknown --metric: what there is, and where firmware metrics come from.
[[noreturn]] void unknown_metric(const MetricRequest &q, const FirmwareReports &firmware, bool console_there,
                                 const fs::path &run_dir) {
    std::vector<std::string> names;
    for (const auto &m : builtin_metrics()) names.push_back(m.name);
    std::vector<std::string> reported;
    for (const auto &[name, reports] : firmware.by_name) reported.push_back(name);
    names.insert(names.end(), reported.begin(), reported.end());
    std::string where =
        console_there
            ? (reported.empty() ? "; its robots reported no metric in " + (run_dir / "console.csv").string()
                                : "; its robots reported " + join(reported))
            : "; metrics robots report (console lines \"metric NAME VALUE\") come from " +
                  (run_dir / "console.csv").string() +
                  ", which is not there: `openswarm run --world` writes it, openswarm-sim with --console-csv FILE";
    throw MetricsError("--metric " + q.text + ": no built-in metric of that name" + did_you_mean(q.name, names) +
                       where + " (`openswarm metrics --list` lists the built-ins)");
}

// The samples' times, and the last report's when it came after them.
std::vector<double> with_last_report(const std::vector<double> &times, const std::vector<FirmwareReport> &reports) {
    std::vector<double> at = times;
    double last = -INFINITY;
    for (const auto &p : reports) last = std::max(last, p.time_s);
    if (at.empty() || last > at.back()) at.push_back(last);
    return at;
}

// "NAME.settled_s" for a metric the robots reported as NAME.
bool is_settled_request(const MetricRequest &q, const FirmwareReports &firmware) {
    const std::string suffix = settled_suffix;
    if (q.name.size() <= suffix.size() || q.name.compare(q.name.size() - suffix.size(), suffix.size(), suffix) != 0)
        return false;
    if (!firmware.by_name.count(q.name.substr(0, q.name.size() - suffix.size()))) return false;
    if (!q.arguments.empty())
        throw MetricsError("--metric " + q.text + ": " + q.name + " takes no arguments; give --metric " + q.name);
    return true;
}

MetricResult settled_result(const std::string &name, const FirmwareReports &firmware, const std::vector<double> &times,
                            const std::vector<size_t> &robots) {
    const std::string of = name.substr(0, name.size() - std::string(settled_suffix).size());
    MetricResult r{name, "s",
                   "the time since which every robot holds the value it last reported as \"metric " + of +
                       " VALUE\" (none until every robot has reported)",
                   "firmware", {}, {}};
    const auto &reports = firmware.by_name.at(of);
    std::vector<double> at = with_last_report(times, reports);
    std::vector<size_t> counts = robots;
    counts.resize(at.size(), robots.empty() ? 0 : robots.back()); // as many after the last sample
    std::vector<double> settled = firmware_settled_at(reports, at, counts);
    for (size_t k = 0; k < at.size(); k++)
        if (std::isfinite(settled[k])) r.swarm.push_back({at[k], settled[k]});
    return r;
}

}  // namespace

MetricsOutcome measure_run(const MetricsRequest &request) {
    std::error_code ec;
    if (!fs::is_directory(request.run_dir, ec))
        throw MetricsError(request.run_dir.string() + ": no such folder; give the --out folder of a run in a world "
                           "(`openswarm run --world FILE` writes <app>/out/<world>/)");
    RunWorld world = world_of(request);
    fs::path console = request.run_dir / "console.csv";
    bool console_there = fs::is_regular_file(console, ec);
    FirmwareReports firmware = read_firmware_reports(console);

    MetricsOutcome outcome;
    outcome.notes = firmware.warnings;
    std::vector<Measuring> measuring;
    std::vector<std::string> from_firmware, settled;
    bool with_objects = false, with_ir = false;
    auto measure = [&](const BuiltinMetric &m, const MetricRequest &q) {
        measuring.push_back({make_builtin_metric(m, q, world, request.run_dir), outcome.results.size()});
        outcome.results.push_back(result_of(m));
        with_objects |= m.needs == MetricNeeds::objects;
        with_ir |= m.needs == MetricNeeds::ir;
    };
    if (request.metrics.empty()) {
        for (const auto &m : builtin_metrics()) {
            std::string why = builtin_metric_unavailable(m, world, request.run_dir);
            if (why.empty()) measure(m, {m.name, {}, m.name});
            else outcome.notes.push_back(m.name + " left out: " + why);
        }
        for (const auto &[name, reports] : firmware.by_name) from_firmware.push_back(name);
    } else {
        std::set<std::string> asked;
        for (const auto &text : request.metrics) {
            MetricRequest q = parse_metric_request(text);
            if (!asked.insert(q.name).second)
                throw MetricsError("--metric " + q.name + " is given twice; give each metric once");
            if (const BuiltinMetric *m = find_builtin_metric(q.name)) {
                measure(*m, q);
            } else if (is_settled_request(q, firmware)) {
                settled.push_back(q.name);
            } else if (firmware.by_name.count(q.name)) {
                if (!q.arguments.empty())
                    throw MetricsError("--metric " + q.text + ": " + q.name +
                                       " is reported by the robots, and takes no arguments; give --metric " + q.name);
                from_firmware.push_back(q.name);
            } else {
                unknown_metric(q, firmware, console_there, request.run_dir);
            }
        }
    }

    // The samples, one at a time.
    std::vector<double> times;
    std::vector<size_t> robots_at; // the robots at each time kept
    SnapshotReader reader(request.run_dir, with_objects, with_ir);
    Snapshot s;
    double next_due = -INFINITY;
    while (reader.next(s)) {
        for (auto &m : measuring) m.metric->see(s);
        if (!(s.time_s >= next_due - 1e-9) && !reader.done()) continue;
        next_due = s.time_s + request.every_s;
        times.push_back(s.time_s);
        robots_at.push_back(s.robots.size());
        for (auto &m : measuring) {
            double v = m.metric->value(s);
            if (std::isfinite(v)) outcome.results[m.result].swarm.push_back({s.time_s, v});
        }
    }
    if (times.empty() && !measuring.empty())
        throw MetricsError((request.run_dir / "trajectories.csv").string() +
                           ": no samples; the run ended before its first one (run it for longer)");

    for (const auto &name : from_firmware) {
        const auto &reports = firmware.by_name.at(name);
        MetricResult r{name, "", "the robots' mean, reported as \"metric " + name + " VALUE\"", "firmware", {}, {}};
        std::vector<double> at = with_last_report(times, reports);
        FirmwareMean mean = firmware_mean_at(reports, at);
        for (size_t k = 0; k < at.size(); k++)
            if (std::isfinite(mean.mean[k])) r.swarm.push_back({at[k], mean.mean[k]});
        for (const auto &p : reports) r.robots[p.robot].push_back({p.time_s, p.value});
        outcome.results.push_back(r);
    }

    for (const auto &name : settled) outcome.results.push_back(settled_result(name, firmware, times, robots_at));

    std::set<std::string> taken;
    for (const auto &r : outcome.results) taken.insert(r.name);
    double end = times.empty() ? NAN : times.back();
    for (const auto &script : request.scripts) {
        std::map<std::string, size_t> mine;
        for (const auto &v : run_metric_script(script, request.run_dir, world.file)) {
            if (!mine.count(v.name)) {
                if (taken.count(v.name))
                    throw MetricsError("metric script " + script.string() + " prints " + v.name +
                                           ", which another metric of this run is called already; name it otherwise",
                                       false);
                taken.insert(v.name);
                mine[v.name] = outcome.results.size();
                outcome.results.push_back({v.name, "", "printed by " + script.string(), "script " + script.string(), {}, {}});
            }
            outcome.results[mine[v.name]].swarm.push_back({std::isnan(v.time_s) ? end : v.time_s, v.value});
        }
        // In time order whatever order it printed them in; a time not known
        // (no samples) last.
        for (const auto &[name, k] : mine)
            std::stable_sort(outcome.results[k].swarm.begin(), outcome.results[k].swarm.end(),
                             [](const MetricPoint &a, const MetricPoint &b) {
                                 return !std::isnan(a.time_s) && (std::isnan(b.time_s) || a.time_s < b.time_s);
                             });
    }
    return outcome;
}

}  // namespace openswarm
