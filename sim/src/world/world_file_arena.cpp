/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* world.json's arena and what stands in it besides the robots: its size,
 * the fixed obstacles (a rectangle or a simple polygon inside the arena),
 * the movable objects and the light sources.
 * Obstacles and objects come before the robots in the world, so the
 * robots' placement (world_file_robots.cpp) asks here whether a place is
 * clear of them. */
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "world/kilobot_light.h"
#include "world/world_file_reader.hpp"

namespace world_file {

void Reader::arena(const Node &n) {
    const std::string example = "\"arena\": {\"width_mm\": 600, \"height_mm\": 400}";
    object(n, {"width_mm", "height_mm"}, example);
    w_ = number(need(n, "width_mm", example), BODY, FAR_MM, false, "the arena's width in mm", "\"width_mm\": 600");
    h_ = number(need(n, "height_mm", example), BODY, FAR_MM, false, "the arena's height in mm", "\"height_mm\": 400");
}

void Reader::obstacle(const Node &n) {
    const std::string example = "{\"rect\": {\"x_mm\": 100, \"y_mm\": 100, \"width_mm\": 50, \"height_mm\": 20}} "
                                "or {\"polygon\": [[300, 50], [350, 50], [325, 90]]}";
    object(n, {"rect", "polygon"}, example);
    bool rect = n->contains("rect");
    if (rect == n->contains("polygon"))
        fail(n, std::string(rect ? "\"rect\" and \"polygon\" both given: an obstacle is one shape; "
                                   "split it into two obstacles"
                                 : "expected a \"rect\" or a \"polygon\"; e.g. ") +
                    (rect ? "" : example));
    world_obstacle o{};
    std::vector<Node> where; /* each vertex's node, for messages */
    Node shape = child(n, rect ? "rect" : "polygon");
    if (rect)
        rect_corners(shape, o, where);
    else
        polygon_vertices(shape, o, where);
    check_in_arena(o, where, rect);
    check_outline(shape, o, where);
    obstacle_vertices_within(n, o.n);
    obstacles_.push_back(o);
}

void Reader::rect_corners(const Node &rect, world_obstacle &o, std::vector<Node> &where) const {
    const std::string ex = "\"rect\": {\"x_mm\": 100, \"y_mm\": 100, \"width_mm\": 50, \"height_mm\": 20}";
    object(rect, {"x_mm", "y_mm", "width_mm", "height_mm"}, ex);
    double x = number(need(rect, "x_mm", ex), -FAR_MM, FAR_MM, false, "the left edge's x in mm", "\"x_mm\": 100");
    double y = number(need(rect, "y_mm", ex), -FAR_MM, FAR_MM, false, "the bottom edge's y in mm", "\"y_mm\": 100");
    double rw = number(need(rect, "width_mm", ex), 0, FAR_MM, true, "a width in mm", "\"width_mm\": 50");
    double rh = number(need(rect, "height_mm", ex), 0, FAR_MM, true, "a height in mm", "\"height_mm\": 20");
    o.n = 4;
    o.v[0] = {x, y};
    o.v[1] = {x + rw, y};
    o.v[2] = {x + rw, y + rh};
    o.v[3] = {x, y + rh};
    where.assign(4, rect);
}

void Reader::polygon_vertices(const Node &polygon, world_obstacle &o, std::vector<Node> &where) const {
    const std::string ex = "\"polygon\": [[300, 50], [350, 50], [325, 90]]";
    if (!polygon->is_array() || polygon->size() < 3 || polygon->size() > WORLD_MAX_VERTICES)
        fail(polygon, "expected a list of 3.." + std::to_string(WORLD_MAX_VERTICES) + " vertices [x_mm, y_mm], found " +
                          (polygon->is_array() ? std::to_string(polygon->size()) + " vertices" : found(*polygon)) + "; e.g. " + ex +
                          (polygon->is_array() && polygon->size() > WORLD_MAX_VERTICES ? " (split a larger shape into several obstacles)" : ""));
    o.n = (int)polygon->size();
    for (int k = 0; k < o.n; k++) {
        Node v = item(polygon, (size_t)k);
        if (!v->is_array() || v->size() != 2 || !(*v)[0].is_number() || !(*v)[1].is_number())
            fail(v, "expected a vertex [x_mm, y_mm], two numbers, found " + found(*v) + "; e.g. [300, 50]");
        o.v[k] = {number(item(v, 0), -FAR_MM, FAR_MM, false, "x in mm", "[300, 50]"),
                  number(item(v, 1), -FAR_MM, FAR_MM, false, "y in mm", "[300, 50]")};
        where.push_back(v);
    }
}

void Reader::check_in_arena(const world_obstacle &o, const std::vector<Node> &where, bool rect) const {
    for (int k = 0; k < o.n; k++) {
        const P &p = o.v[k];
        if (p.x < -EPS || p.x > w_ + EPS || p.y < -EPS || p.y > h_ + EPS)
            fail(where[(size_t)k], (rect ? "its corner " : "vertex ") + at_text(p.x, p.y) +
                                       " lies outside the arena (x 0.." + num(w_) + ", y 0.." + num(h_) +
                                       "): move the obstacle inside, or enlarge the arena");
    }
}

/* A simple polygon with area: no vertex repeated, no zero-width spike,
 * no two edges crossing. */
void Reader::check_outline(const Node &shape, const world_obstacle &o, const std::vector<Node> &where) const {
    for (int k = 0; k < o.n; k++) {
        P a = o.v[k], b = o.v[(k + 1) % o.n], c = o.v[(k + 2) % o.n];
        if (std::hypot(b.x - a.x, b.y - a.y) <= EPS)
            fail(where[(size_t)(k + 1) % o.n], "vertex " + std::to_string((k + 1) % o.n) + " repeats vertex " +
                                                   std::to_string(k) + ": remove one of them");
        double turn = cross(a, b, c), dot = (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y);
        if (std::fabs(turn) <= EPS && dot < 0)
            fail(shape, "the outline doubles back on itself at vertex " + std::to_string((k + 1) % o.n) +
                            " (a zero-width spike, or all vertices on one line): list the vertices in order "
                            "around a shape with area");
    }
    for (int k = 0; k < o.n; k++)
        for (int j = k + 2; j < o.n; j++) {
            if (k == 0 && j == o.n - 1) continue; /* neighbours through vertex 0 */
            if (segments_meet(o.v[k], o.v[k + 1], o.v[j], o.v[(j + 1) % o.n]))
                fail(shape, "the edges from vertex " + std::to_string(k) + " to " + std::to_string(k + 1) +
                                " and from vertex " + std::to_string(j) + " to " + std::to_string((j + 1) % o.n) +
                                " cross: list the vertices in order around the shape (or split it into "
                                "several obstacles)");
        }
}

/* The first obstacle a disc at c, radius r, reaches into (-1: none), d
 * its centre's distance from it. */
int Reader::obstacle_hit(P c, double r, double &d) const {
    for (size_t k = 0; k < obstacles_.size(); k++)
        if ((d = obstacle_distance(c, obstacles_[k])) < r - EPS) return (int)k;
    return -1;
}

/* obstacle_hit's, described; `radius` says what r is ("its radius 20 mm"). */
std::optional<Reader::Conflict> Reader::obstacle_conflict(P c, double r, const std::string &radius) const {
    double d;
    int k = obstacle_hit(c, r, d);
    if (k < 0) return std::nullopt;
    return Conflict{d == 0 ? "has its centre inside obstacles[" + std::to_string(k) + "]"
                           : "overlaps obstacles[" + std::to_string(k) + "]: its centre is " + mm_beside(d, r) +
                                 " mm from it, " + radius,
                    "move it at least " + num(r) + " mm clear of the obstacle"};
}

/* The first object a disc at c, radius r, overlaps (-1: none), d the
 * distance between their centres. */
int Reader::object_hit(P c, double r, double &d) const {
    for (size_t k = 0; k < objects_.size(); k++) {
        const world_object &b = objects_[k];
        if ((d = std::hypot(c.x - b.at.x, c.y - b.at.y)) < r + b.radius_mm - EPS) return (int)k;
    }
    return -1;
}

/* object_hit's, described; `needed` says why the centres must be that far
 * apart ("(the radii added)"). */
std::optional<Reader::Conflict> Reader::object_conflict(P c, double r, const std::string &needed) const {
    double d;
    int k = object_hit(c, r, d);
    if (k < 0) return std::nullopt;
    const world_object &b = objects_[(size_t)k];
    return Conflict{"overlaps objects[" + std::to_string(k) + "] at " + at_text(b.at.x, b.at.y) + ": centres " +
                        mm_beside(d, r + b.radius_mm) + " mm apart, at least " + num(r + b.radius_mm) +
                        " needed " + needed,
                    "move them apart"};
}

/* Whether a round thing (an object) at c, radius r, fits: in the arena,
 * clear of obstacles and of the objects before it. */
std::optional<Reader::Conflict> Reader::round_conflict(P c, double r) const {
    /* Wherever its centre, it reaches past a wall (and the range for the
     * centre below would run backwards). */
    if (2 * r > w_ + 2 * EPS || 2 * r > h_ + 2 * EPS)
        return Conflict{"is " + num(2 * r) + " mm across, more than the arena (" + num(w_) + " x " + num(h_) +
                            " mm) holds",
                        "lower radius_mm to at most " + num(std::min(w_, h_) / 2) + ", or enlarge the arena"};
    if (c.x - r < -EPS || c.x + r > w_ + EPS || c.y - r < -EPS || c.y + r > h_ + EPS)
        return Conflict{"reaches past the arena's walls (x 0.." + num(w_) + ", y 0.." + num(h_) + ")",
                        "keep its centre within x " + num(r) + ".." + num(w_ - r) + " and y " + num(r) + ".." +
                            num(h_ - r)};
    if (auto hit = obstacle_conflict(c, r, "its radius " + num(r) + " mm")) return hit;
    return object_conflict(c, r, "(the radii added)");
}

void Reader::movable_object(const Node &n) {
    const std::string example = "{\"x_mm\": 200, \"y_mm\": 200, \"radius_mm\": 20, \"mass_g\": 10, \"friction\": 0.5}";
    object(n, {"x_mm", "y_mm", "radius_mm", "mass_g", "friction"}, example);
    world_object o{};
    o.at.x = number(need(n, "x_mm", example), -FAR_MM, FAR_MM, false, "x in mm", "\"x_mm\": 200");
    o.at.y = number(need(n, "y_mm", example), -FAR_MM, FAR_MM, false, "y in mm", "\"y_mm\": 200");
    o.radius_mm = number(need(n, "radius_mm", example), 1, 1000, false, "a radius in mm", "\"radius_mm\": 20");
    o.mass_g = n->contains("mass_g")
                   ? number(child(n, "mass_g"), 0, 100000, true, "a mass in grams", "\"mass_g\": 10")
                   : 10;
    o.friction = n->contains("friction")
                     ? number(child(n, "friction"), 0, 2, false, "a friction coefficient", "\"friction\": 0.5")
                     : 0.5;
    if (auto c = round_conflict(o.at, o.radius_mm)) fail(n, "this object " + c->what + ": " + c->fix);
    objects_.push_back(o);
}

void Reader::light(const Node &n, world_spec &w) {
    const std::string example = "\"light\": {\"ambient_mv\": 300, \"sources\": [{\"x_mm\": 500, \"y_mm\": 200, "
                                "\"intensity_mv\": 2000}]}";
    object(n, {"ambient_mv", "shadow", "sources"}, example);
    if (auto a = get(n, "ambient_mv"))
        w.ambient_light_mv = number(*a, 0, 5000, false, "the light sensor's input with no source near, in mV",
                                    "\"ambient_mv\": 300");
    if (auto s = get(n, "shadow")) {
        if (!s.value()->is_boolean())
            fail(*s, "expected true (the robot's battery shades its light sensor) or false (no shadow), found " +
                         found(**s) + "; e.g. \"shadow\": false");
        w.light_unshaded = !s.value()->get<bool>();
    }
    auto sources = get(n, "sources");
    if (!sources) return;
    const std::string ex = "{\"x_mm\": 500, \"y_mm\": 200, \"intensity_mv\": 2000, \"height_mm\": 150}";
    if (!sources.value()->is_array())
        fail(*sources, "expected a list of light sources, found " + found(**sources) + "; e.g. [" + ex + "]");
    for (size_t k = 0; k < sources.value()->size(); k++) {
        Node s = item(*sources, k);
        object(s, {"x_mm", "y_mm", "intensity_mv", "height_mm"}, ex);
        world_light l{};
        /* A lamp may stand beyond the arena's walls, as beside a table. */
        l.at.x = number(need(s, "x_mm", ex), -FAR_MM, FAR_MM, false, "x in mm", "\"x_mm\": 500");
        l.at.y = number(need(s, "y_mm", ex), -FAR_MM, FAR_MM, false, "y in mm", "\"y_mm\": 200");
        l.intensity_mv = number(need(s, "intensity_mv", ex), 0, 100000, false,
                                "what it adds to a light sensor 100 mm away, in mV", "\"intensity_mv\": 2000");
        l.height_mm = s->contains("height_mm")
                          ? number(child(s, "height_mm"), 0, FAR_MM, false,
                                   "the bulb's height above the floor in mm", "\"height_mm\": 150")
                          : KILOBOT_LIGHT_DEFAULT_HEIGHT_MM;
        lights_.push_back(l);
    }
}

}  // namespace world_file
