// The case study's placement (docs/case-study.md): a grid of marks centred
// in the arena, as the paper's 165 pencil marks 25 cm apart; each robot
// and each object on a mark of its own drawn from the trial's seed, each
// robot with a heading drawn too. The clustering experiment file and a
// sweep's "marks" place their worlds this way, with the same draws.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace openswarm {

struct Marks {
    int columns = 0, rows = 0;
    double spacing_mm = 0;
};

// Why the world's robots and objects cannot go on these marks (the grid
// does not fit its arena, fewer marks than robots and objects, an object
// wider than the space between marks, robots in more than one group), or
// "" when they can.
std::string marks_problem(const nlohmann::json &world, const Marks &marks);

// Sets the poses of the world's one group of robots (replacing its
// "count" or "poses") and every object's x_mm and y_mm, drawn from seed
// alone. The world passed marks_problem.
void place_on_marks(nlohmann::json &world, const Marks &marks, uint32_t seed);

}  // namespace openswarm
