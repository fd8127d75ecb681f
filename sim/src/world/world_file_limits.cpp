/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* world.json: what one world may hold (world_spec.h's WORLD_MAX_*,
 * docs/world.md's "Limits"). Past them a world is refused while it is
 * read, at the list or group that goes over, instead of running into
 * undefined territory: 10000 identical obstacles took 2.7 GB and then
 * crashed in Box2D's broad phase (issue 30). */
#include <string>

#include "world/world_file_reader.hpp"

namespace world_file {

namespace {

const std::string obstacles_why =
    "every two overlapping obstacle edges are paired when the world starts, in memory growing with their square";

}  // namespace

void Reader::list_within(const Node &list, const char *what, size_t limit, const std::string &fix) const {
    if (list->size() <= limit) return;
    fail(list, std::to_string(list->size()) + " " + what + ": at most " + std::to_string(limit) +
                   " in one world (docs/world.md, \"Limits\"); " + fix);
}

void Reader::obstacle_vertices_within(const Node &n, int added) {
    obstacle_vertices_ += added;
    if (obstacle_vertices_ <= WORLD_MAX_OBSTACLE_VERTICES) return;
    fail(n, "the obstacles up to this one have " + std::to_string(obstacle_vertices_) + " vertices: at most " +
                std::to_string(WORLD_MAX_OBSTACLE_VERTICES) + " in one world, as many edges (" + obstacles_why +
                "; docs/world.md, \"Limits\"); merge neighbouring obstacles into one polygon, or simplify them");
}

void Reader::robots_within(const Node &blame, long count) const {
    size_t total = robots_.size() + (size_t)count;
    if (total <= WORLD_MAX_ROBOTS) return;
    fail(blame, "this group's " + std::to_string(count) + " robots bring the world's to " + std::to_string(total) +
                    ": at most " + std::to_string(WORLD_MAX_ROBOTS) +
                    " in one world (docs/world.md, \"Limits\"); lower this group's count to at most " +
                    std::to_string(WORLD_MAX_ROBOTS - robots_.size()));
}

}  // namespace world_file
