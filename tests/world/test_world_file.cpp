// world.json reader (sim/src/world/world_file.cpp): what it builds, that
// random placement repeats, and that every message points at the right
// line and column.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "world_file_fixture.hpp"

namespace {

const char *full_example = R"({
  "arena": {"width_mm": 600, "height_mm": 400},
  "seed": 7,
  "duration_s": 120,
  "ir": {"range_mm": 80, "loss_pct": 10},
  "clock_spread_pct": 0.5,
  "light": {"ambient_mv": 300, "sources": [{"x_mm": 700, "y_mm": 200, "intensity_mv": 2000}]},
  "obstacles": [{"rect": {"x_mm": 100, "y_mm": 100, "width_mm": 50, "height_mm": 20}},
                {"polygon": [[300, 50], [350, 50], [325, 90]]}],
  "objects": [{"x_mm": 200, "y_mm": 200, "radius_mm": 20}],
  "robots": [
    {"poses": [{"x_mm": 50, "y_mm": 50, "heading_deg": 90}, {"x_mm": 100, "y_mm": 50, "heading_deg": -90}]},
    {"count": 8, "region": {"x_mm": 230, "y_mm": 230, "width_mm": 150, "height_mm": 150}},
    {"grid": {"x_mm": 420, "y_mm": 100, "columns": 3, "rows": 2, "spacing_mm": 50}},
    {"count": 2, "uid": 100, "calibration": [70, 71, 65, 68]},
    {"count": 1, "calibration": "erased"}
  ]
})";

TEST_F(WorldFile, ReadsEverySection) {
    world_spec w{};
    ASSERT_EQ(load(full_example, &w), "");
    EXPECT_EQ(w.width_mm, 600);
    EXPECT_EQ(w.height_mm, 400);
    EXPECT_EQ(w.seed, 7u);
    EXPECT_EQ(w.duration_s, 120);
    EXPECT_DOUBLE_EQ(w.sample_period_s, 0.1);
    EXPECT_EQ(w.ir_range_mm, 80);
    EXPECT_EQ(w.ir_loss_pct, 10);
    EXPECT_EQ(w.clock_spread_pct, 0.5);
    EXPECT_EQ(w.ambient_light_mv, 300);
    ASSERT_EQ(w.n_lights, 1); // beyond the arena's wall: allowed
    EXPECT_EQ(w.lights[0].at.x, 700);
    EXPECT_EQ(w.lights[0].height_mm, 150); // a desk lamp unless the file says
    ASSERT_EQ(w.n_obstacles, 2);
    ASSERT_EQ(w.obstacles[0].n, 4);
    EXPECT_EQ(w.obstacles[0].v[2].x, 150);
    EXPECT_EQ(w.obstacles[0].v[2].y, 120);
    EXPECT_EQ(w.obstacles[1].n, 3);
    ASSERT_EQ(w.n_objects, 1);
    EXPECT_EQ(w.objects[0].mass_g, 10);    // default
    EXPECT_EQ(w.objects[0].friction, 0.5); // default
    ASSERT_EQ(w.n_robots, 2 + 8 + 6 + 2 + 1);
    EXPECT_EQ(w.robots[0].heading_deg, 90);
    EXPECT_EQ(w.robots[1].heading_deg, 270);
    for (int i = 0; i < 16; i++) EXPECT_EQ(w.robots[i].uid, i + 1);
    EXPECT_EQ(w.robots[16].uid, 100);
    EXPECT_EQ(w.robots[17].uid, 101);
    EXPECT_EQ(w.robots[18].uid, 102);
    EXPECT_EQ(w.robots[0].calibration[0], -2);
    EXPECT_EQ(w.robots[17].calibration[1], 71);
    EXPECT_EQ(w.robots[18].calibration[3], -1);
    EXPECT_EQ(w.robots[0].firmware, -1);
    EXPECT_EQ(w.n_firmware, 0);
    // The grid: columns along x, rows along y, heading 0.
    EXPECT_EQ(w.robots[10].at.x, 420);
    EXPECT_EQ(w.robots[12].at.x, 520);
    EXPECT_EQ(w.robots[13].at.y, 150);
    EXPECT_EQ(w.robots[13].heading_deg, 0);
    world_spec_free(&w);
}

TEST_F(WorldFile, DefaultsWhenOnlyTheArenaIsGiven) {
    world_spec w{};
    ASSERT_EQ(load(R"({"arena": {"width_mm": 300, "height_mm": 200}})", &w), "");
    EXPECT_EQ(w.seed, 1u);
    EXPECT_EQ(w.duration_s, -1);
    EXPECT_EQ(w.ir_range_mm, -1);
    EXPECT_EQ(w.ir_loss_pct, -1);
    EXPECT_EQ(w.clock_spread_pct, -1);
    EXPECT_EQ(w.ambient_light_mv, 0);
    EXPECT_EQ(w.n_robots, 0);
    EXPECT_EQ(w.robots, nullptr);
    world_spec_free(&w);
}

// Random robots: inside their region, apart from each other and from
// everything else, at the same places every time; a larger count keeps the
// first robots where they were.
TEST_F(WorldFile, RandomPlacementIsDeterministicAndValid) {
    auto world = [](int seed, int count) {
        return "{\"arena\": {\"width_mm\": 600, \"height_mm\": 600}, \"seed\": " + std::to_string(seed) +
               ", \"objects\": [{\"x_mm\": 300, \"y_mm\": 300, \"radius_mm\": 20}], \"robots\": [{\"count\": " +
               std::to_string(count) +
               ", \"region\": {\"x_mm\": 200, \"y_mm\": 200, \"width_mm\": 200, \"height_mm\": 200}}]}";
    };
    world_spec a{}, b{}, c{}, d{};
    ASSERT_EQ(load(world(7, 20), &a), "");
    ASSERT_EQ(load(world(7, 20), &b), "");
    ASSERT_EQ(load(world(8, 20), &c), "");
    ASSERT_EQ(load(world(7, 25), &d), "");
    bool differs = false;
    for (int i = 0; i < 20; i++) {
        EXPECT_EQ(a.robots[i].at.x, b.robots[i].at.x);
        EXPECT_EQ(a.robots[i].at.y, b.robots[i].at.y);
        EXPECT_EQ(a.robots[i].heading_deg, b.robots[i].heading_deg);
        EXPECT_EQ(a.robots[i].at.x, d.robots[i].at.x);
        differs |= a.robots[i].at.x != c.robots[i].at.x;
        EXPECT_GE(a.robots[i].at.x, 200);
        EXPECT_LE(a.robots[i].at.x, 400);
        EXPECT_GE(a.robots[i].at.y, 200);
        EXPECT_LE(a.robots[i].at.y, 400);
        EXPECT_GE(a.robots[i].heading_deg, 0);
        EXPECT_LT(a.robots[i].heading_deg, 360);
        EXPECT_GE(std::hypot(a.robots[i].at.x - 300, a.robots[i].at.y - 300), 36.5);
        for (int j = 0; j < i; j++)
            EXPECT_GE(std::hypot(a.robots[i].at.x - a.robots[j].at.x, a.robots[i].at.y - a.robots[j].at.y), 33);
    }
    EXPECT_TRUE(differs);
    for (world_spec *w : {&a, &b, &c, &d}) world_spec_free(w);
}

// Robots at random anywhere keep their bodies inside the arena.
TEST_F(WorldFile, CountAloneFillsTheArena) {
    world_spec w{};
    ASSERT_EQ(load(R"({"arena": {"width_mm": 400, "height_mm": 300}, "robots": [{"count": 40}]})", &w), "");
    ASSERT_EQ(w.n_robots, 40);
    for (int i = 0; i < 40; i++) {
        EXPECT_GE(w.robots[i].at.x, 16.5);
        EXPECT_LE(w.robots[i].at.x, 400 - 16.5);
        EXPECT_GE(w.robots[i].at.y, 16.5);
        EXPECT_LE(w.robots[i].at.y, 300 - 16.5);
    }
    world_spec_free(&w);
}

TEST_F(WorldFile, FirmwareIsRelativeToTheFileAndShared) {
    write("worlds/seed.elf", "x");
    write("worlds/build/follower.elf", "x");
    world_spec w{};
    ASSERT_EQ(load(R"({"arena": {"width_mm": 600, "height_mm": 400}, "robots": [
        {"count": 1, "firmware": "seed.elf"},
        {"count": 3, "firmware": "build/follower.elf"},
        {"count": 1, "firmware": "./seed.elf"},
        {"count": 1}]})",
                   &w, "worlds/w.json"),
              "");
    ASSERT_EQ(w.n_firmware, 2);
    EXPECT_EQ(fs::path(w.firmware[0]), (dir / "worlds/seed.elf").lexically_normal());
    EXPECT_EQ(fs::path(w.firmware[1]), (dir / "worlds/build/follower.elf").lexically_normal());
    EXPECT_EQ(w.robots[0].firmware, 0);
    EXPECT_EQ(w.robots[3].firmware, 1);
    EXPECT_EQ(w.robots[4].firmware, 0);
    EXPECT_EQ(w.robots[5].firmware, -1);
    world_spec_free(&w);
}

TEST_F(WorldFile, AFailureLeavesTheSpecUntouched) {
    world_spec w{};
    w.n_robots = 1234;
    EXPECT_NE(load(R"({"arena": {"width_mm": 600}})", &w), "");
    EXPECT_EQ(w.n_robots, 1234);
}

TEST_F(WorldFile, MissingFileSaysSo) {
    world_spec w{};
    testing::internal::CaptureStderr();
    EXPECT_EQ(world_spec_load((dir / "none.json").c_str(), &w), -1);
    EXPECT_NE(testing::internal::GetCapturedStderr().find("none.json: No such file"), std::string::npos);
}

// Positions: line and column (1-based, in characters) of the key or value
// at fault, whatever comes before it on the line.
TEST_F(WorldFile, UnknownKeyPointsAtTheKey) {
    EXPECT_EQ(error_of("{\n  \"arena\": {\"width_mm\": 600, \"height_mm\": 400},\n  \"robots\": [\n"
                       "    {\"count\": 3, \"reigon\": {}}\n  ]\n}\n"),
              "world.json:4:18: robots[0]: unknown key \"reigon\"; did you mean \"region\"?\n"
              "        {\"count\": 3, \"reigon\": {}}\n"
              "                     ^\n");
}

// Of several unknown keys, the first in the file is named (nlohmann keeps
// keys sorted).
TEST_F(WorldFile, FirstUnknownKeyInTheFile) {
    std::string err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400, "zz": 1, "aa": 2}})");
    EXPECT_EQ(err.substr(0, err.find('\n')),
              "world.json:1:47: arena: unknown key \"zz\"; the keys here are width_mm, height_mm");
}

TEST_F(WorldFile, ColumnsCountCharactersAndTabs) {
    // "é" is two bytes, one column; a tab is one column and the caret line
    // keeps it, so the caret stands under the value in any tab width.
    std::string err = error_of("{\"description\": \"é\",\t\"arena\": {\"width_mm\": -1, \"height_mm\": 400}}");
    EXPECT_EQ(err.substr(0, err.find('\n')),
              "world.json:1:44: arena.width_mm: expected the arena's width in mm 33..100000, found -1; "
              "e.g. \"width_mm\": 600");
    EXPECT_NE(err.find("\n    " + std::string(20, ' ') + "\t" + std::string(22, ' ') + "^\n"), std::string::npos) << err;
}

// A UTF-8 byte order mark (Notepad's "UTF-8 with BOM") is not JSON but is
// accepted, as in openswarm.json; columns on the first line do not count it.
TEST_F(WorldFile, AByteOrderMarkIsAccepted) {
    const std::string bom = "\xEF\xBB\xBF";
    world_spec w{};
    ASSERT_EQ(load(bom + R"({"arena": {"width_mm": 600, "height_mm": 400}, "seed": 5})", &w), "");
    EXPECT_EQ(w.seed, 5u);
    world_spec_free(&w);
    EXPECT_EQ(error_of(bom + R"({"seed": -3, "arena": {"width_mm": 600, "height_mm": 400}})"),
              "world.json:1:10: seed: expected the random seed, a whole number 0..4294967295, found -3; e.g. \"seed\": 7\n"
              "    {\"seed\": -3, \"arena\": {\"width_mm\": 600, \"height_mm\": 400}}\n"
              "             ^\n");
}

// A lamp's height decides how the robot's battery shades it: a height
// below the floor is refused where it stands, with the range and an example.
TEST_F(WorldFile, WindowsLineEndings) {
    std::string err = error_of("{\r\n\"arena\": {\"width_mm\": 600, \"height_mm\": 400},\r\n\"seed\": -3\r\n}\r\n");
    EXPECT_EQ(err.substr(0, err.find('\n')),
              "world.json:3:9: seed: expected the random seed, a whole number 0..4294967295, found -3; e.g. \"seed\": 7");
    EXPECT_NE(err.find("\n    \"seed\": -3\n"), std::string::npos) << err;
}

TEST_F(WorldFile, NestedValuesAreLocated) {
    std::string err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400},
"obstacles": [
  {"rect": {"x_mm": 1, "y_mm": 1, "width_mm": 5, "height_mm": 5}},
  {"polygon": [[10, 10], [20, 10],
               [20, "x"]]}
]})");
    EXPECT_EQ(err.substr(0, err.find('\n')),
              "world.json:5:16: obstacles[1].polygon[2]: expected a vertex [x_mm, y_mm], two numbers, found a list "
              "[20,\"x\"]; e.g. [300, 50]");
}

TEST_F(WorldFile, KeysWithEscapesAreLocated) {
    std::string err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400}, "a\/b\u00e9": 1})");
    EXPECT_EQ(err.substr(0, err.find('\n')),
              "world.json:1:48: unknown key \"a/b\xc3\xa9\"; the keys here are description, robot, arena, seed, duration_s, "
              "sample_period_s, fidelity, ir, clock_spread_pct, light, noise, camera, obstacles, objects, robots, eeprom");
}

TEST_F(WorldFile, SyntaxErrorsArePlaced) {
    auto first_line = [&](const std::string &text) {
        std::string err = error_of(text);
        return err.substr(0, err.find('\n'));
    };
    EXPECT_EQ(first_line("{\"arena\": {\"width_mm\": 600 \"height_mm\": 400}}"),
              "world.json:1:28: expected ',' or '}' after the value of \"width_mm\", found '\"height_mm\"': a ',' is "
              "missing before it");
    EXPECT_EQ(first_line("{\"robots\": [1, 2,]}"),
              "world.json:1:18: expected a value before ']': remove the ',' before it, or give the value");
    EXPECT_EQ(first_line("{\"seed\": 07}"), "world.json:1:10: a JSON number has no leading zeros: write 7");
    EXPECT_EQ(first_line("{\"seed\": 7,\n\"arena\": {\"width_mm\": 6\n"),
              "world.json:3:1: the file ends inside an object: a closing '}' or ']' is missing (or the file was cut short)");
    EXPECT_EQ(first_line("{arena: 1}"),
              "world.json:1:2: expected a key in double quotes, found 'arena': write \"arena\"");
    EXPECT_EQ(first_line(""),
              "world.json:1:1: the file is empty; a world is an object, e.g. {\"arena\": {\"width_mm\": 600, "
              "\"height_mm\": 400}}");
    EXPECT_EQ(first_line("{\"arena\": {\"width_mm\": 600, \"height_mm\": 400}} x"),
              "world.json:1:48: text after the end of the world's object: remove it (or, if it belongs inside, the "
              "'}' before it closes the world too early)");
    EXPECT_EQ(first_line("{\"seed\": 1e999}"), "world.json:1:10: this number is too large for any world: check it");
}

// A value or a key of a megabyte is echoed clipped, in the message and in
// the line shown under it (100 bytes either side of the caret).
TEST_F(WorldFile, LongValuesAreClipped) {
    const std::string head = R"({"arena": {"width_mm": 600, "height_mm": 400}, "robot": ")";
    std::string err = error_of(head + std::string(1000000, 'a') + "\"}");
    EXPECT_EQ(err, "world.json:1:57: robot: unknown robot \"" + std::string(57, 'a') + "...\"; known: kilobot, epuck\n"
                   "    " + head + std::string(99, 'a') + "...\n"
                   "    " + std::string(56, ' ') + "^\n");
    // The caret far along a long line: the line is cut before it too.
    std::string key = std::string(1000000, 'k');
    err = error_of("{\"description\": \"" + std::string(1000, 'd') + "\", \"" + key +
                   "\": 1, \"arena\": {\"width_mm\": 600, \"height_mm\": 400}}");
    EXPECT_EQ(err, "world.json:1:1021: unknown key \"" + std::string(57, 'k') +
                       "...\"; the keys here are description, robot, arena, seed, duration_s, sample_period_s, "
                       "fidelity, ir, clock_spread_pct, light, noise, camera, obstacles, objects, robots, eeprom\n"
                       "    ..." + std::string(97, 'd') + "\", \"" + std::string(99, 'k') + "...\n"
                       "       " + std::string(100, ' ') + "^\n");
    // A cut does not split a character ("é" is two bytes).
    std::string e;
    for (int k = 0; k < 100; k++) e += "\xc3\xa9";
    err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400}, "fidelity": ")" + e + "\"}");
    EXPECT_NE(err.find("unknown fidelity \"" + e.substr(0, 56) + "...\"; known"), std::string::npos) << err;
}

TEST_F(WorldFile, PhysicalConflictsNameBothSides) {
    std::string err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400},
"robots": [{"poses": [{"x_mm": 100, "y_mm": 100}]},
           {"grid": {"x_mm": 40, "y_mm": 120, "columns": 4, "rows": 1, "spacing_mm": 40}}]})");
    EXPECT_EQ(err.substr(0, err.find('\n')),
              "world.json:3:21: robots[1].grid: its robot at column 1, row 0 (80.0, 120.0) overlaps robot 0 "
              "(robots[0].poses[0], at (100.0, 100.0)): centres 28.3 mm apart, Kilobots are 33 mm across: move them "
              "at least 33 mm apart (or move the grid, or change its columns, rows or spacing)");
}

// An object larger than the arena fits nowhere: said so, not as a range
// for its centre that runs backwards ("x 1000..-400").
TEST_F(WorldFile, AnObjectLargerThanTheArenaIsSaidNotToFit) {
    std::string err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400},
"objects": [{"x_mm": 300, "y_mm": 200, "radius_mm": 250}]})");
    EXPECT_EQ(err.substr(0, err.find('\n')),
              "world.json:2:13: objects[0]: this object is 500 mm across, more than the arena (600 x 400 mm) holds: "
              "lower radius_mm to at most 200, or enlarge the arena");
    // As large as the arena's height: it fits, centred.
    EXPECT_EQ(error_of(R"({"arena": {"width_mm": 600, "height_mm": 400},
"objects": [{"x_mm": 300, "y_mm": 200, "radius_mm": 200}]})"),
              "");
}

// A distance refused for being under a limit is printed under it, with as
// many decimals as that takes: not "16.5 mm from it" where 16.5 is allowed.
TEST_F(WorldFile, DistancesUnderALimitArePrintedUnderIt) {
    auto first_line = [&](const std::string &rest) {
        std::string err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400}, )" + rest + "}");
        return err.substr(0, err.find('\n'));
    };
    EXPECT_EQ(first_line(R"("robots": [{"poses": [{"x_mm": 16.49, "y_mm": 100}]}])"),
              "world.json:1:70: robots[0].poses[0]: this robot reaches past the arena's left wall: its centre is "
              "16.49 mm from it, a Kilobot's radius is 16.5 mm: keep robots' centres within x 16.5..583.5 and y "
              "16.5..383.5");
    EXPECT_NE(first_line(R"("robots": [{"poses": [{"x_mm": 583.5001, "y_mm": 100}]}])")
                  .find("right wall: its centre is 16.4999 mm from it"),
              std::string::npos);
    EXPECT_NE(first_line(R"("robots": [{"poses": [{"x_mm": -0.01, "y_mm": 100}]}])")
                  .find("left wall: its centre is outside, 0.01 mm beyond it"),
              std::string::npos);
    EXPECT_NE(first_line(R"("robots": [{"poses": [{"x_mm": 100, "y_mm": 100}, {"x_mm": 132.99, "y_mm": 100}]}])")
                  .find("centres 32.99 mm apart, Kilobots are 33 mm across"),
              std::string::npos);
    EXPECT_NE(first_line(R"("objects": [{"x_mm": 300, "y_mm": 200, "radius_mm": 20}],
                            "robots": [{"poses": [{"x_mm": 336.49, "y_mm": 200}]}])")
                  .find("centres 36.49 mm apart, at least 36.5 needed"),
              std::string::npos);
    EXPECT_NE(first_line(R"("obstacles": [{"rect": {"x_mm": 100, "y_mm": 100, "width_mm": 50, "height_mm": 20}}],
                            "robots": [{"poses": [{"x_mm": 83.51, "y_mm": 110}]}])")
                  .find("overlaps obstacles[0]: its centre is 16.49 mm from it"),
              std::string::npos);
    // A whole tenth under the limit reads as before.
    EXPECT_NE(first_line(R"("robots": [{"poses": [{"x_mm": 16.4, "y_mm": 100}]}])").find("its centre is 16.4 mm from it"),
              std::string::npos);
}

TEST_F(WorldFile, RegionTooSmallSaysHowManyFit) {
    std::string err = error_of(R"({"arena": {"width_mm": 600, "height_mm": 400}, "seed": 3,
"robots": [{"count": 10, "region": {"x_mm": 250, "y_mm": 150, "width_mm": 40, "height_mm": 40}}]})");
    EXPECT_NE(err.find("world.json:2:36: robots[0].region: found room for "), std::string::npos) << err;
    EXPECT_NE(err.find("enlarge the region or lower count to"), std::string::npos) << err;
    // The count it names fits, with the same seed.
    size_t at = err.find("lower count to ") + strlen("lower count to ");
    int fits = std::atoi(err.c_str() + at);
    EXPECT_GT(fits, 0);
    EXPECT_EQ(error_of(R"({"arena": {"width_mm": 600, "height_mm": 400}, "seed": 3,
"robots": [{"count": )" + std::to_string(fits) +
                       R"(, "region": {"x_mm": 250, "y_mm": 150, "width_mm": 40, "height_mm": 40}}]})"),
              "");
}

TEST_F(WorldFile, PolygonsMustBeSimple) {
    auto first_line = [&](const std::string &polygon) {
        std::string err = error_of("{\"arena\": {\"width_mm\": 600, \"height_mm\": 400}, \"obstacles\": [{\"polygon\": " +
                                   polygon + "}]}");
        return err.substr(0, err.find('\n'));
    };
    EXPECT_EQ(first_line("[[0, 0], [100, 0], [100, 100], [0, 100]]"), "");
    EXPECT_EQ(first_line("[[0, 0], [100, 0], [50, 50], [100, 100], [0, 100]]"), ""); // concave
    EXPECT_NE(first_line("[[0, 0], [100, 100], [100, 0], [0, 100]]").find("cross"), std::string::npos);
    EXPECT_NE(first_line("[[0, 0], [50, 0], [100, 0]]").find("doubles back"), std::string::npos);
    EXPECT_NE(first_line("[[0, 0], [0, 0], [100, 0], [0, 100]]").find("vertex 1 repeats vertex 0"), std::string::npos);
    // Two loops sharing a vertex.
    EXPECT_NE(first_line("[[0, 0], [50, 50], [100, 0], [100, 100], [50, 50], [0, 100]]").find("cross"),
              std::string::npos);
}

TEST_F(WorldFile, UidsAreUniqueAndInRange) {
    EXPECT_NE(error_of(R"({"arena": {"width_mm": 600, "height_mm": 400},
"robots": [{"count": 3, "uid": 65534}]})")
                  .find("world.json:2:32: robots[0].uid: its 3 robots would get uids 65534..65536, past 65535: give the "
                        "group a \"uid\" of at most 65533"),
              std::string::npos);
    EXPECT_NE(error_of(R"({"arena": {"width_mm": 600, "height_mm": 400},
"robots": [{"count": 3, "uid": 10}, {"count": 1, "uid": 12}]})")
                  .find("robots[1].uid: robot 3 (this group's robot 0) would get uid 12, which robot 2 (robots[0], "
                        "placed at random, at "),
              std::string::npos);
}

} // namespace

namespace {

TEST_F(WorldFile, EpuckWorldsPlaceEpuckSizedRobots) {
    world_spec w{};
    ASSERT_EQ(load(R"({"robot": "epuck", "arena": {"width_mm": 400, "height_mm": 300},
                      "robots": [{"poses": [{"x_mm": 100, "y_mm": 100}, {"x_mm": 180, "y_mm": 100}]}]})",
                   &w),
              "");
    EXPECT_EQ(w.robot_kind, WORLD_ROBOT_EPUCK);
    EXPECT_DOUBLE_EQ(w.robot_radius_mm, EPUCK_RADIUS_MM);
    world_spec_free(&w);
    // 60 mm apart: two Kilobots would fit, two e-pucks overlap.
    EXPECT_NE(error_of(R"({"robot": "epuck", "arena": {"width_mm": 400, "height_mm": 300},
                          "robots": [{"poses": [{"x_mm": 100, "y_mm": 100}, {"x_mm": 160, "y_mm": 100}]}]})")
                  .find("e-pucks are 74 mm across"),
              std::string::npos);
    EXPECT_NE(error_of(R"({"robot": "epuck", "arena": {"width_mm": 400, "height_mm": 300},
                          "robots": [{"poses": [{"x_mm": 20, "y_mm": 100}]}]})")
                  .find("an e-puck's radius is 37 mm"),
              std::string::npos);
}

TEST_F(WorldFile, UnknownRobotKindIsNamedWithTheNearestKnown) {
    std::string err = error_of(R"({"robot": "epuk", "arena": {"width_mm": 400, "height_mm": 300}})");
    EXPECT_EQ(err.substr(0, err.find('\n')),
              "world.json:1:11: robot: unknown robot \"epuk\"; known: kilobot, epuck (did you mean \"epuck\"?)");
}

}  // namespace
