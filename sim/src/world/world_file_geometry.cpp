/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The plane geometry the world file's checks need: whether an obstacle's
 * outline crosses itself, and how far a point lies from an obstacle (a
 * robot or an object must stand clear of it). Within EPS, touching is not
 * overlapping, so shapes placed edge to edge in the file are accepted. */
#include <algorithm>
#include <cmath>

#include "world/world_file_reader.hpp"

namespace world_file {

namespace {

bool on_segment(P p, P a, P b) {
    return std::min(a.x, b.x) - EPS <= p.x && p.x <= std::max(a.x, b.x) + EPS &&
           std::min(a.y, b.y) - EPS <= p.y && p.y <= std::max(a.y, b.y) + EPS;
}

double segment_distance(P p, P a, P b) {
    double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
    double s = len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(p.x - (a.x + s * dx), p.y - (a.y + s * dy));
}

bool inside(P p, const world_obstacle &o) {
    bool in = false;
    for (int k = 0, j = o.n - 1; k < o.n; j = k++) {
        const P &a = o.v[k], &b = o.v[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
    }
    return in;
}

}  // namespace

double cross(P o, P a, P b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

bool segments_meet(P a, P b, P c, P d) {
    double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
    if (((d1 > EPS && d2 < -EPS) || (d1 < -EPS && d2 > EPS)) && ((d3 > EPS && d4 < -EPS) || (d3 < -EPS && d4 > EPS)))
        return true;
    return (std::fabs(d1) <= EPS && on_segment(a, c, d)) || (std::fabs(d2) <= EPS && on_segment(b, c, d)) ||
           (std::fabs(d3) <= EPS && on_segment(c, a, b)) || (std::fabs(d4) <= EPS && on_segment(d, a, b));
}

double obstacle_distance(P p, const world_obstacle &o) {
    if (inside(p, o)) return 0;
    double d = INFINITY;
    for (int k = 0; k < o.n; k++) d = std::min(d, segment_distance(p, o.v[k], o.v[(k + 1) % o.n]));
    return d;
}

}  // namespace world_file
