// A researcher's own metric (cli/src/metrics/script_metrics.cpp): what it
// prints, and how it fails, with real scripts run by /bin/sh.
#include <gtest/gtest.h>

#include <cmath>
#include <sys/stat.h>

#include "../../cli/src/metrics/metrics_error.hpp"
#include "../../cli/src/metrics/run_metrics.hpp"
#include "../../cli/src/metrics/script_metrics.hpp"
#include "metrics_test_files.hpp"

using namespace openswarm;
using metrics_test::fresh_dir;
using metrics_test::write_file;
namespace fs = std::filesystem;

namespace {

fs::path script(const fs::path &dir, const std::string &name, const std::string &body, bool executable = true) {
    fs::path file = dir / name;
    write_file(file, "#!/bin/sh\n" + body);
    chmod(file.c_str(), executable ? 0755 : 0644);
    return file;
}

std::string failure(const fs::path &s, const fs::path &run_dir, bool *bad_input = nullptr) {
    try {
        run_metric_script(s, run_dir, "");
    } catch (const MetricsError &e) {
        if (bad_input) *bad_input = e.bad_input;
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST(ScriptMetrics, BothFormsOfOutput) {
    auto v = parse_script_output("s", "# made by hand\n\ntime_s,name,value\n0.5,spread,12\n1.0, spread ,14.5\n"
                                      "final_score 0.75\n");
    ASSERT_EQ(v.size(), 3u);
    EXPECT_EQ(v[0].time_s, 0.5);
    EXPECT_EQ(v[0].name, "spread");
    EXPECT_EQ(v[1].value, 14.5);
    EXPECT_TRUE(std::isnan(v[2].time_s));
    EXPECT_EQ(v[2].name, "final_score");
    EXPECT_EQ(v[2].value, 0.75);
}

TEST(ScriptMetrics, OutputThatIsNeitherFormNamesTheLine) {
    try {
        parse_script_output("my.sh", "a 1\nb one\n");
        FAIL();
    } catch (const MetricsError &e) {
        EXPECT_NE(std::string(e.what()).find("metric script my.sh: line 2 of its output is \"b one\": expected NAME "
                                             "VALUE"),
                  std::string::npos)
            << e.what();
        EXPECT_FALSE(e.bad_input);
    }
    EXPECT_THROW(parse_script_output("s", "1.0,x\n"), MetricsError);
    EXPECT_THROW(parse_script_output("s", "-1,x,2\n"), MetricsError);
    EXPECT_THROW(parse_script_output("s", "x nan\n"), MetricsError);
}

TEST(ScriptMetrics, RunsWithTheRunsFolder) {
    fs::path dir = fresh_dir("script-run");
    // It gets the folder as its argument and in its environment.
    fs::path s = script(dir, "count.sh",
                        "test \"$1\" = \"$OPENSWARM_RUN_DIR\" || exit 9\n"
                        "echo \"rows $(wc -l < \"$1/trajectories.csv\")\"\necho '0.000,first,1'\n");
    write_file(dir / "trajectories.csv", "time_s,robot,x_mm,y_mm,heading_deg,led_r,led_g,led_b\n"
                                         "0.000,0,0.00,0.00,0.0,0,0,0\n2.000,0,9.00,0.00,0.0,0,0,0\n");
    auto v = run_metric_script(s, dir, "");
    ASSERT_EQ(v.size(), 2u);
    EXPECT_EQ(v[0].name, "rows");
    EXPECT_EQ(v[0].value, 3);
    // Through the run: a value without a time is at the last sample.
    MetricsOutcome o = measure_run({dir, {}, {"led_agreement"}, {s}, 0});
    ASSERT_EQ(o.results.size(), 3u);
    EXPECT_EQ(o.results[1].name, "rows");
    EXPECT_EQ(o.results[1].source, "script " + s.string());
    EXPECT_EQ(o.results[1].swarm[0].time_s, 2.0);
    EXPECT_EQ(o.results[2].swarm[0].time_s, 0.0);
}

TEST(ScriptMetrics, FailuresSayWhatAndWhatNext) {
    fs::path dir = fresh_dir("script-fail");
    bool bad_input = true;
    std::string failed = failure(script(dir, "fails.sh", "echo 'reading the run' >&2\necho 'no such column' >&2\nexit 3\n"),
                                 dir, &bad_input);
    EXPECT_NE(failed.find("fails.sh failed with exit status 3; the end of what it wrote on standard error:\n"
                          "    reading the run\n    no such column\nRun it by hand to see why: "),
              std::string::npos)
        << failed;
    EXPECT_FALSE(bad_input);
    EXPECT_NE(failure(script(dir, "silent.sh", "true\n"), dir).find("silent.sh printed no values"), std::string::npos);
    EXPECT_NE(failure(script(dir, "killed.sh", "kill -9 $$\n"), dir).find("was killed by signal 9"), std::string::npos);
    std::string plain = failure(script(dir, "plain.sh", "echo a 1\n", false), dir, &bad_input);
    EXPECT_NE(plain.find("not executable; make it so (chmod +x"), std::string::npos) << plain;
    EXPECT_TRUE(bad_input);
    EXPECT_NE(failure(dir / "missing.sh", dir).find("missing.sh: no such file"), std::string::npos);
    // A name another metric has already.
    write_file(dir / "trajectories.csv", "time_s,robot,x_mm,y_mm,heading_deg,led_r,led_g,led_b\n"
                                         "0.000,0,0.00,0.00,0.0,0,0,0\n");
    fs::path clash = script(dir, "clash.sh", "echo led_agreement 1\n");
    try {
        measure_run({dir, {}, {"led_agreement"}, {clash}, 0});
        FAIL();
    } catch (const MetricsError &e) {
        EXPECT_NE(std::string(e.what()).find("prints led_agreement, which another metric"), std::string::npos);
    }
}
