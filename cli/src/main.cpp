// openswarm: scaffold, build and run swarm-robot apps.
#include <algorithm>
#include <cstdio>

#include "commands/commands.hpp"
#include "suggest.hpp"

namespace openswarm {

int exit_code = EXIT_OK;

// Flushed after what the command printed before it, in the order it came.
static std::vector<std::string> reported;

void report(const std::string &message) {
    std::fflush(stdout);
    std::fprintf(stderr, "openswarm: %s\n", message.c_str());
    reported.push_back(message);
}

const std::vector<std::string> &reported_messages() { return reported; }

}  // namespace openswarm

int main(int argc, char **argv) {
    using namespace openswarm;
    CLI::App app{"openswarm: scaffold, build and run apps for swarm robots on the OpenSwarm kernel"};
    app.set_version_flag("-V,--version", "openswarm " OPENSWARM_VERSION);
    app.require_subcommand(1);
    app.footer("Exit status: 0 done, 1 a build or run failed, 2 bad usage or configuration.\n"
               "Start with: openswarm new my_robot --template blinky");
    Paths paths;
    try {
        paths = locate_paths(argv[0]);
    } catch (const std::exception &e) {
        report(e.what());
        return EXIT_USAGE;
    }
    add_new_command(app, paths);
    add_build_command(app, paths);
    add_run_command(app, paths);
    add_ports_command(app, paths);
    add_templates_command(app, paths);
    add_test_command(app, paths);
    add_experiment_command(app, paths);
    add_metrics_command(app, paths);
    add_size_command(app, paths);
    add_config_command(app, paths);
    add_doctor_command(app, paths);
    add_clean_command(app, paths);
    add_upload_command(app, paths);
    add_monitor_command(app, paths);
    add_completion_command(app, paths);
    std::vector<std::string> names;
    for (const auto *sub : app.get_subcommands({})) names.push_back(sub->get_name());
    if (argc > 1 && argv[1][0] != '-' &&
        std::find(names.begin(), names.end(), argv[1]) == names.end()) {
        report(std::string("unknown command '") + argv[1] + "'" + did_you_mean(argv[1], names, '\'') +
               "; commands: " + join(names) + " (`openswarm --help` says what each does)");
        return EXIT_USAGE;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError &e) {
        int rc = app.exit(e);
        return rc == 0 ? EXIT_OK : EXIT_USAGE;
    }
    return exit_code;
}
