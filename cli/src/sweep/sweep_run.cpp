#include "sweep_run.hpp"

#include <atomic>
#include <csignal>
#include <chrono>
#include <cmath>
#include <ctime>
#include <map>
#include <fstream>
#include <mutex>
#include <optional>
#include <thread>

#include "../app_config.hpp"
#include "../duration_text.hpp"
#include "../commands/build.hpp"
#include "../commands/commands.hpp"
#include "../process.hpp"
#include "../results_folder.hpp"
#include "../trial_outcome.hpp"
#include "sweep_plot.hpp"
#include "sweep_results.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace openswarm {

namespace {

// "K/N" into which trials are this shard's; false after a message.
bool parse_shard(const std::string &text, size_t &k, size_t &n) {
    k = 0;
    n = 1;
    if (text.empty()) return true;
    unsigned long a = 0, b = 0;
    char end = 0;
    if (std::sscanf(text.c_str(), "%lu/%lu%c", &a, &b, &end) == 2 && b >= 1 && b <= 100000 && a < b) {
        k = a;
        n = b;
        return true;
    }
    report("--shard " + text + ": give K/N, this shard's number K from 0 and the number of shards N, "
           "e.g. --shard $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT with --array=0-(N-1)");
    return false;
}

// The trial runs another program of the app's build than its image (a
// sweep's "program": the case study's plain loop); false after saying
// that the build makes no such program.
bool select_program(const Sweep &s, const std::string &program, SweepTrial &t) {
    // The native build's programs are shared objects beside the app's, the
    // QEMU build's e-puck2 images.
    const fs::path image = t.firmware.extension();
    const std::string suffix =
        (image == ".so" || image == ".elf") && fs::path(program).extension() != image ? image.string() : "";
    fs::path file = t.firmware.parent_path() / (program + suffix);
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) {
        report(s.file.string() + ": \"program\": the app's build made no " + file.string() +
               ": give the name of a program its CMakeLists.txt builds for this port (" +
               t.firmware.filename().string() + " is the app's own), or build it first");
        exit_code = EXIT_USAGE;
        return false;
    }
    t.firmware = file;
    t.firmware_hash = file_fingerprint(file);
    return true;
}

// The build a point's world's "fidelity" runs: the exact mode's image (an
// e-puck's host program), the native mode's shared object, or an e-puck's
// e-puck2 image under QEMU; nullopt after saying why a point cannot have it.
std::optional<Variant> fidelity_variant(const Sweep &s, const AppConfig &config, size_t point) {
    const json world = point_world(s, point, 0);
    const std::string fidelity = world.value("fidelity", "exact");
    if (fidelity == "native") return Variant::native;
    if (fidelity != "qemu") return Variant::release;
    if (config.port != "epuck_world" || world.value("robot", "kilobot") != "epuck") {
        report(s.file.string() + ": \"fidelity\": \"qemu\" (" + point_label(s, point) + ") runs e-pucks' e-puck2 "
               "images under QEMU, and " + s.app.string() + " is a " + config.port + " app in a world of " +
               world.value("robot", "kilobot") + "s: a Kilobot app's sweep takes \"exact\" (simavr) and "
               "\"native\"; drop \"qemu\" from the file's \"fidelity\" values");
        exit_code = EXIT_USAGE;
        return std::nullopt;
    }
    if (!find_program("qemu-system-arm")) {
        report(s.file.string() + ": \"fidelity\": \"qemu\" (" + point_label(s, point) + ") runs the robots in "
               "QEMU, and qemu-system-arm was not found: sudo apt-get install qemu-system-arm (or OpenSwarm's "
               "./setup.sh)");
        exit_code = EXIT_FAILED;
        return std::nullopt;
    }
    return Variant::qemu;
}

// The app built once for each fidelity its points run in (the exact
// mode's image, the native mode's shared object) and each set of its
// parameters the points give (a folder each, kept: a resumed sweep
// builds nothing again), each trial given its image and the image's
// fingerprint; false after the build said why.
bool build_images(const Sweep &s, const Paths &paths, std::vector<SweepTrial> &trials) {
    AppConfig config;
    try {
        config = load_app_config(s.app);
    } catch (const ConfigError &err) {
        report(err.what());
        exit_code = EXIT_USAGE;
        return false;
    }
    if (config.port != "kilobot" && config.port != "epuck_world") {
        report(s.app.string() + ": a " + config.port + " app; a sweep runs apps for the world simulator, a "
               "Kilobot's or an e-puck's (\"port\": \"kilobot\" or \"epuck_world\" in its openswarm.json): give "
               "such an app's \"app\"");
        exit_code = EXIT_USAGE;
        return false;
    }
    using Build = std::pair<Variant, ParameterValues>; // the fidelity's build, the parameters
    std::vector<Build> of_point(s.points.size());
    for (size_t p = 0; p < s.points.size(); p++) {
        auto variant = fidelity_variant(s, config, p);
        if (!variant) return false;
        of_point[p] = {*variant, point_parameters(s, p)};
    }
    std::map<Build, std::pair<fs::path, std::string>> built; // the image and its fingerprint
    for (SweepTrial &t : trials) {
        const Build &b = of_point[t.point];
        auto it = built.find(b);
        if (it == built.end()) {
            auto image = build_app(paths, s.app, "", Progress::brief, b.first, false, b.second);
            if (!image) return false;
            it = built.emplace(b, std::make_pair(image->image, file_fingerprint(image->image))).first;
        }
        t.firmware = it->second.first;
        t.firmware_hash = it->second.second;
        t.parameters = b.second;
        if (!point_program(s, t.point).empty() && !select_program(s, point_program(s, t.point), t)) return false;
    }
    return true;
}

// What ran, with what, when: beside the results, for whoever reads them.
void write_provenance(const Sweep &s, const Paths &paths, const std::vector<SweepTrial> &trials,
                      const fs::path &out, const std::string &command) {
    std::ofstream f(out / "command.txt");
    std::time_t now = std::time(nullptr);
    char when[64];
    std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&now));
    f << "command: " << command << "\n"
      << "started: " << when << "\n"
      << "openswarm: " << OPENSWARM_VERSION << " (" << paths.root.string() << ")\n"
      << "simulator: " << paths.simulator.string() << "\n"
      << "sweep: " << fs::absolute(s.file).string() << " (" << file_fingerprint(s.file) << ")\n"
      << "world: " << s.world.string() << " (" << file_fingerprint(s.world) << ")\n";
    std::vector<fs::path> seen;
    for (const SweepTrial &t : trials)
        if (std::find(seen.begin(), seen.end(), t.firmware) == seen.end()) {
            seen.push_back(t.firmware);
            f << "firmware: " << t.firmware.string() << " (" << t.firmware_hash << ")\n";
        }
}

struct Tally {
    size_t done = 0, reused = 0, failed = 0;
    bool refused = false;
};

std::string first_metric(const SweepTrial &t) {
    auto series = read_trial_metrics(t.dir);
    for (const auto &m : series)
        if (!m.values.empty()) {
            char text[96];
            std::snprintf(text, sizeof text, "%s %.4g", m.metric.c_str(), m.values.back().second);
            return text;
        }
    return "measured";
}

// This process's trials on `workers` threads, a line as each ends; stops
// starting trials once the simulator refused a world (it will refuse the
// others alike).
Tally run_trials(const Sweep &s, const Paths &paths, std::vector<SweepTrial *> &mine, unsigned workers,
                 const std::string &who) {
    std::atomic<size_t> next{0};
    std::atomic<bool> stop{false};
    std::mutex print;
    Tally tally;
    auto began = std::chrono::steady_clock::now();
    auto work = [&] {
        for (size_t i; !stop && !interrupted() && (i = next++) < mine.size();) {
            SweepTrial &t = *mine[i];
            run_sweep_trial(s, paths.simulator, t);
            std::lock_guard<std::mutex> lock(print);
            if (t.pending) { // stopped by Ctrl-C or SIGTERM
                std::printf("[%sstopped] point %zu, trial %d: not run yet (interrupted)\n", who.c_str(), t.point + 1, t.trial + 1);
                continue;
            }
            tally.done++;
            tally.reused += t.reused;
            tally.failed += !t.failure.empty();
            if (t.refused && !stop.exchange(true)) tally.refused = true;
            double spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
            size_t ran = tally.done - tally.reused;
            std::string left = ran ? "about " + duration_text(spent / (double)ran * (double)(mine.size() - tally.done)) + " left"
                                   : "";
            std::printf("[%s%zu/%zu] point %zu, trial %d: %s; %zu failed, %s so far%s%s\n", who.c_str(), tally.done,
                        mine.size(), t.point + 1, t.trial + 1,
                        !t.failure.empty() ? "FAILED"
                        : t.remeasured     ? ("simulated before, measured again: " + first_metric(t)).c_str()
                        : t.reused         ? "done before"
                                           : first_metric(t).c_str(),
                        tally.failed, duration_text(spent).c_str(), left.empty() ? "" : ", ", left.c_str());
            if (!t.failure.empty()) std::printf("    %s: %s\n", t.dir.string().c_str(), t.failure.c_str());
            std::fflush(stdout);
        }
    };
    std::vector<std::thread> pool;
    for (unsigned w = 0; w < std::max(1u, std::min<unsigned>(workers, (unsigned)mine.size())); w++)
        pool.emplace_back(work);
    for (auto &t : pool) t.join();
    return tally;
}

// The summary's word on videos: how many trials have theirs.
std::string videos_made(const Sweep &s, const std::vector<SweepTrial> &trials) {
    if (!s.video.on) return "";
    size_t n = 0;
    std::error_code ec;
    for (const SweepTrial &t : trials) n += s.video.wanted(t.trial) && fs::is_regular_file(t.dir / "video.mp4", ec);
    return " (video.mp4 in " + std::to_string(n) + " of them)";
}

}  // namespace

int run_sweep(const SweepOptions &o, const Paths &paths, const Ranks &ranks) {
    Sweep s;
    try {
        s = load_sweep(o.file);
    } catch (const ConfigError &err) {
        report(err.what());
        return EXIT_USAGE;
    }
    if (o.trials) s.trials = o.trials;
    if (o.duration_s > 0) s.duration_s = o.duration_s;
    if (o.native) {
        for (const auto &p : s.parameters)
            if (p.path == "fidelity") {
                report("--native: " + o.file + " sweeps \"fidelity\" itself: leave --native out, or drop "
                       "\"fidelity\" from its points to run every one native");
                return EXIT_USAGE;
            }
        s.native = true;
    }
    s.video = o.video;
    size_t shard = 0, shards = 1;
    if (!parse_shard(o.shard, shard, shards)) return EXIT_USAGE;
    fs::path file(o.file);
    fs::path out = o.out.empty() ? file.parent_path() / (file.stem().string() + "-results") : fs::path(o.out);
    if (!prepare_results_folder(out, ranks)) return EXIT_USAGE;

    // Trial-major: every point's first trial before any second one, so a
    // world the simulator refuses shows at once, and an early stop leaves
    // every point measured.
    std::vector<SweepTrial> trials;
    int width_p = s.points.size() > 99 ? (int)std::to_string(s.points.size()).size() : 2;
    int width_t = s.trials > 99 ? (int)std::to_string(s.trials).size() : 2;
    for (int t = 0; t < s.trials; t++)
        for (size_t p = 0; p < s.points.size(); p++) {
            char name[64];
            std::snprintf(name, sizeof name, "point-%0*zu/trial-%0*d", width_p, p + 1, width_t, t + 1);
            SweepTrial trial;
            trial.point = p;
            trial.trial = t;
            trial.seed = s.seed + (uint32_t)t;
            trial.dir = out / name;
            trials.push_back(trial);
        }
    if (std::string why = simulator_problem(paths); !why.empty()) {
        report(why);
        return EXIT_FAILED;
    }
    // Rank 0 builds first: ranks building at once would share the build folder.
    if (ranks.rank() == 0 && !build_images(s, paths, trials)) return exit_code ? exit_code : EXIT_FAILED;
    ranks.barrier();
    if (ranks.rank() != 0 && !build_images(s, paths, trials)) return exit_code ? exit_code : EXIT_FAILED;

    std::vector<SweepTrial *> mine;
    for (size_t k = 0; k < trials.size(); k++)
        if (k % shards == shard && ranks.mine(k / shards)) mine.push_back(&trials[k]);
    unsigned cores = std::max(1u, std::thread::hardware_concurrency() / (unsigned)ranks.local_size());
    unsigned workers = o.jobs ? o.jobs : cores;
    if (ranks.rank() == 0) {
        write_provenance(s, paths, trials, out, o.file);
        std::printf("Sweeping %zu point%s x %d trial%s = %zu trials of %s%s, %u at a time%s, into %s\n",
                    s.points.size(), s.points.size() == 1 ? "" : "s", s.trials, s.trials == 1 ? "" : "s",
                    trials.size(), s.world.filename().string().c_str(),
                    shards > 1 ? (" (shard " + std::to_string(shard) + " of " + std::to_string(shards) + ": " +
                                  std::to_string(mine.size()) + " of them)").c_str() : "",
                    workers,
                    ranks.size() > 1 ? (" on each of " + std::to_string(ranks.size()) + " ranks").c_str() : "",
                    out.string().c_str());
        std::fflush(stdout);
    }
    auto began = std::chrono::steady_clock::now();
    pass_interrupts_on(); // Ctrl-C: the trials running stop, the rest wait for the next run
    Tally tally = run_trials(s, paths, mine, workers,
                             ranks.size() > 1 ? "rank " + std::to_string(ranks.rank()) + " " : "");
    ranks.barrier();
    if (ranks.rank() != 0)
        return interrupted() ? 128 + interrupted() : tally.refused ? EXIT_USAGE : tally.failed ? EXIT_FAILED : EXIT_OK;

    // Every trial as its folder tells, wherever it ran.
    size_t pending = 0, failed = 0;
    for (SweepTrial &t : trials) {
        if (!t.attempted) read_sweep_trial(t);
        if (t.failure.empty()) t.series = read_trial_metrics(t.dir);
        pending += t.pending;
        failed += !t.pending && !t.failure.empty();
    }
    std::string why;
    std::vector<fs::path> plots;
    bool written = write_sweep_results(s, trials, out, why) && write_sweep_plots(s, trials, out, plots, why);
    std::printf("\n");
    print_sweep_summary(s, trials, stdout);
    if (!written) report("cannot write the results into " + out.string() + ": " + why);
    double spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    std::printf("\n%zu of %zu trials done (%zu by an earlier run), %zu failed%s, in %s: %s, %s, %s, %zu plot%s in "
                "%s; each trial's folder under %s%s\n",
                trials.size() - pending - failed, trials.size(), tally.reused, failed,
                pending ? (", " + std::to_string(pending) + " not run yet").c_str() : "",
                duration_text(spent).c_str(), (out / "results.csv").string().c_str(),
                (out / "summary.csv").string().c_str(), (out / "trials.csv").string().c_str(), plots.size(),
                plots.size() == 1 ? "" : "s", (out / "plots").string().c_str(), out.string().c_str(),
                videos_made(s, trials).c_str());
    if (interrupted()) {
        report(std::string("interrupted by ") + (interrupted() == SIGINT ? "SIGINT" : "SIGTERM") + ": " +
               std::to_string(pending) + " trial" + (pending == 1 ? "" : "s") + " not run yet (trials.csv: pending); "
               "the results above are of those done. Run the same command again to resume: finished trials are kept");
        return 128 + interrupted();
    }
    if (tally.refused) {
        report("the simulator refused a trial's world (its message is above): fix the sweep's parameters or the "
               "world, then run the same command again; finished trials are kept");
        return EXIT_USAGE;
    }
    if (failed) {
        report(std::to_string(failed) + " trial" + (failed == 1 ? "" : "s") + " failed (trials.csv says why); the " +
               "others are kept: run the same command again to retry only those");
        return EXIT_FAILED;
    }
    return written ? EXIT_OK : EXIT_FAILED;
}

}  // namespace openswarm
