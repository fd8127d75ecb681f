// Metrics the firmware reports (cli/src/metrics/firmware_metrics.cpp): the
// console line, console.csv as openswarm-sim writes it, the mean over
// robots at each sample and each robot's own values, and when the values
// settled.
#include <gtest/gtest.h>

#include <cmath>

#include "../../cli/src/metrics/firmware_metrics.hpp"
#include "../../cli/src/metrics/metrics_error.hpp"
#include "../../cli/src/metrics/run_metrics.hpp"
#include "metrics_test_files.hpp"

using namespace openswarm;
using metrics_test::fresh_dir;
using metrics_test::write_file;
namespace fs = std::filesystem;

namespace {

// A run of two robots standing still, sampled at 0 and 1 s.
void two_robots_sampled_twice(const fs::path &dir) {
    write_file(dir / "trajectories.csv",
               "time_s,robot,x_mm,y_mm,heading_deg,led_r,led_g,led_b\n"
               "0.000,0,0.00,0.00,0.0,0,0,0\n0.000,1,50.00,0.00,0.0,0,0,0\n"
               "1.000,0,0.00,0.00,0.0,0,0,0\n1.000,1,50.00,0.00,0.0,0,0,0\n");
}

}  // namespace

TEST(FirmwareMetrics, TheConsoleLine) {
    std::string name, why;
    double v = 0;
    EXPECT_TRUE(parse_metric_line("metric hops 3", name, v, why));
    EXPECT_EQ(name, "hops");
    EXPECT_EQ(v, 3);
    EXPECT_TRUE(parse_metric_line("  metric  gradient.error_mm\t-2.5\r", name, v, why));
    EXPECT_EQ(name, "gradient.error_mm");
    EXPECT_EQ(v, -2.5);
    // Not a metric line: nothing to say.
    EXPECT_FALSE(parse_metric_line("hops 3", name, v, why));
    EXPECT_TRUE(why.empty());
    EXPECT_FALSE(parse_metric_line("metrics are fun", name, v, why));
    EXPECT_TRUE(why.empty());
    // A metric line gone wrong: why.
    EXPECT_FALSE(parse_metric_line("metric hops", name, v, why));
    EXPECT_NE(why.find("expected \"metric NAME VALUE\""), std::string::npos);
    EXPECT_FALSE(parse_metric_line("metric hops three", name, v, why));
    EXPECT_NE(why.find("\"three\" is not a number"), std::string::npos);
    EXPECT_FALSE(parse_metric_line("metric 3hops 1", name, v, why));
    EXPECT_NE(why.find("the name \"3hops\""), std::string::npos);
}

TEST(FirmwareMetrics, ReadsConsoleCsvWithQuotedLines) {
    fs::path dir = fresh_dir("console");
    write_file(dir / "console.csv",
               "time_s,robot,line\n"
               "0.500000,0,\"hello, \"\"world\"\"\"\n"
               "0.600000,1,\"metric hops 2\"\n"
               "0.700000,0,\"metric hops 1\"\n"
               "0.800000,0,\"metric hops x\"\n"
               "0.900000,1,\"metric seen 4\"\n");
    FirmwareReports r = read_firmware_reports(dir / "console.csv");
    ASSERT_EQ(r.by_name.size(), 2u);
    ASSERT_EQ(r.by_name["hops"].size(), 2u);
    EXPECT_EQ(r.by_name["hops"][0].robot, 1);
    EXPECT_EQ(r.by_name["hops"][0].time_s, 0.6);
    EXPECT_EQ(r.by_name["hops"][1].value, 1);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("console.csv:5: robot 0 printed \"metric hops x\""), std::string::npos) << r.warnings[0];
    // No file: no reports; a file of something else: an error.
    EXPECT_TRUE(read_firmware_reports(dir / "none.csv").by_name.empty());
    write_file(dir / "other.csv", "a,b\n");
    EXPECT_THROW(read_firmware_reports(dir / "other.csv"), MetricsError);
    write_file(dir / "cut.csv", "time_s,robot,line\n1.0,0,\"metric hops");
    EXPECT_THROW(read_firmware_reports(dir / "cut.csv"), MetricsError);
}

TEST(FirmwareMetrics, TheMeanHoldsEachRobotsLatestValue) {
    std::vector<FirmwareReport> reports = {{0.5, 0, 4}, {1.5, 1, 2}, {1.7, 0, 6}, {2.5, 0, 8}};
    FirmwareMean m = firmware_mean_at(reports, {0.0, 1.0, 2.0, 3.0});
    EXPECT_TRUE(std::isnan(m.mean[0])); // no robot has reported yet
    EXPECT_EQ(m.mean[1], 4);            // robot 0's 4
    EXPECT_EQ(m.mean[2], (6 + 2) / 2.0); // robot 0's latest, 6, and robot 1's 2
    EXPECT_EQ(m.mean[3], (8 + 2) / 2.0);
    EXPECT_EQ(m.robots, (std::vector<size_t>{0, 1, 2, 2}));
    // A report at a sample's very time counts at it.
    EXPECT_EQ(firmware_mean_at({{1.0, 3, 7}}, {1.0}).mean[0], 7);
}

TEST(FirmwareMetrics, ThroughTheRunFolder) {
    fs::path dir = fresh_dir("firmware-run");
    two_robots_sampled_twice(dir);
    write_file(dir / "console.csv",
               "time_s,robot,line\n0.2,0,\"metric hops 1\"\n0.4,1,\"metric hops 3\"\n1.5,1,\"metric hops 5\"\n");
    MetricsOutcome o = measure_run({dir, {}, {"hops"}, {}, 0});
    ASSERT_EQ(o.results.size(), 1u);
    const MetricResult &hops = o.results[0];
    EXPECT_EQ(hops.source, "firmware");
    // At 0 s no robot has reported; at 1 s both (1 and 3); the report at
    // 1.5 s, after the last sample, is the last value (1 and 5).
    ASSERT_EQ(hops.swarm.size(), 2u);
    EXPECT_EQ(hops.swarm[0].time_s, 1.0);
    EXPECT_EQ(hops.swarm[0].value, 2);
    EXPECT_EQ(hops.swarm[1].time_s, 1.5);
    EXPECT_EQ(hops.swarm[1].value, 3);
    ASSERT_EQ(hops.robots.size(), 2u);
    EXPECT_EQ(hops.robots.at(1).size(), 2u);
    EXPECT_EQ(hops.robots.at(1).back().value, 5);
    // Unasked, it is measured with the built-ins.
    MetricsOutcome all = measure_run({dir, {}, {}, {}, 0});
    EXPECT_EQ(all.results.back().name, "hops");
    // A name no robot reported: what they did report.
    try {
        measure_run({dir, {}, {"hop"}, {}, 0});
        FAIL() << "no error";
    } catch (const MetricsError &e) {
        EXPECT_NE(std::string(e.what()).find("(did you mean \"hops\"?); its robots reported hops"), std::string::npos)
            << e.what();
    }
}

TEST(FirmwareMetrics, SettledIsTheLastChangeOnceEveryRobotReported) {
    // Robot 0 reports 0 at 0.5 s; robot 1 reports 2 at 1.5 s, 1 at 1.7 s,
    // then 1 again at 2.5 s (no change).
    std::vector<FirmwareReport> reports = {{0.5, 0, 0}, {1.5, 1, 2}, {1.7, 1, 1}, {2.5, 1, 1}};
    std::vector<double> at = firmware_settled_at(reports, {1.0, 2.0, 3.0}, {2, 2, 2});
    EXPECT_TRUE(std::isnan(at[0])); // robot 1 has not reported yet
    EXPECT_EQ(at[1], 1.7);
    EXPECT_EQ(at[2], 1.7);          // the same value again changes nothing
    // A robot that never reports: never settled.
    EXPECT_TRUE(std::isnan(firmware_settled_at(reports, {3.0}, {3})[0]));
}

TEST(FirmwareMetrics, SettledThroughTheRunFolder) {
    fs::path dir = fresh_dir("firmware-settled");
    two_robots_sampled_twice(dir);
    write_file(dir / "console.csv",
               "time_s,robot,line\n0.2,0,\"metric hops 0\"\n0.4,1,\"metric hops 3\"\n0.6,1,\"metric hops 1\"\n"
               "1.5,1,\"metric hops 1\"\n");
    MetricsOutcome o = measure_run({dir, {}, {"hops.settled_s"}, {}, 0});
    ASSERT_EQ(o.results.size(), 1u);
    const MetricResult &settled = o.results[0];
    EXPECT_EQ(settled.unit, "s");
    // At 1 s both robots have reported, robot 1 last changed at 0.6 s; the
    // report at 1.5 s repeats its value.
    ASSERT_EQ(settled.swarm.size(), 2u);
    EXPECT_EQ(settled.swarm[0].time_s, 1.0);
    EXPECT_EQ(settled.swarm[0].value, 0.6);
    EXPECT_EQ(settled.swarm[1].value, 0.6);
    // Of a metric no robot reported: unknown, with what they did report.
    try {
        measure_run({dir, {}, {"hop.settled_s"}, {}, 0});
        FAIL() << "no error";
    } catch (const MetricsError &e) {
        EXPECT_NE(std::string(e.what()).find("its robots reported hops"), std::string::npos) << e.what();
    }
}
