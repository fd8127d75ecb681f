#include "sweep_trial.hpp"

#include <fstream>

#include "../fingerprint.hpp"
#include "../last_lines.hpp"
#include "../metrics/metrics_error.hpp"
#include "../metrics/run_metrics.hpp"
#include "../process.hpp"
#include "../trial_outcome.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace openswarm {

namespace {

// The last lines of what the simulator said: why it failed.
std::string tail(const std::string &output, size_t lines) {
    std::string said;
    for (const std::string &line : last_lines(output, lines)) said += (said.empty() ? "" : "\n") + line;
    return said;
}

// What the metrics of a trial depend on besides its outputs: the metrics
// asked for, the scripts' text, the spacing of values.
std::string measures_fingerprint(const Sweep &s) {
    std::string all;
    for (const auto &m : s.metrics) all += m + "\n";
    for (const auto &script : s.scripts) all += script.string() + " " + file_fingerprint(script) + "\n";
    return fingerprint(all + std::to_string(s.every_s));
}

struct Fingerprints {
    std::string world, measures;
};

// Written last (trial_outcome.hpp). simulated: the simulator's part went
// well (a failure was the measuring's).
// video: what the trial's video.mp4 was made with ("" for none).
void write_trial_outcome(const SweepTrial &t, const Fingerprints &f, bool simulated, const std::string &video) {
    json outcome = {{"status", t.failure.empty() ? "done" : "failed"},
                    {"simulated", simulated},
                    {"seed", t.seed},
                    {"world", f.world},
                    {"firmware", t.firmware_hash},
                    {"parameters", t.parameters},
                    {"measures", f.measures}};
    if (!t.failure.empty()) outcome["reason"] = t.failure;
    if (!video.empty()) outcome["video"] = video;
    write_outcome(t.dir, outcome);
}

// The simulator ran this world with this firmware before, and its outputs
// (with the video asked for now) are there to measure.
bool simulated_before(const Sweep &s, const SweepTrial &t, const json &outcome, const Fingerprints &f) {
    return outcome.value("simulated", false) && outcome.value("world", "") == f.world &&
           outcome.value("firmware", "") == t.firmware_hash && !s.video.missing(t.trial, t.dir, outcome);
}

void measure(const Sweep &s, SweepTrial &t) {
    MetricsRequest request{t.dir, {}, s.metrics, s.scripts, s.every_s};
    try {
        MetricsOutcome outcome = measure_run(request);
        write_metrics_csv(outcome.results, t.dir / "metrics.csv");
    } catch (const MetricsError &e) {
        t.failure = std::string("measuring it: ") + e.what();
    }
}

}  // namespace

// Stopped by Ctrl-C or SIGTERM (the simulator's or a metric script's
// run, or the tool's): pending, not failed; its outcome stays unwritten,
// so the same command runs it again.
bool stopped(SweepTrial &t, int status) {
    if (!interrupted_status(status) && interrupted() == 0) return false;
    t.pending = true;
    t.failure = "not run yet";
    forget_outcome(t.dir);
    return true;
}

void run_sweep_trial(const Sweep &s, const fs::path &simulator, SweepTrial &t) {
    t.attempted = true;
    const json point = point_world(s, t.point, t.trial);
    const std::string world = point.dump(2) + "\n";
    // The app's parameters with the world (none: the world's alone, as
    // before there were any, so earlier sweeps resume).
    const std::string parameters = t.parameters.empty() ? "" : "parameters " + json(t.parameters).dump() + "\n";
    const Fingerprints f{fingerprint(world + parameters), measures_fingerprint(s)};
    const json before = read_outcome(t.dir);
    std::error_code ec;
    if (simulated_before(s, t, before, f)) {
        t.reused = true;
        if (before.value("status", "") == "done" && before.value("measures", "") == f.measures &&
            fs::is_regular_file(t.dir / "metrics.csv", ec))
            return;
        t.remeasured = true;
        measure(s, t);
        if (!t.failure.empty() && stopped(t, 0)) return;
        write_trial_outcome(t, f, true, before.value("video", ""));
        return;
    }
    forget_outcome(t.dir);
    fs::create_directories(t.dir, ec);
    if (ec) {
        t.failure = "cannot create the trial's folder " + t.dir.string() + ": " + ec.message();
        return;
    }
    if (!write_text(t.dir / "world.json", world)) {
        t.failure = "cannot write " + (t.dir / "world.json").string() + " (the disk full?)";
        return;
    }
    if (!s.video.wanted(t.trial)) fs::remove(t.dir / "video.mp4", ec); // an earlier run's, of another world
    std::vector<std::string> command{simulator.string(), "--quiet",   "--no-progress", "--world",
                                     (t.dir / "world.json").string(), "--out", t.dir.string()};
    // e-pucks' controllers print to the simulator's standard error; the
    // console's CSV is the Kilobots' (openswarm-sim refuses it beside e-pucks).
    const bool epucks = point.value("robot", "") == "epuck";
    if (!epucks) command.insert(command.end(), {"--console-csv", (t.dir / "console.csv").string()});
    for (const std::string &option : s.video.arguments(t.trial)) command.push_back(option);
    command.push_back(t.firmware.string());
    std::string output;
    int status = capture_program_and_errors(command, output);
    if (status != 0 && stopped(t, status)) return;
    if (status != 0) {
        t.refused = status == 2;
        std::string said = tail(output, 12);
        // An e-puck world's 3 is a controller (a program, or QEMU) that
        // ended, hung or answered nonsense, not a crashed Kilobot firmware.
        t.failure = (status == 2              ? "the simulator refused the trial's world.json"
                     : status == 3 && epucks ? "an e-puck's controller failed (the simulator says which and how)"
                                             : simulator_failure(status)) +
                    (said.empty() ? "" : ":\n" + said);
    } else {
        measure(s, t);
        if (!t.failure.empty() && stopped(t, 0)) return;
    }
    write_trial_outcome(t, f, status == 0, status == 0 ? s.video.request(t.trial) : "");
}

void read_sweep_trial(SweepTrial &t) {
    json outcome = read_outcome(t.dir);
    std::string status = outcome.value("status", "");
    t.pending = status != "done" && status != "failed";
    t.failure = status == "done" ? "" : t.pending ? "not run yet" : outcome.value("reason", "failed");
}

std::vector<TrialSeries> read_trial_metrics(const fs::path &dir) {
    std::ifstream in(dir / "metrics.csv");
    std::string line;
    std::getline(in, line); // time_s,metric,robot,value
    std::vector<TrialSeries> series;
    while (std::getline(in, line)) {
        size_t a = line.find(','), b = line.find(',', a + 1), c = line.find(',', b + 1);
        if (c == std::string::npos || c != b + 1) continue; // a robot's own report
        std::string name = line.substr(a + 1, b - a - 1);
        size_t k = 0;
        while (k < series.size() && series[k].metric != name) k++;
        if (k == series.size()) series.push_back({name, {}});
        series[k].values.push_back({std::strtod(line.c_str(), nullptr), std::strtod(line.c_str() + c + 1, nullptr)});
    }
    return series;
}

}  // namespace openswarm
