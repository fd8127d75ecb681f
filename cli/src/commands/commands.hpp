// One function per subcommand; each registers itself on the CLI11 app.
#pragma once

#include <CLI/CLI.hpp>

#include "../paths.hpp"

namespace openswarm {

// Exit codes, documented in `openswarm --help`.
enum ExitCode { EXIT_OK = 0, EXIT_FAILED = 1, EXIT_USAGE = 2 };

// Set by the subcommand that ran.
extern int exit_code;

void add_new_command(CLI::App &app, const Paths &paths);
void add_build_command(CLI::App &app, const Paths &paths);
void add_run_command(CLI::App &app, const Paths &paths);
void add_ports_command(CLI::App &app, const Paths &paths);
void add_templates_command(CLI::App &app, const Paths &paths);
void add_doctor_command(CLI::App &app, const Paths &paths);
void add_config_command(CLI::App &app, const Paths &paths);
void add_size_command(CLI::App &app, const Paths &paths);
void add_test_command(CLI::App &app, const Paths &paths);
void add_experiment_command(CLI::App &app, const Paths &paths);
void add_metrics_command(CLI::App &app, const Paths &paths);

// "openswarm: <message>" on standard error.
void report(const std::string &message);

}  // namespace openswarm
