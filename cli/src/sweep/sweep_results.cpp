#include "sweep_results.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include "../number_text.hpp"
#include "group_comparison.hpp"
#include "sweep_stats.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace openswarm {

namespace {

// A field of a CSV row: quoted when it holds a comma, quote or line break.
std::string csv_field(const std::string &text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string value_text(const json &v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

// "point,trial,seed,<each parameter>"
std::string key_header(const Sweep &s) {
    std::string header = "point,trial,seed";
    for (const auto &p : s.parameters) header += "," + csv_field(p.path);
    return header;
}

std::string point_fields(const Sweep &s, size_t point) {
    std::string fields;
    for (size_t p = 0; p < s.parameters.size(); p++) fields += "," + csv_field(value_text(s.points[point][p]));
    return fields;
}

std::string key_fields(const Sweep &s, const SweepTrial &t) {
    return std::to_string(t.point + 1) + "," + std::to_string(t.trial + 1) + "," + std::to_string(t.seed) +
           point_fields(s, t.point);
}

// Each metric's value at the end of each trial that ran, by point; the
// metrics in the order they first come.
struct Finals {
    std::map<size_t, std::map<std::string, std::vector<double>>> at;
    std::vector<std::string> order;
};

Finals finals_of(const std::vector<SweepTrial> &trials) {
    Finals f;
    for (const SweepTrial &t : trials) {
        if (!t.failure.empty()) continue;
        for (const TrialSeries &series : t.series) {
            if (series.values.empty()) continue;
            f.at[t.point][series.metric].push_back(series.values.back().second);
            if (std::find(f.order.begin(), f.order.end(), series.metric) == f.order.end())
                f.order.push_back(series.metric);
        }
    }
    return f;
}

size_t failed_at(const std::vector<SweepTrial> &trials, size_t point) {
    size_t failed = 0;
    for (const SweepTrial &t : trials) failed += t.point == point && !t.pending && !t.failure.empty();
    return failed;
}

bool close_checked(std::ofstream &out, const fs::path &file, std::string &why) {
    out.close();
    if (out) return true;
    why = "cannot write " + file.string() + " (the disk full?)";
    return false;
}

// Two points (the case study's two controllers): whether they differ at
// the end, each metric by Welch's t test, and by how much (Cohen's d).
void print_two_point_comparison(Finals &finals, std::FILE *to) {
    for (const std::string &metric : finals.order) {
        Comparison c = compare_groups(finals.at[0][metric], finals.at[1][metric]);
        if (!c.valid) continue;
        std::fprintf(to, "point 1 against point 2, %s: Welch's t %s (df %.1f), p = %s; Cohen's d %s\n", metric.c_str(),
                     number_text(c.t).c_str(), c.degrees, number_text(c.p).c_str(), number_text(c.d).c_str());
    }
}

}  // namespace

bool write_sweep_results(const Sweep &s, const std::vector<SweepTrial> &trials, const fs::path &out,
                         std::string &why) {
    std::ofstream list(out / "trials.csv"), results(out / "results.csv");
    list << key_header(s) << ",status,reason,folder\n";
    results << key_header(s) << ",time_s,metric,value\n";
    for (const SweepTrial &t : trials) {
        std::string folder = fs::relative(t.dir, out).string();
        list << key_fields(s, t) << "," << (t.pending ? "pending" : t.failure.empty() ? "done" : "failed") << ","
             << csv_field(t.failure) << "," << csv_field(folder) << "\n";
        if (!t.failure.empty()) continue;
        for (const TrialSeries &series : t.series)
            for (const auto &[time, value] : series.values)
                results << key_fields(s, t) << "," << number_text(time) << "," << series.metric << "," << number_text(value)
                        << "\n";
    }
    if (!close_checked(list, out / "trials.csv", why) || !close_checked(results, out / "results.csv", why))
        return false;
    std::ofstream summary(out / "summary.csv");
    summary << "point";
    for (const auto &p : s.parameters) summary << "," << csv_field(p.path);
    summary << ",metric,n,failed,mean,sd,ci95_low,ci95_high\n";
    Finals finals = finals_of(trials);
    for (size_t point = 0; point < s.points.size(); point++)
        for (const std::string &metric : finals.order) {
            Summary m = summarise(finals.at[point][metric]);
            summary << point + 1 << point_fields(s, point) << "," << metric << "," << m.n << ","
                    << failed_at(trials, point);
            if (m.n == 0) summary << ",,,,\n";
            else summary << "," << number_text(m.mean) << "," << number_text(m.sd) << "," << number_text(m.low) << ","
                         << number_text(m.high) << "\n";
        }
    return close_checked(summary, out / "summary.csv", why);
}

void print_sweep_summary(const Sweep &s, const std::vector<SweepTrial> &trials, std::FILE *to) {
    Finals finals = finals_of(trials);
    for (size_t point = 0; point < s.points.size(); point++) {
        size_t failed = failed_at(trials, point), ran = 0;
        for (const SweepTrial &t : trials) ran += t.point == point && t.failure.empty();
        std::fprintf(to, "point %zu: %s (%zu trial%s%s)\n", point + 1, point_label(s, point).c_str(), ran,
                     ran == 1 ? "" : "s", failed ? (", " + std::to_string(failed) + " failed").c_str() : "");
        for (const std::string &metric : finals.order) {
            Summary m = summarise(finals.at[point][metric]);
            if (m.n == 0) continue;
            if (m.n == 1) std::fprintf(to, "  %-28s %10s             (n=1)\n", metric.c_str(), number_text(m.mean).c_str());
            else std::fprintf(to, "  %-28s %10s +- %-8s (95%%, n=%zu)\n", metric.c_str(), number_text(m.mean).c_str(),
                              number_text((m.high - m.low) / 2).c_str(), m.n);
        }
    }
    if (s.points.size() == 2) print_two_point_comparison(finals, to);
}

}  // namespace openswarm
