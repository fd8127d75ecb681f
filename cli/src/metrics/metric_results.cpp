#include "metric_results.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

#include "../number_text.hpp"
#include "metrics_error.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

std::string time_text(double t) {
    if (std::isnan(t)) return "";
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", t);
    return text;
}

// The robots' values at the end, "0: 3, 1: 4, ...", the first few.
std::string per_robot_text(const MetricResult &r, size_t at_most) {
    std::string text;
    size_t shown = 0;
    for (const auto &[robot, points] : r.robots) {
        if (shown++ == at_most) {
            text += ", ... (" + std::to_string(r.robots.size()) + " robots; all in the CSV)";
            break;
        }
        text += (text.empty() ? "" : ", ") + std::to_string(robot) + ": " + number_text(points.back().value);
    }
    return text;
}

}  // namespace

void write_metrics_csv(const std::vector<MetricResult> &results, const fs::path &file) {
    std::ofstream csv(file);
    csv << "time_s,metric,robot,value\n";
    for (const auto &r : results) {
        for (const auto &p : r.swarm) csv << time_text(p.time_s) << ',' << r.name << ",," << number_text(p.value) << '\n';
        for (const auto &[robot, points] : r.robots)
            for (const auto &p : points)
                csv << time_text(p.time_s) << ',' << r.name << ',' << robot << ',' << number_text(p.value) << '\n';
    }
    csv.close();
    if (!csv)
        throw MetricsError("cannot write " + file.string() + ": " + std::strerror(errno) +
                           "; give another file with --csv FILE");
}

void print_metrics_table(const std::vector<MetricResult> &results, std::FILE *out) {
    size_t width = 6;
    for (const auto &r : results) width = std::max(width, r.name.size());
    std::fprintf(out, "%-*s  %12s  %12s  %12s  %7s  %s\n", (int)width, "metric", "at end", "lowest", "highest",
                 "samples", "from");
    for (const auto &r : results) {
        if (r.swarm.empty()) {
            std::fprintf(out, "%-*s  %12s  %12s  %12s  %7d  %s\n", (int)width, r.name.c_str(), "-", "-", "-", 0,
                         r.source.c_str());
            continue;
        }
        double lo = r.swarm[0].value, hi = lo;
        for (const auto &p : r.swarm) lo = std::min(lo, p.value), hi = std::max(hi, p.value);
        std::string from = r.source;
        if (!r.robots.empty()) from += ", mean of " + std::to_string(r.robots.size()) + " robots";
        std::fprintf(out, "%-*s  %12s  %12s  %12s  %7zu  %s\n", (int)width, r.name.c_str(),
                     number_text(r.swarm.back().value).c_str(), number_text(lo).c_str(), number_text(hi).c_str(),
                     r.swarm.size(), from.c_str());
        if (!r.robots.empty())
            std::fprintf(out, "%-*s  per robot at end: %s\n", (int)width, "", per_robot_text(r, 12).c_str());
    }
}

}  // namespace openswarm
