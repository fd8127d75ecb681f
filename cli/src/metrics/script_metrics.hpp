// A researcher's own metric: an executable run as
//     SCRIPT RUN_DIR
// (also given OPENSWARM_RUN_DIR and OPENSWARM_WORLD, the world file or
// empty, in its environment) that reads what it likes of the run's folder
// and prints, one a line on its standard output,
//     NAME VALUE             a value at the end of the run
//     TIME_S,NAME,VALUE      a value at a time (a header time_s,name,value
//                            may come first)
// Blank lines and lines starting with '#' are skipped. It must exit with
// status 0; what it prints on standard error is shown when it fails.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace openswarm {

struct ScriptValue {
    double time_s; // NaN: at the end of the run
    std::string name;
    double value;
};

// The values in a script's output; throws MetricsError naming the script
// and the line that is neither form.
std::vector<ScriptValue> parse_script_output(const std::string &script, const std::string &output);

// Runs it and reads its output; throws MetricsError when it cannot be run,
// fails (its exit status and the end of its standard error), or prints
// nothing usable.
std::vector<ScriptValue> run_metric_script(const std::filesystem::path &script, const std::filesystem::path &run_dir,
                                           const std::filesystem::path &world);

}  // namespace openswarm
