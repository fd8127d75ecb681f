// A run's samples as openswarm-sim wrote them into its --out folder
// (sim/src/output/trajectories.c): trajectories.csv, one row per robot per
// sample (time_s,robot,x_mm,y_mm,heading_deg,led_r,led_g,led_b), and
// objects.csv, one row per object per sample (time_s,object,x_mm,y_mm);
// read one sample at a time, so an hour of a thousand robots never sits in
// memory at once.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "object_clusters.hpp"

namespace openswarm {

struct RobotSample {
    int robot;
    double x_mm, y_mm, heading_deg;
    int led_r, led_g, led_b; // 0..3 each
};

// Everything at one sample time.
struct Snapshot {
    double time_s = 0;
    std::vector<RobotSample> robots;
    std::vector<ObjectPosition> objects;
};

// The rows of one CSV file, a group of rows with the same time_s at a time.
class TimedRows {
public:
    // Throws MetricsError when the file is missing or its header is not
    // header; an absent optional file reads as empty.
    TimedRows(const std::filesystem::path &file, const std::string &header, bool optional);
    TimedRows() = default; // no file: no rows
    bool empty() const { return !has_next_; }
    double next_time() const { return next_[0]; }
    // The fields of every row at time t (next_time()), numbers all.
    void take(double t, std::vector<std::vector<double>> &rows);

private:
    void read_ahead();
    std::filesystem::path file_;
    std::ifstream in_;
    size_t fields_ = 0;
    long line_ = 1;
    bool has_next_ = false;
    std::vector<double> next_;
};

class SnapshotReader {
public:
    // run_dir/trajectories.csv must be there; run_dir/objects.csv is read
    // when with_objects (missing: no objects).
    SnapshotReader(const std::filesystem::path &run_dir, bool with_objects);
    // The next sample, false after the last.
    bool next(Snapshot &s);
    // No sample after the one next() gave.
    bool done() const { return robots_.empty() && objects_.empty(); }

private:
    TimedRows robots_, objects_;
    std::vector<std::vector<double>> rows_;
};

}  // namespace openswarm
