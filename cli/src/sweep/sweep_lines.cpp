#include "sweep_lines.hpp"

#include <algorithm>
#include <map>

using nlohmann::json;

namespace openswarm {

std::vector<std::vector<size_t>> parameter_lines(const std::vector<std::vector<json>> &points, size_t which) {
    std::map<std::vector<json>, std::vector<size_t>> by_others;
    for (size_t point = 0; point < points.size(); point++) {
        std::vector<json> others = points[point];
        others.erase(others.begin() + (long)which);
        by_others[others].push_back(point);
    }
    bool some_vary = std::any_of(by_others.begin(), by_others.end(), [](const auto &l) { return l.second.size() > 1; });
    std::vector<std::vector<size_t>> lines;
    for (const auto &[others, members] : by_others)
        if (!some_vary || members.size() > 1) lines.push_back(members);
    return lines;
}

}  // namespace openswarm
