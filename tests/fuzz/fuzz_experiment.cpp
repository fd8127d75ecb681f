// An experiment file, any bytes: load_experiment accepts it (and a trial's
// world is drawn from it) or throws ConfigError with a message; nothing
// else may escape, crash or read out of bounds.
#include "app_config.hpp"
#include "experiment_spec.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    auto path = write_input("experiment.json", data, size);
    try {
        openswarm::Experiment e = openswarm::load_experiment(path);
        (void)openswarm::trial_world(e, 7, "controller");
    } catch (const openswarm::ConfigError &) {
    }
    return 0;
}
