// Metrics the firmware reports: a robot prints a console line
//     metric NAME VALUE
// (NAME: letters, digits, '_', '.', '-', starting with a letter; VALUE: a
// number), and openswarm-sim keeps every robot's console lines in the
// run's console.csv (time_s,robot,line; `openswarm run --world` asks for it,
// openswarm-sim --console-csv FILE). Each report holds from its time until
// the robot's next one.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace openswarm {

struct FirmwareReport {
    double time_s;
    int robot;
    double value;
};

// Every report of every name, in the file's order (by time within a robot).
struct FirmwareReports {
    std::map<std::string, std::vector<FirmwareReport>> by_name;
    std::vector<std::string> warnings; // "metric" lines that are not NAME VALUE
};

// The value of "metric NAME VALUE" lines; false for other lines, and for a
// malformed metric line with why set.
bool parse_metric_line(const std::string &line, std::string &name, double &value, std::string &why);

// Throws MetricsError when the file is there but is not a console.csv;
// a missing file reads as no reports.
FirmwareReports read_firmware_reports(const std::filesystem::path &console_csv);

// At each of times (ascending), the mean over robots that have reported
// by then of their latest value (NaN before the first report), and the
// robots counted.
struct FirmwareMean {
    std::vector<double> mean;
    std::vector<size_t> robots;
};
FirmwareMean firmware_mean_at(const std::vector<FirmwareReport> &reports, const std::vector<double> &times);

// "NAME.settled_s": at each of times (ascending), with robots[i] robots
// in the run at times[i], the time of the latest report by then that gave
// a robot a value other than its last (its first report counts too): the
// time since which every robot holds its value. NaN until every robot
// has reported.
std::vector<double> firmware_settled_at(const std::vector<FirmwareReport> &reports, const std::vector<double> &times,
                                        const std::vector<size_t> &robots);

// The suffix that asks for a reported metric's settling time.
constexpr const char *settled_suffix = ".settled_s";

}  // namespace openswarm
