#include "run_snapshots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "metrics_error.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

size_t count_fields(const std::string &header) { return (size_t)std::count(header.begin(), header.end(), ',') + 1; }

// A CSV row of numbers, or false: a row cut short, a word, an empty field
// (unless blanks: NaN then).
bool parse_numbers(const std::string &line, size_t fields, bool blanks, std::vector<double> &out) {
    out.clear();
    const char *p = line.c_str();
    for (size_t k = 0; k < fields; k++) {
        char *end;
        double v = std::strtod(p, &end);
        if (end == p && blanks && (*p == ',' || *p == '\0' || *p == '\r')) v = NAN;
        else if (end == p || !std::isfinite(v)) return false;
        out.push_back(v);
        if (k + 1 < fields && *end != ',') return false;
        p = end + 1;
        if (k + 1 == fields && *end != '\0' && *end != '\r') return false;
    }
    return true;
}

}  // namespace

TimedRows::TimedRows(const fs::path &file, const std::string &header, bool optional, bool blanks)
    : file_(file), fields_(count_fields(header)), blanks_(blanks) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) {
        if (optional) return;
        throw MetricsError(file.string() + ": no such file; give the --out folder of a run in a world "
                           "(`openswarm run --world FILE` writes <app>/out/<world>/, `openswarm-sim "
                           "--world FILE --out DIR` writes DIR)");
    }
    in_.open(file);
    std::string first;
    if (!in_ || !std::getline(in_, first))
        throw MetricsError(file.string() + ": cannot be read, or is empty; run the world again to write it");
    if (!first.empty() && first.back() == '\r') first.pop_back();
    if (first != header)
        throw MetricsError(file.string() + ":1: the header is \"" + first.substr(0, 80) + "\", expected \"" +
                           header + "\": not a file openswarm-sim wrote; give the folder of a run");
    read_ahead();
}

void TimedRows::read_ahead() {
    std::string line;
    has_next_ = false;
    while (std::getline(in_, line)) {
        line_++;
        if (line.empty() || line == "\r") continue;
        if (!parse_numbers(line, fields_, blanks_, next_) || std::isnan(next_[0]))
            throw MetricsError(file_.string() + ":" + std::to_string(line_) + ": expected " +
                               std::to_string(fields_) + " numbers separated by commas, found \"" +
                               line.substr(0, 80) + "\"; was the run cut short? Run the world again");
        has_next_ = true;
        return;
    }
}

void TimedRows::take(double t, std::vector<std::vector<double>> &rows) {
    rows.clear();
    while (has_next_ && next_[0] == t) {
        rows.push_back(next_);
        read_ahead();
    }
    if (has_next_ && next_[0] < t)
        throw MetricsError(file_.string() + ":" + std::to_string(line_) + ": time " +
                           std::to_string(next_[0]) + " s comes after " + std::to_string(t) +
                           " s; the rows must be in time order, as openswarm-sim writes them");
}

SnapshotReader::SnapshotReader(const fs::path &run_dir, bool with_objects, bool with_ir)
    : robots_(run_dir / "trajectories.csv", "time_s,robot,x_mm,y_mm,heading_deg,led_r,led_g,led_b", false),
      objects_(with_objects ? TimedRows(run_dir / "objects.csv", "time_s,object,x_mm,y_mm", true) : TimedRows()),
      ir_(with_ir ? TimedRows(run_dir / "ir.csv", IR_TABLE_HEADER, false, true) : TimedRows()) {}

bool SnapshotReader::next(Snapshot &s) {
    if (done()) return false;
    double t = INFINITY;
    for (const TimedRows *rows : {&robots_, &objects_, &ir_})
        if (!rows->empty()) t = std::min(t, rows->next_time());
    s.time_s = t;
    s.robots.clear();
    s.objects.clear();
    s.ir.clear();
    robots_.take(t, rows_);
    for (const auto &r : rows_)
        s.robots.push_back({(int)r[1], r[2], r[3], r[4], (int)r[5], (int)r[6], (int)r[7]});
    objects_.take(t, rows_);
    for (const auto &o : rows_) s.objects.push_back({o[2], o[3]});
    ir_.take(t, rows_);
    for (const auto &r : rows_) {
        if (std::isnan(r[1]) || std::isnan(r[9]) || std::isnan(r[10]))
            throw MetricsError("ir.csv: a row at " + std::to_string(t) + " s has no robot, heard or lost_channel; "
                               "it is not a file openswarm-sim wrote: run the world again");
        s.ir.push_back({(int)r[1], r[2], r[3], r[9], r[10]});
    }
    return true;
}

}  // namespace openswarm
