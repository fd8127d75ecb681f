// Running the programs the tool drives (cmake, the simulator).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace openswarm {

// Run argv[0] with its arguments, its output going to ours; its exit
// status (or 127 if it could not be started).
int run_program(const std::vector<std::string> &argv);

// The same, its standard output going to our standard error: progress
// that must stay out of a result printed on standard output (--json).
int run_program_to_stderr(const std::vector<std::string> &argv);

// Run it and capture its standard output.
int capture_program(const std::vector<std::string> &argv, std::string &output);

// Run it and capture its standard output and error together: a step whose
// failure the tool explains itself, rather than showing the tool's noise.
int capture_program_and_errors(const std::vector<std::string> &argv, std::string &output);

// From now on SIGINT and SIGTERM do not end the tool: they are noted
// (interrupted()) and passed on to every program it runs, so each stops
// in its own way (openswarm-sim writes the run so far and exits 130 or
// 143). A signal from the terminal (Ctrl-C) is not passed on: the
// terminal sends it to the programs too.
void pass_interrupts_on();

// The signal that interrupted the tool (SIGINT, SIGTERM), or 0.
int interrupted();

// An exit status that says the program was stopped by SIGINT or SIGTERM
// (128 + the signal, as openswarm-sim and the shell report it).
bool interrupted_status(int status);

// What openswarm-sim's exit status says went wrong, for a person.
std::string simulator_failure(int status);

// Run it, handing each line of its standard output (without the newline)
// to on_line as it comes; its standard error goes to ours, or with
// with_errors to on_line too. After timeout_seconds (0: never) it is
// killed and 124 returned.
int run_program_lines(const std::vector<std::string> &argv,
                      const std::function<void(const std::string &)> &on_line,
                      double timeout_seconds, bool with_errors = false);

}  // namespace openswarm
