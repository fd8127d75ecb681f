// openswarm metrics RUN_DIR: the built-in metrics, the ones the robots
// reported and the user's scripts' over one run's folder, as a table and
// a tidy CSV (docs/experiments.md, "Metrics").
#include <cmath>

#include "../metrics/builtin_metrics.hpp"
#include "../metrics/metrics_error.hpp"
#include "../metrics/run_metrics.hpp"
#include "commands.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

struct MetricsOptions {
    std::string run_dir;
    std::vector<std::string> metrics, scripts;
    std::string world, csv;
    std::string every = "0";
    bool list = false;
};

void print_list() {
    std::printf("Built-in metrics (--metric NAME or NAME:key=value,...), measured at every sample of "
                "trajectories.csv\n(objects.csv for the objects, ir.csv for the IR frames):\n\n");
    for (const auto &m : builtin_metrics()) {
        std::printf("  %-22s %s\n", m.name.c_str(), m.doc.c_str());
        for (const auto &a : m.arguments) std::printf("  %-22s   %s: %s\n", "", a.key.c_str(), a.doc.c_str());
    }
    std::printf("\nReported by the robots: a console line \"metric NAME VALUE\"; the mean over robots of each\n"
                "one's latest value, and each robot's own (needs console.csv in the run's folder).\n"
                "Your own: --script PATH runs PATH RUN_DIR, which prints NAME VALUE or TIME_S,NAME,VALUE lines.\n"
                "docs/experiments.md, \"Metrics\", says more.\n");
}

int measure(const MetricsOptions &o) {
    if (o.list) {
        print_list();
        return EXIT_OK;
    }
    if (o.run_dir.empty()) {
        report("give the folder of a run in a world, e.g. openswarm metrics out/packed (`openswarm run --world "
               "FILE` writes <app>/out/<world>/); --list shows the metrics");
        return EXIT_USAGE;
    }
    char *end;
    double every = std::strtod(o.every.c_str(), &end);
    if (*end != '\0' || end == o.every.c_str() || !(every >= 0 && every <= 1e6)) {
        report("--every " + o.every + ": give the seconds between two values, 0 (every sample) to 1000000, "
               "e.g. --every 5");
        return EXIT_USAGE;
    }
    MetricsRequest request{o.run_dir, o.world, o.metrics, {}, every};
    for (const auto &s : o.scripts) request.scripts.push_back(s);
    fs::path csv = o.csv.empty() ? fs::path(o.run_dir) / "metrics.csv" : fs::path(o.csv);
    try {
        MetricsOutcome outcome = measure_run(request);
        for (const auto &note : outcome.notes) report("note: " + note);
        print_metrics_table(outcome.results, stdout);
        write_metrics_csv(outcome.results, csv);
        std::printf("\nEvery value over time: %s (time_s,metric,robot,value)\n", csv.string().c_str());
    } catch (const MetricsError &e) {
        report(e.what());
        return e.bad_input ? EXIT_USAGE : EXIT_FAILED;
    }
    return EXIT_OK;
}

}  // namespace

void add_metrics_command(CLI::App &app, const Paths &) {
    auto o = std::make_shared<MetricsOptions>();
    CLI::App *cmd = app.add_subcommand(
        "metrics", "Measure a run in a world: built-in metrics, those its robots reported, your scripts'");
    cmd->add_option("run_dir", o->run_dir,
                    "the run's folder: its trajectories.csv, objects.csv, console.csv and world.json")
        ->type_name("RUN_DIR");
    cmd->add_option("-m,--metric", o->metrics,
                    "a built-in metric (NAME or NAME:key=value,...; --list shows them) or one the robots "
                    "reported; repeatable (default: every one the run allows)")
        ->type_name("NAME[:ARGS]");
    cmd->add_option("--script", o->scripts,
                    "your own metric: an executable run as PATH RUN_DIR, printing NAME VALUE or "
                    "TIME_S,NAME,VALUE lines; repeatable")
        ->type_name("PATH");
    cmd->add_option("--world", o->world, "the world the run was in (default: RUN_DIR/world.json)")
        ->type_name("FILE");
    cmd->add_option("--csv", o->csv, "where every value over time goes (default: RUN_DIR/metrics.csv)")
        ->type_name("FILE");
    cmd->add_option("--every", o->every, "seconds between two values over time (default 0: every sample)")
        ->type_name("SECONDS");
    cmd->add_flag("--list", o->list, "list the built-in metrics and their arguments");
    cmd->footer("Exit status: 0 measured, 1 a script failed, 2 bad input (the folder, a metric, its arguments).\n"
                "docs/experiments.md, \"Metrics\": the built-ins, the firmware's metric lines, scripts.");
    cmd->callback([o] { exit_code = measure(*o); });
}

}  // namespace openswarm
