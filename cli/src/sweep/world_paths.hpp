// A place in a world.json named as the world file's messages name it:
// keys joined by '.', list items by [index] ("robots[0].count",
// "ir.loss_percent"), every item of a list by [*] ("objects[*].mass_g"),
// for a sweep to set.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace openswarm {

// Why path cannot be set in world ("" if it can): malformed, a list item
// the world does not have, a key inside something that is not an object.
// Missing objects on the way are made, as the world's defaults apply.
std::string world_path_problem(const nlohmann::json &world, const std::string &path);

// Sets the value at path (world_path_problem said "").
void set_world_path(nlohmann::json &world, const std::string &path, const nlohmann::json &value);

}  // namespace openswarm
