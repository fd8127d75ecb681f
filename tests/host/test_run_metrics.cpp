// A run's folder measured (cli/src/metrics/run_metrics.cpp): a hand-made
// trajectories.csv, objects.csv and world.json with known answers, the
// choice of metrics, their arguments, thinning, and the mistakes.
#include <gtest/gtest.h>

#include <cmath>

#include "../../cli/src/metrics/metrics_error.hpp"
#include "../../cli/src/metrics/object_clusters.hpp"
#include "../../cli/src/metrics/run_metrics.hpp"
#include "metrics_test_files.hpp"

using namespace openswarm;
using metrics_test::fresh_dir;
using metrics_test::write_file;
namespace fs = std::filesystem;

namespace {

// Three robots at three samples: packed (t 0), spread (t 1), packed again
// (t 2); two objects touching, then apart.
fs::path three_robots(const std::string &name, bool with_world = true) {
    fs::path dir = fresh_dir(name);
    write_file(dir / "trajectories.csv",
               "time_s,robot,x_mm,y_mm,heading_deg,led_r,led_g,led_b\n"
               "0.000,0,100.00,100.00,0.0,3,0,0\n"
               "0.000,1,130.00,100.00,90.0,3,0,0\n"
               "0.000,2,100.00,140.00,0.0,0,3,0\n"
               "1.000,0,100.00,100.00,0.0,3,0,0\n"
               "1.000,1,300.00,100.00,0.0,3,0,0\n"
               "1.000,2,100.00,400.00,0.0,3,0,0\n"
               "2.000,0,100.00,100.00,0.0,3,0,0\n"
               "2.000,1,130.00,100.00,0.0,3,0,0\n"
               "2.000,2,100.00,140.00,0.0,0,3,0\n");
    write_file(dir / "objects.csv",
               "time_s,object,x_mm,y_mm\n"
               "0.000,0,200.00,200.00\n0.000,1,250.00,200.00\n"
               "1.000,0,200.00,200.00\n1.000,1,300.00,200.00\n"
               "2.000,0,200.00,200.00\n2.000,1,300.00,200.00\n");
    // Robot 2's firmware keeps no IR counters: its fields are empty.
    write_file(dir / "ir.csv",
               "time_s,robot,sent,received,refused,bad_crc,broken,collisions,busy,heard,lost_channel\n"
               "0.000,0,0,0,0,0,0,0,0,0,0\n0.000,1,0,0,0,0,0,0,0,0,0\n0.000,2,,,,,,,,0,0\n"
               "1.000,0,4,3,0,1,0,0,0,5,1\n1.000,1,6,5,0,0,0,0,0,5,2\n1.000,2,,,,,,,,4,3\n"
               "2.000,0,8,6,0,1,0,0,0,10,2\n2.000,1,10,9,0,0,0,0,0,9,4\n2.000,2,,,,,,,,8,6\n");
    if (with_world)
        write_file(dir / "world.json",
                   R"({"arena": {"width_mm": 500, "height_mm": 500}, "ir": {"range_mm": 100},
                       "light": {"sources": [{"x_mm": 100, "y_mm": 0, "intensity_mv": 2000}]},
                       "objects": [{"x_mm": 200, "y_mm": 200, "radius_mm": 20},
                                   {"x_mm": 250, "y_mm": 200, "radius_mm": 20}],
                       "robots": [{"count": 3}]})");
    return dir;
}

const MetricResult &named(const MetricsOutcome &o, const std::string &name) {
    for (const auto &r : o.results)
        if (r.name == name) return r;
    throw std::runtime_error("no result " + name);
}

std::vector<double> values(const MetricResult &r) {
    std::vector<double> v;
    for (const auto &p : r.swarm) v.push_back(p.value);
    return v;
}

std::string error_of(const MetricsRequest &request) {
    try {
        measure_run(request);
    } catch (const MetricsError &e) {
        EXPECT_TRUE(e.bad_input);
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST(RunMetrics, EveryBuiltinAtEverySample) {
    fs::path dir = three_robots("every");
    MetricsOutcome o = measure_run({dir, {}, {}, {}, 0});
    EXPECT_TRUE(o.notes.empty());
    ASSERT_EQ(o.results.size(), 11u); // every built-in: the world has lights and objects, the run ir.csv
    const MetricResult &nn = named(o, "nearest_neighbour_mm");
    ASSERT_EQ(nn.swarm.size(), 3u);
    EXPECT_DOUBLE_EQ(nn.swarm[1].time_s, 1.0);
    EXPECT_NEAR(nn.swarm[0].value, (30 + 30 + 40) / 3.0, 1e-9);
    EXPECT_NEAR(nn.swarm[1].value, (200 + 200 + 300) / 3.0, 1e-9);
    // Linked within the world's IR range (100 mm) at 0 and 2, alone at 1.
    EXPECT_EQ(values(named(o, "largest_group")), (std::vector<double>{1.0, 1.0 / 3, 1.0}));
    EXPECT_EQ(values(named(o, "led_agreement")), (std::vector<double>{2.0 / 3, 1.0, 2.0 / 3}));
    // 100 cells of 50 mm: one at first, three once spread, still three.
    EXPECT_EQ(values(named(o, "coverage")), (std::vector<double>{0.01, 0.03, 0.03}));
    EXPECT_NEAR(named(o, "light_distance_mm").swarm[0].value, (100 + std::hypot(30, 100) + 140) / 3, 1e-9);
    // The objects touch rims 10 mm apart at 0 (one cluster), 60 mm later.
    EXPECT_EQ(values(named(o, "largest_cluster")), (std::vector<double>{1.0, 0.5, 0.5}));
}

// The IR metrics: means over robots of ir.csv's counts; the firmware's
// over the robots whose firmware keeps counters (not robot 2), lost as
// heard + lost_channel - received.
TEST(RunMetrics, IrMetricsAreMeansOfTheCounts) {
    fs::path dir = three_robots("ir");
    MetricsOutcome o = measure_run({dir, {}, {"ir_sent", "ir_received", "ir_lost", "ir_lost_channel"}, {}, 0});
    EXPECT_EQ(values(named(o, "ir_sent")), (std::vector<double>{0, 5, 9}));
    EXPECT_EQ(values(named(o, "ir_received")), (std::vector<double>{0, 4, 7.5}));
    EXPECT_EQ(values(named(o, "ir_lost")), (std::vector<double>{0, 2.5, 5}));
    EXPECT_EQ(values(named(o, "ir_lost_channel")), (std::vector<double>{0, 2, 4}));
    EXPECT_EQ(named(o, "ir_lost").unit, "frames");
    // Without ir.csv (an e-puck world, an older simulator's run): left out
    // by default, and an error naming the file when asked for.
    fs::remove(dir / "ir.csv");
    MetricsOutcome without = measure_run({dir, {}, {}, {}, 0});
    ASSERT_EQ(without.notes.size(), 4u);
    EXPECT_NE(without.notes[0].find("ir_sent left out: needs " + (dir / "ir.csv").string()), std::string::npos)
        << without.notes[0];
    EXPECT_NE(error_of({dir, {}, {"ir_lost"}, {}, 0}).find("openswarm-sim --out writes it for a world of Kilobots"),
              std::string::npos);
}

TEST(RunMetrics, ObjectMetricsAreTheExperimentsOwn) {
    fs::path dir = three_robots("objects");
    MetricsOutcome o = measure_run({dir, {}, {"largest_cluster", "compactness"}, {}, 0});
    ASSERT_EQ(o.results.size(), 2u);
    std::vector<ObjectPosition> first = {{200, 200}, {250, 200}}, later = {{200, 200}, {300, 200}};
    EXPECT_EQ(named(o, "compactness").swarm[0].value, compactness(first, 20));
    EXPECT_EQ(named(o, "compactness").swarm[2].value, compactness(later, 20));
    EXPECT_EQ(named(o, "largest_cluster").swarm[1].value, largest_cluster_fraction(later, 20));
    // Bigger objects, radius given: centres 100 mm apart, rims 8 mm: linked.
    MetricsOutcome big = measure_run({dir, {}, {"largest_cluster:radius_mm=46"}, {}, 0});
    EXPECT_EQ(values(big.results[0]), (std::vector<double>{1.0, 1.0, 1.0}));
}

TEST(RunMetrics, ArgumentsChangeTheMeasure) {
    fs::path dir = three_robots("arguments");
    MetricsOutcome o = measure_run({dir, {}, {"largest_group:range_mm=35", "coverage:cell_mm=250"}, {}, 0});
    // 35 mm links robots 0 and 1 (30 mm), not 2 (40 mm).
    EXPECT_EQ(values(o.results[0]), (std::vector<double>{2.0 / 3, 1.0 / 3, 2.0 / 3}));
    // Four cells of 250 mm: (100, 100) and (300, 100) differ, (100, 400) is a third.
    EXPECT_EQ(values(o.results[1]), (std::vector<double>{0.25, 0.75, 0.75}));
}

TEST(RunMetrics, EveryThinsTheValuesButCoverageSeesEverySample) {
    fs::path dir = three_robots("thin");
    MetricsOutcome o = measure_run({dir, {}, {"coverage", "nearest_neighbour_mm"}, {}, 5});
    // The first and the last sample only; coverage at 2 s still counts
    // where the robots were at 1 s.
    ASSERT_EQ(o.results[0].swarm.size(), 2u);
    EXPECT_DOUBLE_EQ(o.results[0].swarm[1].time_s, 2.0);
    EXPECT_DOUBLE_EQ(o.results[0].swarm[1].value, 0.03);
    EXPECT_EQ(o.results[1].swarm.size(), 2u);
}

TEST(RunMetrics, WithoutAWorldTheMetricsThatNeedOneAreLeftOutAndSaySo) {
    fs::path dir = three_robots("no-world", false);
    MetricsOutcome o = measure_run({dir, {}, {}, {}, 0});
    std::vector<std::string> names;
    for (const auto &r : o.results) names.push_back(r.name);
    EXPECT_EQ(names, (std::vector<std::string>{"nearest_neighbour_mm", "largest_group", "led_agreement", "ir_sent",
                                               "ir_received", "ir_lost", "ir_lost_channel"}));
    ASSERT_EQ(o.notes.size(), 4u);
    EXPECT_NE(o.notes[0].find("coverage left out: needs the arena's size"), std::string::npos) << o.notes[0];
    // The IR range falls back to the simulator's 100 mm.
    EXPECT_EQ(values(named(o, "largest_group")), (std::vector<double>{1.0, 1.0 / 3, 1.0}));
    // Asked for by name, it is an error naming the fix.
    EXPECT_NE(error_of({dir, {}, {"coverage"}, {}, 0}).find("give the world the run was in with --world FILE"),
              std::string::npos);
    // --world given: it is used.
    fs::path other = three_robots("world-elsewhere");
    MetricsOutcome with = measure_run({dir, other / "world.json", {"coverage"}, {}, 0});
    EXPECT_EQ(values(with.results[0]), (std::vector<double>{0.01, 0.03, 0.03}));
}

TEST(RunMetrics, MistakesNameTheFileAndTheFix) {
    fs::path dir = three_robots("mistakes");
    EXPECT_NE(error_of({dir / "nowhere", {}, {}, {}, 0}).find("nowhere: no such folder"), std::string::npos);
    std::string unknown = error_of({dir, {}, {"nearest_neighbor_mm"}, {}, 0});
    EXPECT_NE(unknown.find("no built-in metric of that name (did you mean \"nearest_neighbour_mm\"?)"),
              std::string::npos) << unknown;
    EXPECT_NE(unknown.find("console.csv, which is not there"), std::string::npos) << unknown;
    std::string key = error_of({dir, {}, {"largest_group:rang_mm=5"}, {}, 0});
    EXPECT_NE(key.find("largest_group takes range_mm, not \"rang_mm\""), std::string::npos) << key;
    EXPECT_NE(error_of({dir, {}, {"coverage:cell_mm=0"}, {}, 0}).find("cell_mm 0 is out of range"), std::string::npos);
    EXPECT_NE(error_of({dir, {}, {"coverage:cell_mm"}, {}, 0}).find("is not key=number"), std::string::npos);
    EXPECT_NE(error_of({dir, {}, {"coverage", "coverage:cell_mm=9"}, {}, 0}).find("given twice"), std::string::npos);
    EXPECT_NE(error_of({dir, {}, {"led_agreement:x=1"}, {}, 0}).find("takes no arguments"), std::string::npos);
    write_file(dir / "world.json", R"({"arena": {"width_mm": 500}})");
    std::string world = error_of({dir, {}, {"coverage"}, {}, 0});
    EXPECT_NE(world.find("world.json: \"arena.height_mm\": missing"), std::string::npos) << world;
}

TEST(RunMetrics, ABrokenTrajectoryFileIsNamedWithItsLine) {
    fs::path dir = three_robots("broken", false);
    write_file(dir / "trajectories.csv",
               "time_s,robot,x_mm,y_mm,heading_deg,led_r,led_g,led_b\n0.000,0,1.00,2.00,0.0,0,0,0\n0.100,0,1.0");
    std::string cut = error_of({dir, {}, {"led_agreement"}, {}, 0});
    EXPECT_NE(cut.find("trajectories.csv:3: expected 8 numbers"), std::string::npos) << cut;
    write_file(dir / "trajectories.csv", "t,x\n");
    EXPECT_NE(error_of({dir, {}, {}, {}, 0}).find("trajectories.csv:1: the header is \"t,x\""), std::string::npos);
    fs::remove(dir / "trajectories.csv");
    EXPECT_NE(error_of({dir, {}, {}, {}, 0}).find("trajectories.csv: no such file"), std::string::npos);
}
