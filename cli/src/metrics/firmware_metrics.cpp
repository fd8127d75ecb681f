#include "firmware_metrics.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>

#include "metrics_error.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

bool name_ok(const std::string &name) {
    if (name.empty() || !std::isalpha((unsigned char)name[0])) return false;
    for (char c : name)
        if (!std::isalnum((unsigned char)c) && c != '_' && c != '.' && c != '-') return false;
    return true;
}

// One CSV row of console.csv: time_s,robot,"line" (the line's quotes
// doubled), or false.
bool parse_console_row(const std::string &row, double &time_s, int &robot, std::string &line) {
    const char *p = row.c_str();
    char *end;
    time_s = std::strtod(p, &end);
    if (end == p || *end != ',') return false;
    p = end + 1;
    long r = std::strtol(p, &end, 10);
    if (end == p || *end != ',' || r < 0) return false;
    robot = (int)r;
    p = end + 1;
    line.clear();
    if (*p != '"') {
        line = p; // unquoted: as it is
        return true;
    }
    for (p++; *p; p++) {
        if (*p == '"') {
            if (p[1] != '"') return p[1] == '\0' || p[1] == '\r';
            p++;
        }
        line += *p;
    }
    return false; // no closing quote
}

}  // namespace

bool parse_metric_line(const std::string &line, std::string &name, double &value, std::string &why) {
    why.clear();
    size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line.compare(start, 7, "metric ") != 0) return false;
    std::vector<std::string> words;
    for (size_t p = start; p < line.size();) {
        size_t b = line.find_first_not_of(" \t\r", p);
        if (b == std::string::npos) break;
        size_t e = line.find_first_of(" \t\r", b);
        words.push_back(line.substr(b, e == std::string::npos ? std::string::npos : e - b));
        p = e == std::string::npos ? line.size() : e;
    }
    if (words.size() != 3) {
        why = "expected \"metric NAME VALUE\", found " + std::to_string(words.size()) + " words";
        return false;
    }
    if (!name_ok(words[1])) {
        why = "the name \"" + words[1] + "\" is not letters, digits, '_', '.' or '-' starting with a letter";
        return false;
    }
    char *end;
    value = std::strtod(words[2].c_str(), &end);
    if (*end != '\0' || end == words[2].c_str() || !std::isfinite(value)) {
        why = "the value \"" + words[2] + "\" is not a number";
        return false;
    }
    name = words[1];
    return true;
}

FirmwareReports read_firmware_reports(const fs::path &console_csv) {
    FirmwareReports reports;
    std::error_code ec;
    if (!fs::is_regular_file(console_csv, ec)) return reports;
    std::ifstream in(console_csv);
    std::string row;
    if (!std::getline(in, row) || row.rfind("time_s,robot,line", 0) != 0)
        throw MetricsError(console_csv.string() + ":1: the header is not \"time_s,robot,line\": not the console "
                           "file openswarm-sim writes (--console-csv); run the world again");
    for (long number = 2; std::getline(in, row); number++) {
        double t;
        int robot;
        std::string line, name, why;
        double value;
        if (!parse_console_row(row, t, robot, line))
            throw MetricsError(console_csv.string() + ":" + std::to_string(number) +
                               ": expected time_s,robot,\"line\", found \"" + row.substr(0, 80) +
                               "\"; was the run cut short? Run the world again");
        if (parse_metric_line(line, name, value, why))
            reports.by_name[name].push_back({t, robot, value});
        else if (!why.empty())
            reports.warnings.push_back(console_csv.string() + ":" + std::to_string(number) + ": robot " +
                                       std::to_string(robot) + " printed \"" + line.substr(0, 60) + "\": " + why +
                                       "; ignored");
    }
    return reports;
}

namespace {

// The reports in time order (each robot's own are already).
std::vector<FirmwareReport> by_time(const std::vector<FirmwareReport> &reports) {
    std::vector<FirmwareReport> sorted = reports;
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const FirmwareReport &a, const FirmwareReport &b) { return a.time_s < b.time_s; });
    return sorted;
}

}  // namespace

FirmwareMean firmware_mean_at(const std::vector<FirmwareReport> &reports, const std::vector<double> &times) {
    const std::vector<FirmwareReport> sorted = by_time(reports);
    std::map<int, double> latest;
    FirmwareMean out;
    size_t k = 0;
    for (double t : times) {
        for (; k < sorted.size() && sorted[k].time_s <= t; k++) latest[sorted[k].robot] = sorted[k].value;
        // Summed afresh each time: a running sum would drift over a long run.
        double sum = 0;
        for (const auto &robot_value : latest) sum += robot_value.second;
        out.mean.push_back(latest.empty() ? std::numeric_limits<double>::quiet_NaN() : sum / (double)latest.size());
        out.robots.push_back(latest.size());
    }
    return out;
}

std::vector<double> firmware_settled_at(const std::vector<FirmwareReport> &reports, const std::vector<double> &times,
                                        const std::vector<size_t> &robots) {
    const std::vector<FirmwareReport> sorted = by_time(reports);
    std::map<int, double> latest;
    double changed = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> out;
    size_t k = 0;
    for (size_t i = 0; i < times.size(); i++) {
        for (; k < sorted.size() && sorted[k].time_s <= times[i]; k++) {
            auto [at, first] = latest.emplace(sorted[k].robot, sorted[k].value);
            if (first || at->second != sorted[k].value) changed = sorted[k].time_s;
            at->second = sorted[k].value;
        }
        out.push_back(latest.size() >= robots[i] ? changed : std::numeric_limits<double>::quiet_NaN());
    }
    return out;
}

}  // namespace openswarm
