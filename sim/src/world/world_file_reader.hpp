/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* What the pieces of the world file's reader share, and nothing outside
 * them uses (world_spec.h is the reader's face):
 *   world_file.cpp           world_spec_load: the top level, the report
 *   world_json_text.cpp      the text scanned as strict JSON, with positions
 *   world_file_checks.cpp    the checks of single values, the words of messages
 *   world_file_geometry.cpp  distances and crossings
 *   world_file_arena.cpp     the arena, obstacles, objects, lights
 *   world_file_robots.cpp    the groups of robots, placed
 *   world_file_eeprom.cpp    the bytes the robots' EEPROM holds */
#ifndef OPENSWARM_WORLD_FILE_READER_HPP
#define OPENSWARM_WORLD_FILE_READER_HPP

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

#include "world/world_random.h"
#include "world/world_spec.h"

namespace world_file {

using nlohmann::json;
using P = world_point;

constexpr double FAR_MM = 100000.0; /* 100 m: beyond any table, a typo */
constexpr long MAX_COUNT = 10000;   /* more robots in a group: a typo */
constexpr double EPS = 1e-9;        /* touching is not overlapping */

/* A mistake in the file: the byte it is reported at, and the message. */
struct Mistake {
    size_t byte;
    std::string text;
};

/* ---- world_json_text.cpp -------------------------------------------- */

/* Where each key and each value starts in the text, by JSON pointer:
 * nlohmann keeps no positions. */
struct TextPositions {
    std::map<std::string, size_t> value_at, key_at;
};

/* Scans text as strict JSON; throws a Mistake at the first thing that is not. */
TextPositions scan_json_text(const std::string &text);
/* The JSON pointer of the member key of the object at ptr. */
std::string pointer_child(const std::string &ptr, const std::string &key);

/* ---- world_file_checks.cpp: the words of messages -------------------- */

std::string mm(double v);  /* a measured length */
std::string num(double v); /* a bound, as written */
/* A measured length v that a check found on one side of bound: with one
 * decimal, or as many more as it takes to read on that side of bound as
 * num() prints it (16.49 mm from a wall where 16.5 is the least is not
 * "16.5 mm"). */
std::string mm_beside(double v, double bound);
std::string at_text(double x, double y);
std::string found(const json &v); /* a value of the document, for "found ..." */
/* Text from the file echoed in a message is clipped: a value may be a
 * megabyte on one line. */
constexpr size_t ECHO_BYTES = 60;  /* a value or a key */
constexpr size_t PATH_BYTES = 240; /* a path made from one */
constexpr size_t LINE_BYTES = 100; /* the line under a message, either side of the caret */
/* Whether c is a UTF-8 character's tail byte: no cut falls before one. */
inline bool continues_character(char c) { return ((unsigned char)c & 0xC0) == 0x80; }
/* text, or its start cut between UTF-8 characters and "..." added, in at
 * most `bytes` bytes. */
std::string clip(const std::string &text, size_t bytes = ECHO_BYTES);
/* A string from the file, clipped, in double quotes. */
std::string quote(const std::string &text);

/* ---- world_file_geometry.cpp ----------------------------------------- */

double cross(P o, P a, P b);
/* Whether segments ab and cd share a point (touching counts). */
bool segments_meet(P a, P b, P c, P d);
/* How far p lies from the obstacle's outline; 0 inside it. */
double obstacle_distance(P p, const world_obstacle &o);

/* ---- The Reader: the document, walked with names and positions ------- */

/* The placement's own stream (world_random.h): the same on every machine. */
struct Draws {
    uint64_t state;
    uint32_t seed; /* the world's, for messages */
    double next() { return world_random_uniform(&state); }
};

/* A value in the document: its key path for messages ("robots[1].region")
 * and its JSON pointer for the scanner's positions. */
struct Node {
    const json *v;
    std::string name, ptr;
    const json &operator*() const { return *v; }
    const json *operator->() const { return v; }
};

/* Where a robot came from, to name it in messages. */
struct Origin {
    int group, k;    /* robots[group], its k-th robot */
    std::string how; /* ".poses[3]", ".grid column 1 row 0", ", placed at random" */
};

class Reader {
  public:
    Reader(const std::string &path, const TextPositions &at) : path_(path), at_(at) {}

    /* world_file.cpp: the whole world, then the C arrays world_spec_free frees. */
    world_spec load(const json &doc);
    void export_to(world_spec &w) const;

    /* world_file_checks.cpp: each check throws a Mistake at the value's
     * place, naming its key path, what was expected and what was found. */
    [[noreturn]] void fail(const Node &n, const std::string &message) const;
    /* At n's key; the message names the object holding it (parent). */
    [[noreturn]] void fail_key(const Node &n, const std::string &parent, const std::string &message) const;
    Node child(const Node &n, const std::string &key) const;
    Node item(const Node &n, size_t k) const;
    /* An object with only these keys. */
    void object(const Node &n, const std::vector<std::string> &allowed, const std::string &example) const;
    std::optional<Node> get(const Node &n, const std::string &key) const;
    Node need(const Node &n, const std::string &key, const std::string &example) const;
    /* A number in lo..hi (above lo when lo_open). */
    double number(const Node &n, double lo, double hi, bool lo_open, const std::string &what,
                  const std::string &example) const;
    long whole(const Node &n, long lo, long hi, const std::string &what, const std::string &example) const;

  private:
    std::string path_;
    const TextPositions &at_;

    /* The world under construction. */
    int kind_ = WORLD_ROBOT_KILOBOT;
    double ROBOT_R = KILOBOT_RADIUS_MM;
    double BODY = 2 * KILOBOT_RADIUS_MM; /* two centres closer overlap */
    std::string robot_ = "a Kilobot", robots_plural_ = "Kilobots"; /* for messages */
    double w_ = 0, h_ = 0;
    std::vector<world_obstacle> obstacles_;
    std::vector<world_object> objects_;
    std::vector<world_light> lights_;
    std::vector<world_robot> robots_;
    std::vector<Origin> origins_;
    std::vector<std::string> firmware_;
    std::unordered_map<int64_t, std::vector<int>> cells_; /* robots by 33 mm square, for overlap */
    std::map<int, int> uids_;                             /* uid -> robot */

    struct Conflict {
        std::string what, fix;
    };

    /* world_file.cpp: the top level's settings. */
    void robot_kind(const Node &n);
    int fidelity(const Node &n);
    void ir(const Node &n, world_spec &w);

    /* world_file_arena.cpp: the arena and what stands in it besides robots. */
    void arena(const Node &n);
    void obstacle(const Node &n);
    void rect_corners(const Node &rect, world_obstacle &o, std::vector<Node> &where) const;
    void polygon_vertices(const Node &polygon, world_obstacle &o, std::vector<Node> &where) const;
    void check_in_arena(const world_obstacle &o, const std::vector<Node> &where, bool rect) const;
    void check_outline(const Node &shape, const world_obstacle &o, const std::vector<Node> &where) const;
    void movable_object(const Node &n); /* "objects": one that robots push */
    void light(const Node &n, world_spec &w);
    void noise(const Node &n, world_spec &w);
    void camera(const Node &n, world_spec &w);
    void camera_noise(const Node &n, world_spec &w); /* "camera": "pixel_noise", "misread_pct_per_m" */
    std::optional<Conflict> round_conflict(P c, double r) const; /* an object's */
    int obstacle_hit(P c, double r, double &d) const;
    int object_hit(P c, double r, double &d) const;
    std::optional<Conflict> obstacle_conflict(P c, double r, const std::string &radius) const;
    std::optional<Conflict> object_conflict(P c, double r, const std::string &needed) const;

    /* world_file_eeprom.cpp: "eeprom", bytes every robot starts with. */
    void eeprom(const Node &n, world_spec &w) const;

    /* world_file_limits.cpp: what one world may hold. */
    int obstacle_vertices_ = 0; /* the obstacles' so far */
    void list_within(const Node &list, const char *what, size_t limit, const std::string &fix) const;
    void obstacle_vertices_within(const Node &n, int added);
    void robots_within(const Node &blame, long count) const; /* a group of count more */

    /* world_file_robots.cpp: the groups of robots, placed. */
    struct Placing {
        int group;
        size_t start;     /* the group's first robot */
        world_robot base; /* what all its robots share */
    };
    struct Room {
        double x0, y0, x1, y1; /* where random centres are drawn */
    };
    void group(const Node &n, int g, Draws &draws, long &next_uid);
    int firmware(const Node &f);
    void calibration(const Node &c, world_robot &base) const;
    std::string placement(const Node &n, const std::string &example) const;
    void place_poses(const Node &poses, const Placing &p);
    void place_grid(const Node &grid, const Placing &p);
    void place_at_random(const Node &n, const Placing &p, Draws &draws);
    void region(const Node &r, Room &room) const;
    void place(const Placing &p, P at, double heading, const std::string &how);
    void give_uids(const Node &blame, size_t start, long &next_uid);
    std::string robot_name(int r) const;
    int wall_hit(P c, double gaps[4]) const;
    int robot_hit(P c, double &d) const;
    bool robot_fits(P c) const;
    std::optional<Conflict> robot_conflict(P c) const;
    void add_robot(const world_robot &r, const Origin &o);
    static int64_t cell_key(int64_t cx, int64_t cy) { return cx * 4000037 + cy; }
};

}  // namespace world_file

#endif
