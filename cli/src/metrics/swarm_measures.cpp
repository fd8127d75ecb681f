#include "swarm_measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <tuple>

namespace openswarm {

namespace {

const double none = std::numeric_limits<double>::quiet_NaN();

double squared_distance(const RobotSample &a, const RobotSample &b) {
    double dx = a.x_mm - b.x_mm, dy = a.y_mm - b.y_mm;
    return dx * dx + dy * dy;
}

}  // namespace

// Every pair: a hundred robots are 5000 pairs a sample, quick enough; a
// grid would pay off from a few thousand.
double mean_nearest_neighbour_mm(const std::vector<RobotSample> &robots) {
    if (robots.size() < 2) return none;
    double sum = 0;
    for (size_t i = 0; i < robots.size(); i++) {
        double nearest = std::numeric_limits<double>::infinity();
        for (size_t j = 0; j < robots.size(); j++)
            if (j != i) nearest = std::min(nearest, squared_distance(robots[i], robots[j]));
        sum += std::sqrt(nearest);
    }
    return sum / (double)robots.size();
}

double largest_group_fraction(const std::vector<RobotSample> &robots, double range_mm) {
    if (robots.empty()) return none;
    std::vector<size_t> parent(robots.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](size_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    for (size_t i = 0; i < robots.size(); i++)
        for (size_t j = i + 1; j < robots.size(); j++)
            if (squared_distance(robots[i], robots[j]) <= range_mm * range_mm) parent[root(i)] = root(j);
    std::vector<size_t> size(robots.size(), 0);
    for (size_t i = 0; i < robots.size(); i++) size[root(i)]++;
    return (double)*std::max_element(size.begin(), size.end()) / (double)robots.size();
}

double led_agreement(const std::vector<RobotSample> &robots) {
    if (robots.empty()) return none;
    std::map<std::tuple<int, int, int>, size_t> showing;
    size_t most = 0;
    for (const auto &r : robots) most = std::max(most, ++showing[{r.led_r, r.led_g, r.led_b}]);
    return (double)most / (double)robots.size();
}

double mean_light_distance_mm(const std::vector<RobotSample> &robots, const std::vector<LightSource> &lights) {
    if (robots.empty() || lights.empty()) return none;
    double sum = 0;
    for (const auto &r : robots) {
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto &l : lights) nearest = std::min(nearest, std::hypot(r.x_mm - l.x_mm, r.y_mm - l.y_mm));
        sum += nearest;
    }
    return sum / (double)robots.size();
}

CoverageGrid::CoverageGrid(double width_mm, double height_mm, double cell_mm)
    : cell_mm_(cell_mm), columns_(std::max(1L, (long)std::ceil(width_mm / cell_mm))),
      rows_(std::max(1L, (long)std::ceil(height_mm / cell_mm))), visited_((size_t)(columns_ * rows_), 0) {}

void CoverageGrid::visit(const std::vector<RobotSample> &robots) {
    for (const auto &r : robots) {
        // A centre on the far wall belongs to the last cell, not one past it.
        long c = std::clamp((long)std::floor(r.x_mm / cell_mm_), 0L, columns_ - 1);
        long w = std::clamp((long)std::floor(r.y_mm / cell_mm_), 0L, rows_ - 1);
        char &seen = visited_[(size_t)(w * columns_ + c)];
        if (!seen) count_++;
        seen = 1;
    }
}

double CoverageGrid::fraction() const { return (double)count_ / (double)visited_.size(); }

}  // namespace openswarm
