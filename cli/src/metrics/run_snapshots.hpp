// A run's samples as openswarm-sim wrote them into its --out folder
// (sim/src/output/trajectories.c, ir_table.c): trajectories.csv, one row
// per robot per sample (time_s,robot,x_mm,y_mm,heading_deg,led_r,led_g,
// led_b), objects.csv, one row per object per sample (time_s,object,x_mm,
// y_mm), and ir.csv, one row per Kilobot per sample (IR_TABLE_HEADER);
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

// A robot's IR frames since the run began (ir.csv): those its firmware
// sent and received (NaN when its firmware keeps no counters), and, of
// the frames robots in range sent, those that reached it and those the
// channel lost on the way.
struct IrSample {
    int robot;
    double sent, received, heard, lost_channel;
};

inline const char *const IR_TABLE_HEADER =
    "time_s,robot,sent,received,refused,bad_crc,broken,collisions,busy,heard,lost_channel";

// Everything at one sample time.
struct Snapshot {
    double time_s = 0;
    std::vector<RobotSample> robots;
    std::vector<ObjectPosition> objects;
    std::vector<IrSample> ir;
};

// The rows of one CSV file, a group of rows with the same time_s at a time.
class TimedRows {
public:
    // Throws MetricsError when the file is missing or its header is not
    // header; an absent optional file reads as empty. blanks: an empty
    // field reads as NaN (a count not known), not as a row cut short.
    TimedRows(const std::filesystem::path &file, const std::string &header, bool optional, bool blanks = false);
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
    bool blanks_ = false;
    long line_ = 1;
    bool has_next_ = false;
    std::vector<double> next_;
};

class SnapshotReader {
public:
    // run_dir/trajectories.csv must be there; run_dir/objects.csv is read
    // when with_objects (missing: no objects), run_dir/ir.csv when with_ir
    // (there: builtin_metric_unavailable checked it).
    SnapshotReader(const std::filesystem::path &run_dir, bool with_objects, bool with_ir = false);
    // The next sample, false after the last.
    bool next(Snapshot &s);
    // No sample after the one next() gave.
    bool done() const { return robots_.empty() && objects_.empty() && ir_.empty(); }

private:
    TimedRows robots_, objects_, ir_;
    std::vector<std::vector<double>> rows_;
};

}  // namespace openswarm
