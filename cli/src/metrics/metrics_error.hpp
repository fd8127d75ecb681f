// What stops a metric from being measured, as a message a person can act
// on: the file and place, what was expected, what to do next.
#pragma once

#include <stdexcept>
#include <string>

namespace openswarm {

struct MetricsError : std::runtime_error {
    // bad_input: the run folder, a metric's name or its arguments are wrong
    // (exit 2); otherwise something the tool ran failed (a script, exit 1).
    MetricsError(const std::string &message, bool input_at_fault = true)
        : std::runtime_error(message), bad_input(input_at_fault) {}
    bool bad_input;
};

}  // namespace openswarm
