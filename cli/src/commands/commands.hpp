// One function per subcommand; each registers itself on the CLI11 app.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>

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
void add_clean_command(CLI::App &app, const Paths &paths);
void add_upload_command(CLI::App &app, const Paths &paths);
void add_monitor_command(CLI::App &app, const Paths &paths);
// Registered last: its script lists every command registered before it.
void add_completion_command(CLI::App &app, const Paths &paths);

// A number option's check: a finite number in [lo, hi] (CLI::Range lets
// nan through: every comparison with it is false). The message names the
// option, what it was given, the range and an example.
inline CLI::Validator finite_seconds(const std::string &option, double lo, double hi,
                                     const std::string &example) {
    return CLI::Validator(
        [=](std::string &text) -> std::string {
            char *end = nullptr;
            double v = std::strtod(text.c_str(), &end);
            if (end != text.c_str() && *end == '\0' && std::isfinite(v) && v >= lo && v <= hi) return "";
            char range[64];
            std::snprintf(range, sizeof range, "%g..%g", lo, hi);
            // CLI11 puts "OPTION: " before it
            return "'" + text + "' is not seconds: give a finite number " + range + ", e.g. " + option + " " + example;
        },
        "SECONDS", "finite seconds");
}

// "openswarm: <message>" on standard error.
void report(const std::string &message);

// Every message report() printed so far, in order: `build --json` repeats
// them in its JSON when the build fails.
const std::vector<std::string> &reported_messages();

}  // namespace openswarm
