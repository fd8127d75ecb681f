/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* world.json's "robots": groups of robots, each placed one way (its
 * "poses", a "grid", or a "count" at random in a "region" or the arena),
 * sharing a firmware, a calibration and a run of uids. Every robot must
 * stand clear of the walls, the obstacles, the objects and every robot
 * placed before it; a message names a robot by the group and the way it
 * came from, since the file has no line for a robot placed at random. */
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>

#include "world/world_file_reader.hpp"

namespace world_file {

namespace {

namespace fs = std::filesystem;

/* Random placement gives up on a robot after this many draws in a row
 * found no room: near jamming a region takes only a few more. */
constexpr int TRIES_PER_ROBOT = 20000;

}  // namespace

void Reader::group(const Node &n, int g, Draws &draws, long &next_uid) {
    const std::string example = "{\"count\": 10, \"region\": {\"x_mm\": 250, \"y_mm\": 150, \"width_mm\": 100, "
                                "\"height_mm\": 100}}";
    object(n, {"poses", "count", "region", "grid", "uid", "firmware", "calibration"}, example);

    /* What every robot of the group shares. */
    Placing p{g, robots_.size(), world_robot{}};
    p.base.firmware = -1;
    p.base.group = g;
    for (int &c : p.base.calibration) c = -2;
    if (auto f = get(n, "firmware")) p.base.firmware = firmware(*f);
    if (auto c = get(n, "calibration")) calibration(*c, p.base);
    std::optional<Node> uid_node = get(n, "uid");
    if (uid_node) next_uid = whole(*uid_node, 0, 65535, "the group's first uid", "\"uid\": 100");

    std::string way = placement(n, example);
    if (way == "poses")
        place_poses(child(n, "poses"), p);
    else if (way == "grid")
        place_grid(child(n, "grid"), p);
    else
        place_at_random(n, p, draws);
    give_uids(uid_node ? *uid_node : n, p.start, next_uid);
}

/* The ELF's index in firmware_, which holds each file once: the path is
 * relative to the world file's folder, and must name a file. */
int Reader::firmware(const Node &f) {
    if (!f->is_string() || f->get<std::string>().empty())
        fail(f, "expected the path of an ELF (relative to this file's folder), found " + found(*f) +
                    "; e.g. \"firmware\": \"build/app.elf\"");
    std::string given = f->get<std::string>();
    fs::path file(given);
    if (file.is_relative()) file = fs::path(path_).parent_path() / file;
    file = file.lexically_normal();
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
        fail(f, quote(given) + ": " + (fs::exists(file, ec) ? "not a file" : "no such file") + " (looked for " +
                    clip(fs::absolute(file, ec).string(), PATH_BYTES) + "); a firmware path is relative to the world file's folder: build the "
                    "firmware, or correct the path");
    auto known = std::find(firmware_.begin(), firmware_.end(), file.string());
    int index = (int)(known - firmware_.begin());
    if (known == firmware_.end()) firmware_.push_back(file.string());
    return index;
}

/* Four motor duties, or "erased" (-1 each); the robot's own without it. */
void Reader::calibration(const Node &c, world_robot &base) const {
    const std::string ex = "\"calibration\": [70, 70, 65, 68] (turn left, turn right, straight left, "
                           "straight right) or \"calibration\": \"erased\"";
    if (c->is_string()) {
        std::string s = c->get<std::string>();
        if (s != "erased")
            fail(c, "unknown calibration " + quote(s) + "; expected \"erased\" or four duties: " + ex);
        for (int &d : base.calibration) d = -1;
    } else {
        if (!c->is_array() || c->size() != 4)
            fail(c, "expected four motor duties 0..255 or \"erased\", found " + found(*c) + "; e.g. " + ex);
        for (size_t k = 0; k < 4; k++)
            base.calibration[k] = (int)whole(item(c, k), 0, 255, "a motor duty", ex);
    }
}

/* The one key that places the group's robots: "poses", "grid", "region"
 * (with "count"), or "" for "count" alone (at random in the arena). */
std::string Reader::placement(const Node &n, const std::string &example) const {
    const char *ways[] = {"poses", "grid", "region"};
    const char *first = nullptr;
    for (const char *way : ways) {
        if (!n->contains(way)) continue;
        if (first != nullptr)
            fail_key(child(n, way), n.name, "\"" + std::string(first) + "\" and \"" + way +
                                        "\" each place the group's robots: give one of them, and put "
                                        "the other robots in a group of their own");
        first = way;
    }
    std::optional<Node> count_node = get(n, "count");
    if (count_node && first != nullptr && std::string(first) != "region")
        fail_key(*count_node, n.name, std::string("\"count\" goes with \"region\" or alone; \"") + first +
                                  "\" already says how many robots: remove \"count\"");
    if (!count_node && first == nullptr)
        fail(n, "where do its robots stand? give \"poses\" (a list), a \"grid\", \"count\" with a \"region\" "
                "(at random in it), or \"count\" alone (at random in the arena); e.g. " + example);
    if (!count_node && std::string(first) == "region")
        fail(n, "\"region\" needs a \"count\": how many robots to place at random in it; e.g. \"count\": 10");
    return first == nullptr ? "" : first;
}

void Reader::place_poses(const Node &poses, const Placing &p) {
    const std::string ex = "{\"x_mm\": 50, \"y_mm\": 50, \"heading_deg\": 90}";
    if (!poses->is_array() || poses->empty() || poses->size() > (size_t)MAX_COUNT)
        fail(poses, "expected a list of 1.." + std::to_string(MAX_COUNT) + " poses, found " + found(*poses) +
                        "; e.g. \"poses\": [" + ex + "]");
    robots_within(poses, (long)poses->size());
    for (size_t k = 0; k < poses->size(); k++) {
        Node pose = item(poses, k);
        object(pose, {"x_mm", "y_mm", "heading_deg"}, ex);
        P at{number(need(pose, "x_mm", ex), -FAR_MM, FAR_MM, false, "x in mm", "\"x_mm\": 50"),
             number(need(pose, "y_mm", ex), -FAR_MM, FAR_MM, false, "y in mm", "\"y_mm\": 50")};
        double heading = pose->contains("heading_deg")
                             ? number(child(pose, "heading_deg"), -360, 360, false,
                                      "degrees counter-clockwise from the x axis", "\"heading_deg\": 90")
                             : 0;
        if (auto c = robot_conflict(at)) fail(pose, "this robot " + c->what + ": " + c->fix);
        place(p, at, std::fmod(heading + 360, 360), ".poses[" + std::to_string(k) + "]");
    }
}

void Reader::place_grid(const Node &grid, const Placing &p) {
    const std::string ex = "\"grid\": {\"x_mm\": 400, \"y_mm\": 100, \"columns\": 3, \"rows\": 2, \"spacing_mm\": 50}";
    object(grid, {"x_mm", "y_mm", "columns", "rows", "spacing_mm"}, ex);
    double x = number(need(grid, "x_mm", ex), -FAR_MM, FAR_MM, false, "the first robot's x in mm", "\"x_mm\": 400");
    double y = number(need(grid, "y_mm", ex), -FAR_MM, FAR_MM, false, "the first robot's y in mm", "\"y_mm\": 100");
    long columns = whole(need(grid, "columns", ex), 1, MAX_COUNT, "robots along x", "\"columns\": 3");
    long rows = whole(need(grid, "rows", ex), 1, MAX_COUNT, "robots along y", "\"rows\": 2");
    Node spacing_node = need(grid, "spacing_mm", ex);
    double spacing = number(spacing_node, BODY, FAR_MM, false,
                            "mm between neighbouring centres (" + robot_ + " is " + num(BODY) + " mm across)",
                            "\"spacing_mm\": 50");
    if (columns * rows > MAX_COUNT)
        fail(grid, std::to_string(columns) + " x " + std::to_string(rows) + " robots: more than " +
                       std::to_string(MAX_COUNT) + ", likely a typo; lower columns or rows");
    robots_within(grid, columns * rows);
    for (long row = 0; row < rows; row++)
        for (long col = 0; col < columns; col++) {
            P at{x + (double)col * spacing, y + (double)row * spacing};
            if (auto c = robot_conflict(at))
                fail(grid, "its robot at column " + std::to_string(col) + ", row " + std::to_string(row) + " " +
                               at_text(at.x, at.y) + " " + c->what + ": " + c->fix +
                               " (or move the grid, or change its columns, rows or spacing)");
            place(p, at, 0, ".grid column " + std::to_string(col) + " row " + std::to_string(row));
        }
}

void Reader::place_at_random(const Node &n, const Placing &p, Draws &draws) {
    Node count_node = child(n, "count");
    long count = whole(count_node, 1, MAX_COUNT, "how many robots",
                       "\"count\": 10 (more than " + std::to_string(MAX_COUNT) + " is taken for a typo)");
    robots_within(count_node, count);
    /* Centres are drawn from the region (the arena by default), kept a
     * radius from the walls. */
    Room room{ROBOT_R, ROBOT_R, w_ - ROBOT_R, h_ - ROBOT_R};
    Node blame = count_node;
    std::string where = "the arena";
    if (auto r = get(n, "region")) {
        blame = *r;
        where = "the region";
        region(*r, room);
    }
    for (long k = 0; k < count; k++) {
        int tries = 0;
        for (;; tries++) {
            if (tries == TRIES_PER_ROBOT || room.x1 < room.x0 || room.y1 < room.y0)
                fail(blame, "found room for " + std::to_string(k) + " of " + std::to_string(count) +
                                " robots at random without overlap (" + std::to_string(TRIES_PER_ROBOT) +
                                " draws for the next found none): " + where + " holds at most about " +
                                std::to_string(k) + " robots (seed " + std::to_string(draws.seed) +
                                "); enlarge " + where + " or lower count to " + std::to_string(k));
            /* Three draws per try, whatever happens, so the first k
             * robots stand where they stood with a larger count. */
            P at{room.x0 + draws.next() * (room.x1 - room.x0), room.y0 + draws.next() * (room.y1 - room.y0)};
            double heading = draws.next() * 360;
            if (!robot_fits(at)) continue;
            place(p, at, heading, ", placed at random");
            break;
        }
    }
}

/* Narrows room to the region r, which must lie in the arena. */
void Reader::region(const Node &r, Room &room) const {
    const std::string ex = "\"region\": {\"x_mm\": 250, \"y_mm\": 150, \"width_mm\": 100, \"height_mm\": 100}";
    object(r, {"x_mm", "y_mm", "width_mm", "height_mm"}, ex);
    double rx = number(need(r, "x_mm", ex), 0, w_, false, "the left edge's x in mm, in the arena", "\"x_mm\": 250");
    double ry = number(need(r, "y_mm", ex), 0, h_, false, "the bottom edge's y in mm, in the arena", "\"y_mm\": 150");
    double rw = number(need(r, "width_mm", ex), 0, FAR_MM, true, "a width in mm", "\"width_mm\": 100");
    double rh = number(need(r, "height_mm", ex), 0, FAR_MM, true, "a height in mm", "\"height_mm\": 100");
    if (rx + rw > w_ + EPS || ry + rh > h_ + EPS)
        fail(r, "reaches past the arena's " + std::string(rx + rw > w_ + EPS ? "right" : "top") +
                    " wall (x 0.." + num(w_) + ", y 0.." + num(h_) + "): x_mm + width_mm is " + num(rx + rw) +
                    ", y_mm + height_mm " + num(ry + rh) + "; move or shrink the region");
    room.x0 = std::max(room.x0, rx);
    room.y0 = std::max(room.y0, ry);
    room.x1 = std::min(room.x1, rx + rw);
    room.y1 = std::min(room.y1, ry + rh);
}

void Reader::place(const Placing &p, P at, double heading, const std::string &how) {
    world_robot r = p.base;
    r.at = at;
    r.heading_deg = heading;
    add_robot(r, Origin{p.group, (int)(robots_.size() - p.start), how});
}

/* The group's first uid is its "uid", or the one after the last robot's;
 * blame is where a clash is reported. */
void Reader::give_uids(const Node &blame, size_t start, long &next_uid) {
    size_t n_robots = robots_.size() - start;
    if (next_uid + (long)n_robots - 1 > 65535)
        fail(blame, "its " + std::to_string(n_robots) + " robots would get uids " +
                        std::to_string(next_uid) + ".." + std::to_string(next_uid + (long)n_robots - 1) +
                        ", past 65535: give the group a \"uid\" of at most " +
                        std::to_string(65536 - (long)n_robots));
    for (size_t k = start; k < robots_.size(); k++) {
        int uid = (int)next_uid++;
        auto taken = uids_.find(uid);
        if (taken != uids_.end()) {
            long highest = uids_.rbegin()->first;
            fail(blame, "robot " + std::to_string(k) + " (this group's robot " + std::to_string(k - start) +
                            ") would get uid " + std::to_string(uid) + ", which " + robot_name(taken->second) +
                            " has; uids are unique: give " +
                            "this group a \"uid\" clear of the others, e.g. \"uid\": " + std::to_string(highest + 1));
        }
        uids_[uid] = (int)k;
        robots_[k].uid = uid;
    }
}

std::string Reader::robot_name(int r) const {
    const Origin &o = origins_[(size_t)r];
    const world_robot &b = robots_[(size_t)r];
    return "robot " + std::to_string(r) + " (robots[" + std::to_string(o.group) + "]" + o.how + ", at " +
           at_text(b.at.x, b.at.y) + ")";
}

/* The arena's wall (0..3: left, right, bottom, top) a robot centred at c
 * reaches past (-1: none), gaps its centre's distances from each. */
int Reader::wall_hit(P c, double gaps[4]) const {
    gaps[0] = c.x;
    gaps[1] = w_ - c.x;
    gaps[2] = c.y;
    gaps[3] = h_ - c.y;
    for (int k = 0; k < 4; k++)
        if (gaps[k] < ROBOT_R - EPS) return k;
    return -1;
}

/* The lowest-numbered robot placed so far that one centred at c overlaps
 * (-1: none), d the distance between their centres. */
int Reader::robot_hit(P c, double &d) const {
    auto cx = (int64_t)std::floor(c.x / BODY), cy = (int64_t)std::floor(c.y / BODY);
    int nearest = -1;
    for (int64_t i = cx - 1; i <= cx + 1; i++)
        for (int64_t j = cy - 1; j <= cy + 1; j++) {
            auto cell = cells_.find(cell_key(i, j));
            if (cell == cells_.end()) continue;
            for (int r : cell->second) {
                const P &o = robots_[(size_t)r].at;
                double apart = std::hypot(c.x - o.x, c.y - o.y);
                if (apart < BODY - EPS && (nearest < 0 || r < nearest)) {
                    nearest = r;
                    d = apart;
                }
            }
        }
    return nearest;
}

/* Whether a robot centred at c fits: in the arena, clear of obstacles,
 * objects and every robot placed so far. Nothing is formatted: a random
 * placement asks this of every draw it rejects (a third of a short
 * 1000-robot run's time went into describing them). */
bool Reader::robot_fits(P c) const {
    double gaps[4], d;
    return wall_hit(c, gaps) < 0 && obstacle_hit(c, ROBOT_R, d) < 0 && object_hit(c, ROBOT_R, d) < 0 &&
           robot_hit(c, d) < 0;
}

/* Why a robot centred at c does not fit (robot_fits), described. */
std::optional<Reader::Conflict> Reader::robot_conflict(P c) const {
    if (robot_fits(c)) return std::nullopt;
    const char *walls[4] = {"left", "right", "bottom", "top"};
    double gaps[4];
    int k = wall_hit(c, gaps);
    if (k >= 0)
        return Conflict{std::string("reaches past the arena's ") + walls[k] + " wall: its centre is " +
                            (gaps[k] < 0 ? "outside, " + mm_beside(-gaps[k], 0) + " mm beyond it"
                                         : mm_beside(gaps[k], ROBOT_R) + " mm from it") +
                            ", " + robot_ + "'s radius is " + num(ROBOT_R) + " mm",
                        "keep robots' centres within x " + num(ROBOT_R) + ".." + num(w_ - ROBOT_R) + " and y " +
                            num(ROBOT_R) + ".." + num(h_ - ROBOT_R)};
    if (auto hit = obstacle_conflict(c, ROBOT_R, robot_ + "'s radius is " + num(ROBOT_R) + " mm"))
        return hit;
    if (auto hit = object_conflict(c, ROBOT_R, "(the object's radius + " + robot_ + "'s " + num(ROBOT_R) + ")"))
        return hit;
    double d = BODY;
    int nearest = robot_hit(c, d);
    return Conflict{"overlaps " + robot_name(nearest) + ": centres " + mm_beside(d, BODY) + " mm apart, " +
                        robots_plural_ + " are " + num(BODY) + " mm across",
                    "move them at least " + num(BODY) + " mm apart"};
}

void Reader::add_robot(const world_robot &r, const Origin &o) {
    int index = (int)robots_.size();
    robots_.push_back(r);
    origins_.push_back(o);
    cells_[cell_key((int64_t)std::floor(r.at.x / BODY), (int64_t)std::floor(r.at.y / BODY))].push_back(index);
}

}  // namespace world_file
