// A sweep file, any bytes, beside a fixed app and world: load_sweep accepts
// it (and every point's world and label can be made) or throws ConfigError
// with a message; nothing else may escape, crash or read out of bounds.
#include "app_config.hpp"
#include "fuzz_input_file.hpp"
#include "sweep/sweep_spec.hpp"

namespace {

// The app and world a sweep file beside them names ("world": "world.json").
void write_neighbours() {
    static bool written = false;
    if (written) return;
    written = true;
    const char app[] = R"({"name": "fuzzed", "port": "kilobot",
  "parameters": {"SPEED": {"default": 50, "min": 0, "max": 255}}})";
    const char world[] = R"({"arena": {"width_mm": 500, "height_mm": 500}, "ir": {"range_mm": 80},
  "robots": [{"count": 3, "poses": [{"x_mm": 100, "y_mm": 100}]}, {"count": 2}]})";
    write_input("openswarm.json", reinterpret_cast<const uint8_t *>(app), sizeof app - 1);
    write_input("world.json", reinterpret_cast<const uint8_t *>(world), sizeof world - 1);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    write_neighbours();
    auto path = write_input("sweep.json", data, size);
    try {
        openswarm::Sweep s = openswarm::load_sweep(path);
        for (size_t p = 0; p < s.points.size() && p < 64; p++) {
            (void)openswarm::point_world(s, p, s.trials - 1);
            (void)openswarm::point_parameters(s, p);
            (void)openswarm::point_label(s, p);
        }
    } catch (const openswarm::ConfigError &) {
    }
    return 0;
}
