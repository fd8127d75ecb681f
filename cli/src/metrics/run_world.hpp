// What the metrics need to know of the world a run was in (docs/world.md):
// the arena, the lights, the IR range and the objects' sizes, read from
// its world.json (the run's own copy: `openswarm run --world` keeps one
// beside the trajectories, `openswarm experiment` writes one per trial).
#pragma once

#include <filesystem>
#include <vector>

namespace openswarm {

struct LightSource {
    double x_mm, y_mm, intensity_mv;
};

struct RunWorld {
    std::filesystem::path file; // empty: no world known
    double arena_width_mm = 0, arena_height_mm = 0;
    double ir_range_mm = 100; // the simulator's default (--ir-range) when the world gives none
    std::vector<LightSource> lights;
    std::vector<double> object_radii_mm; // one per object, in the file's order
    bool known() const { return !file.empty(); }
};

// Throws MetricsError naming the file and the key when it cannot be read.
RunWorld read_run_world(const std::filesystem::path &file);

}  // namespace openswarm
