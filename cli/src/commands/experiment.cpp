// openswarm experiment FILE: trials of controllers in generated worlds, in
// parallel, with the clustering metrics over time, a plot and a summary
// (docs/case-study.md).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cmath>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "../app_config.hpp"
#include "../duration_text.hpp"
#include "../fingerprint.hpp"
#include "../metrics/object_clusters.hpp"
#include "../experiment_curves.hpp"
#include "../experiment_plot.hpp"
#include "../experiment_ranks.hpp"
#include "../experiment_spec.hpp"
#include "../process.hpp"
#include "../results_folder.hpp"
#include "../trial_outcome.hpp"
#include "../sweep/sweep_run.hpp"
#include "../sweep/sweep_spec.hpp"
#include "../suggest.hpp"
#include "commands.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

struct ExperimentOptions {
    std::string file;
    std::string shard; // sweeps only
    std::string out; // default: <file's folder>/<file's stem>-results
    unsigned jobs = 0;
    int trials = 0;         // 0: the file's
    double duration_s = 0;  // 0: the file's
    bool native = false;    // --native: as the file's "fidelity": "native"
    TrialVideo video;       // --video, --video-fps, --video-speed, --video-trials
};

struct Job {
    int trial;
    size_t controller;
    uint32_t seed;
    fs::path dir;
    std::vector<Sample> samples;
    std::string failure; // empty when it ran; not_run_yet when stopped
    bool reused = false; // done by an earlier run of the same command
};

// A trial stopped by Ctrl-C or SIGTERM: pending, not failed (the same
// command runs it again).
const char *const not_run_yet = "not run yet (interrupted)";

bool pending(const Job &j) { return j.failure == not_run_yet; }

// objects.csv (time_s,object,x_mm,y_mm) to the metrics at each time.
std::vector<Sample> metrics_of(const fs::path &objects_csv, double radius_mm) {
    std::ifstream in(objects_csv);
    std::string line;
    std::getline(in, line); // header
    std::map<double, std::vector<ObjectPosition>> at;
    while (std::getline(in, line)) {
        double t, x, y;
        int k;
        if (std::sscanf(line.c_str(), "%lf,%d,%lf,%lf", &t, &k, &x, &y) == 4) at[t].push_back({x, y});
    }
    std::vector<Sample> samples;
    for (const auto &[t, objects] : at)
        samples.push_back({t, largest_cluster_fraction(objects, radius_mm), compactness(objects, radius_mm)});
    return samples;
}

// What the trial runs: its world's text and the controller's bytes, as
// its outcome.json records them (trial_outcome.hpp).
nlohmann::json fingerprints_of(const std::string &world, const fs::path &program) {
    return {{"world", fingerprint(world)}, {"controller", file_fingerprint(program)}};
}

// The trial's samples when an earlier run of the same command did it, in
// the same world with the same controller.
bool done_before(Job &job, const nlohmann::json &fingerprints, double radius_mm, const TrialVideo &video) {
    nlohmann::json before = read_outcome(job.dir);
    if (before.value("status", "") != "done" || before.value("world", "") != fingerprints["world"] ||
        before.value("controller", "") != fingerprints["controller"] || video.missing(job.trial, job.dir, before))
        return false;
    job.samples = metrics_of(job.dir / "objects.csv", radius_mm);
    job.reused = !job.samples.empty();
    return job.reused;
}

void run_job(const Experiment &e, const Paths &paths, const TrialVideo &video, Job &job) {
    const ExperimentController &c = e.controllers[job.controller];
    const std::string world = trial_world(e, job.seed, c.program);
    nlohmann::json outcome = fingerprints_of(world, c.program);
    if (done_before(job, outcome, e.object_radius_mm, video)) return;
    forget_outcome(job.dir);
    std::error_code ec;
    fs::create_directories(job.dir, ec);
    if (ec) {
        job.failure = "cannot create the trial's folder " + job.dir.string() + ": " + ec.message();
        return;
    }
    if (!write_text(job.dir / "world.json", world)) {
        job.failure = "cannot write " + (job.dir / "world.json").string() + " (the disk full?)";
        return;
    }
    if (!video.wanted(job.trial)) fs::remove(job.dir / "video.mp4", ec); // an earlier run's, of another world
    std::vector<std::string> command{paths.simulator.string(), "--quiet", "--no-progress", "--world",
                                     (job.dir / "world.json").string(), "--out", job.dir.string()};
    for (const std::string &option : video.arguments(job.trial)) command.push_back(option);
    std::string output;
    int status = capture_program_and_errors(command, output);
    if (status != 0 && (interrupted_status(status) || interrupted() != 0)) {
        job.failure = not_run_yet; // no outcome.json: the next run does it
        return;
    }
    if (status != 0) {
        job.failure = simulator_failure(status) + ":\n" + output;
    } else {
        job.samples = metrics_of(job.dir / "objects.csv", e.object_radius_mm);
        if (job.samples.empty()) job.failure = "no objects.csv samples in " + job.dir.string();
    }
    outcome["status"] = job.failure.empty() ? "done" : "failed";
    if (!job.failure.empty()) outcome["reason"] = job.failure;
    if (status == 0 && video.wanted(job.trial)) outcome["video"] = video.request(job.trial);
    write_outcome(job.dir, outcome);
}

// Which rank runs a job: trial and controller both rotate the ranks, so
// each gets its share of every controller (some are much slower).
size_t slot_of(const Job &j) { return (size_t)j.trial + j.controller; }

// This rank's jobs shared out among workers; progress after each, with the
// time left.
void run_all(const Experiment &e, const Paths &paths, const TrialVideo &video, std::vector<Job> &jobs,
             const Ranks &ranks, unsigned workers) {
    std::vector<size_t> mine;
    for (size_t k = 0; k < jobs.size(); k++)
        if (ranks.mine(slot_of(jobs[k]))) mine.push_back(k);
    std::atomic<size_t> next{0};
    std::mutex print;
    size_t done = 0;
    const std::string who = ranks.size() > 1 ? "rank " + std::to_string(ranks.rank()) + " " : "";
    auto began = std::chrono::steady_clock::now();
    auto work = [&] {
        for (size_t i; !interrupted() && (i = next++) < mine.size();) {
            size_t k = mine[i];
            run_job(e, paths, video, jobs[k]);
            std::lock_guard<std::mutex> lock(print);
            if (pending(jobs[k])) {
                std::printf("[%sstopped] %s, trial %d: %s\n", who.c_str(),
                            e.controllers[jobs[k].controller].name.c_str(), jobs[k].trial + 1, not_run_yet);
                continue;
            }
            done++;
            double spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
            const Job &j = jobs[k];
            std::printf("[%s%zu/%zu] %s, trial %d: %s%s; about %s left\n", who.c_str(), done, mine.size(),
                        e.controllers[j.controller].name.c_str(), j.trial + 1, j.reused ? "done before, " : "",
                        j.failure.empty()
                            ? ("largest cluster " + std::to_string((int)std::lround(j.samples.back().cluster * 100)) +
                               "% at " + duration_text(j.samples.back().time_s)).c_str()
                            : "FAILED",
                        duration_text(spent / (double)done * (double)(mine.size() - done)).c_str());
            std::fflush(stdout);
        }
    };
    std::vector<std::thread> pool;
    for (unsigned w = 0; w < workers; w++) pool.emplace_back(work);
    for (auto &t : pool) t.join();
}

// Every job's samples and failure on rank 0, wherever it ran.
void gather(const Ranks &ranks, std::vector<Job> &jobs) {
    std::vector<TrialOutcome> outcomes(jobs.size());
    for (size_t k = 0; k < jobs.size(); k++) {
        for (const Sample &s : jobs[k].samples)
            outcomes[k].samples.insert(outcomes[k].samples.end(), {s.time_s, s.cluster, s.compactness});
        outcomes[k].failure = jobs[k].failure;
        outcomes[k].here = ranks.mine(slot_of(jobs[k]));
    }
    ranks.gather(outcomes);
    for (size_t k = 0; k < jobs.size(); k++) {
        if (outcomes[k].here) continue;
        jobs[k].samples.clear();
        const auto &v = outcomes[k].samples;
        for (size_t i = 0; i + 3 <= v.size(); i += 3) jobs[k].samples.push_back({v[i], v[i + 1], v[i + 2]});
        jobs[k].failure = outcomes[k].failure;
    }
}

bool write_results(const Experiment &e, const std::vector<Job> &jobs, const fs::path &out) {
    std::ofstream csv(out / "results.csv");
    csv << "trial,controller,seed,time_s,largest_cluster,compactness\n";
    char row[256];
    for (const Job &j : jobs)
        for (const Sample &s : j.samples) {
            std::snprintf(row, sizeof row, "%d,%s,%u,%.3f,%.4f,%.4f\n", j.trial + 1,
                          e.controllers[j.controller].name.c_str(), j.seed, s.time_s, s.cluster,
                          s.compactness);
            csv << row;
        }
    return (bool)csv;
}

// Mean and standard deviation over a controller's trials, sample by sample.
std::vector<ControllerCurves> curves_of(const Experiment &e, const std::vector<Job> &jobs) {
    std::vector<ControllerCurves> curves;
    for (size_t c = 0; c < e.controllers.size(); c++) {
        std::vector<const std::vector<Sample> *> ran;
        for (const Job &j : jobs)
            if (j.controller == c && j.failure.empty() && !j.samples.empty()) ran.push_back(&j.samples);
        curves.push_back(controller_curves(e.controllers[c].name, ran));
    }
    return curves;
}

// Every controller program must exist before hours of trials start.
bool programs_present(const Experiment &e) {
    for (const auto &c : e.controllers) {
        std::error_code ec;
        if (fs::is_regular_file(c.program, ec)) continue;
        report(e.file.string() + ": controller \"" + c.name + "\": " + c.program.string() +
               " does not exist: build it first (openswarm build --port epuck_world" +
               (e.native ? " --native" : "") + " in its app)");
        return false;
    }
    return true;
}

int run_experiment(const ExperimentOptions &o, const Paths &paths, const Ranks &ranks) {
    Experiment e;
    try {
        e = load_experiment(o.file);
    } catch (const ConfigError &err) {
        report(err.what());
        return EXIT_USAGE;
    }
    if (o.trials) e.trials = o.trials;
    if (o.duration_s > 0) e.duration_s = o.duration_s;
    e.native = e.native || o.native;
    if (e.native)
        for (auto &c : e.controllers) c.program = native_program(c.program);
    if (e.reference_time_s > e.duration_s) e.reference_fraction = -1; // off the plot
    std::string too_many = trial_rows_problem(e, o.duration_s > 0);
    if (!too_many.empty()) {
        report(too_many);
        return EXIT_USAGE;
    }
    if (!programs_present(e)) return EXIT_USAGE;
    if (std::string why = simulator_problem(paths); !why.empty()) {
        report(why);
        return EXIT_FAILED;
    }
    fs::path file(o.file);
    fs::path out = o.out.empty() ? file.parent_path() / (file.stem().string() + "-results") : fs::path(o.out);
    if (!prepare_results_folder(out, ranks)) return EXIT_USAGE;
    std::vector<Job> jobs;
    for (int t = 0; t < e.trials; t++)
        for (size_t c = 0; c < e.controllers.size(); c++) {
            char name[64];
            std::snprintf(name, sizeof name, "trial-%02d-", t + 1);
            jobs.push_back({t, c, e.seed + (uint32_t)t, out / (name + controller_folder(e.controllers[c].name)), {}, {}});
        }
    // Ranks on one machine share its cores.
    unsigned cores = std::max(1u, std::thread::hardware_concurrency() / (unsigned)ranks.local_size());
    unsigned workers = o.jobs ? o.jobs : cores;
    if (ranks.rank() == 0)
        std::printf("Running %zu trials (%d per controller, %zu controllers) of %s each, %u at a time%s, "
                    "into %s\n",
                    jobs.size(), e.trials, e.controllers.size(), duration_text(e.duration_s).c_str(),
                    workers,
                    ranks.size() > 1 ? (" on each of " + std::to_string(ranks.size()) + " ranks").c_str() : "",
                    out.string().c_str());
    std::fflush(stdout);
    auto began = std::chrono::steady_clock::now();
    pass_interrupts_on(); // Ctrl-C: the trials running stop, the rest wait for the next run
    run_all(e, paths, o.video, jobs, ranks, workers);
    gather(ranks, jobs);
    if (ranks.rank() != 0) return EXIT_OK;
    auto curves = curves_of(e, jobs);
    std::string why;
    bool written = write_results(e, jobs, out) && write_experiment_plot(e, curves, out, why);
    print_experiment_table(e, curves);
    size_t failed = 0, not_run = 0;
    for (const Job &j : jobs)
        if (pending(j) || (j.failure.empty() && j.samples.empty())) {
            not_run++; // stopped, or never started after the interrupt
        } else if (!j.failure.empty()) {
            failed++;
            report(e.controllers[j.controller].name + ", trial " + std::to_string(j.trial + 1) +
                   " (" + j.dir.string() + ") failed: " + j.failure);
        }
    double spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    if (!written) report("cannot write the results into " + out.string() + ": " + why);
    std::printf("\n%zu of %zu trials ran in %s: %s, %s and .svg, each trial's final.png and "
                "viewer.html%s\n",
                jobs.size() - failed - not_run, jobs.size(), duration_text(spent).c_str(),
                (out / "results.csv").string().c_str(), (out / "results.png").string().c_str(),
                o.video.on ? (o.video.trials.empty() ? ", video.mp4" : ", the trials asked for video.mp4") : "");
    if (interrupted()) {
        report(std::string("interrupted by ") + (interrupted() == SIGINT ? "SIGINT" : "SIGTERM") + ": " +
               std::to_string(not_run) + " trial" + (not_run == 1 ? "" : "s") + " not run yet; the results are "
               "of those done. Run the same command again to resume: finished trials are kept");
        return 128 + interrupted();
    }
    return failed || !written ? EXIT_FAILED : EXIT_OK;
}

}  // namespace

void add_experiment_command(CLI::App &app, const Paths &paths) {
    auto o = std::make_shared<ExperimentOptions>();
    CLI::App *cmd = app.add_subcommand(
        "experiment", "Run trials of controllers in worlds an experiment file describes, and compare them");
    cmd->add_option("file", o->file,
                    "the experiment: a sweep file (docs/experiments.md; its points' \"fidelity\": \"exact\", "
                    "\"native\", or \"qemu\" - an e-puck app's e-puck2 image under QEMU), or a clustering "
                    "experiment (docs/case-study.md), e.g. experiments/paper.json")
        ->required();
    cmd->add_option("-o,--out", o->out, "where the results go (default: next to FILE, <FILE's name>-results)");
    cmd->add_option("-j,--jobs", o->jobs, "trials run at once (default: one per core)")
        ->check(CLI::Range(1u, 1024u));
    cmd->add_option("--trials", o->trials, "trials per controller instead of the file's (a quick look)")
        ->check(CLI::Range(1, 10000));
    cmd->add_option("--duration", o->duration_s, "seconds a trial lasts instead of the file's")
        ->check(finite_seconds("--duration", 1, 86400, "600"));
    cmd->add_flag("--native", o->native,
                  "run the app or controllers built for the host, in the simulator's process (a sweep: every "
                  "point's world in \"fidelity\": \"native\"; a clustering experiment: each controller built with "
                  "`openswarm build --native --port epuck_world`, as the file's \"fidelity\": \"native\" asks)");
    cmd->add_option("--shard", o->shard,
                    "a sweep's K-th share of N (0-based), as a Slurm array task runs it: "
                    "--shard $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT")
        ->type_name("K/N");
    add_video_options(cmd, o->video);
    cmd->callback([o, &paths] {
        Ranks ranks;
        int status;
        try {
            if (is_sweep_file(o->file))
                status = run_sweep({o->file, o->out, o->jobs, o->trials, o->duration_s, o->shard, o->native, o->video},
                                   paths, ranks);
            else if (!o->shard.empty()) {
                report("--shard: for sweep files (a \"world\" and what to vary in it); " + o->file +
                       " is a clustering experiment: spread it with mpirun instead (docs/case-study.md)");
                status = EXIT_USAGE;
            } else
                status = run_experiment(*o, paths, ranks);
        } catch (const fs::filesystem_error &err) { // a last resort: each place above says more
            report(std::string("experiment: ") + err.what() + "; check the --out folder and the disk");
            status = EXIT_FAILED;
        }
        exit_code = ranks.agree(status);
    });
}

}  // namespace openswarm
