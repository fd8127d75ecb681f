// openswarm.json, any bytes: load_app_config accepts it (and the code
// generated from it is written) or throws ConfigError with a message;
// nothing else may escape, crash or read out of bounds.
#include "app_config.hpp"
#include "fuzz_input_file.hpp"
#include "generate.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    write_input("openswarm.json", data, size);
    try {
        openswarm::AppConfig config = openswarm::load_app_config(fuzz_dir());
        openswarm::generate_app_files(config, {}, fuzz_dir() / "generated");
    } catch (const openswarm::ConfigError &) {
    }
    return 0;
}
