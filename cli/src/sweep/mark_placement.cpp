#include "mark_placement.hpp"

#include <utility>
#include <vector>

using nlohmann::json;

namespace openswarm {

namespace {

// splitmix64: the same draws on every machine.
uint64_t next(uint64_t &s) {
    uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// Keeps this clear of the walls (an e-puck is 74 mm across).
constexpr double wall_margin_mm = 50;

size_t robots_of(const json &group) {
    if (group.contains("poses") && group["poses"].is_array()) return group["poses"].size();
    if (group.contains("count") && group["count"].is_number_integer() && group["count"].get<long>() > 0)
        return group["count"].get<size_t>();
    return 0;
}

double number_in(const json &object, const char *key) {
    return object.contains(key) && object[key].is_number() ? object[key].get<double>() : 0.0;
}

}  // namespace

std::string marks_problem(const json &world, const Marks &m) {
    const json none;
    const json &arena = world.contains("arena") ? world["arena"] : none;
    double width = number_in(arena, "width_mm"), height = number_in(arena, "height_mm");
    std::string grid = std::to_string(m.columns) + " x " + std::to_string(m.rows) + " marks";
    if ((m.columns - 1) * m.spacing_mm + 2 * wall_margin_mm > width ||
        (m.rows - 1) * m.spacing_mm + 2 * wall_margin_mm > height)
        return "a grid of " + grid + " this far apart does not fit the world's arena (with " +
               std::to_string((int)wall_margin_mm) + " mm to the walls): fewer marks, or closer";
    const json &robots = world.contains("robots") ? world["robots"] : none;
    if (!robots.is_array() || robots.size() != 1 || robots_of(robots[0]) == 0)
        return "the world's robots go on marks as one group with \"count\" or \"poses\": give the world one "
               "such group";
    const json &objects = world.contains("objects") ? world["objects"] : none;
    size_t things = robots_of(robots[0]) + (objects.is_array() ? objects.size() : 0);
    if (things > (size_t)m.columns * (size_t)m.rows)
        return std::to_string(things) + " robots and objects need as many marks, and the grid has " +
               std::to_string(m.columns * m.rows) + ": fewer, or more marks";
    if (objects.is_array())
        for (size_t k = 0; k < objects.size(); k++)
            if (number_in(objects[k], "radius_mm") > m.spacing_mm / 2 - 1)
                return "objects[" + std::to_string(k) + "] is wider than the space between two marks: "
                       "smaller objects, or marks farther apart";
    return "";
}

void place_on_marks(json &world, const Marks &m, uint32_t seed) {
    // Marks in a random order: the robots take the first, the objects the next.
    int n = m.columns * m.rows;
    std::vector<int> marks(n);
    for (int k = 0; k < n; k++) marks[k] = k;
    uint64_t s = 0x6578706572696D65ull ^ ((uint64_t)seed << 17);
    for (int k = n - 1; k > 0; k--) std::swap(marks[k], marks[next(s) % (uint64_t)(k + 1)]);
    double x0 = (world["arena"]["width_mm"].get<double>() - (m.columns - 1) * m.spacing_mm) / 2;
    double y0 = (world["arena"]["height_mm"].get<double>() - (m.rows - 1) * m.spacing_mm) / 2;
    auto at = [&](int mark, json &j) {
        j["x_mm"] = x0 + (mark % m.columns) * m.spacing_mm;
        j["y_mm"] = y0 + (mark / m.columns) * m.spacing_mm;
    };
    json &group = world["robots"][0];
    size_t robots = robots_of(group);
    json poses = json::array();
    for (size_t k = 0; k < robots; k++) {
        json p;
        at(marks[k], p);
        p["heading_deg"] = (double)(next(s) % 360);
        poses.push_back(p);
    }
    group.erase("count");
    group.erase("region");
    group["poses"] = poses;
    if (world.contains("objects") && world["objects"].is_array())
        for (size_t k = 0; k < world["objects"].size(); k++) at(marks[robots + k], world["objects"][k]);
}

}  // namespace openswarm
