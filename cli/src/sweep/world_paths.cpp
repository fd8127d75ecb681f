#include "world_paths.hpp"

#include <cctype>
#include <vector>

using nlohmann::json;

namespace openswarm {

namespace {

// A step of a path: a key, or a list index (key empty), or every item of
// a list ([*]: key empty, every set).
struct Step {
    std::string key;
    size_t index = 0;
    bool every = false;
};

bool key_char(char c) { return std::isalnum((unsigned char)c) || c == '_'; }

// The steps, or why the text is no path.
bool parse(const std::string &path, std::vector<Step> &steps, std::string &why) {
    size_t i = 0;
    while (i < path.size()) {
        if (!steps.empty() && path[i] == '[') {
            size_t close = path.find(']', i);
            std::string digits = close == std::string::npos ? "" : path.substr(i + 1, close - i - 1);
            if (digits == "*") {
                steps.push_back({"", 0, true});
                i = close + 1;
                continue;
            }
            if (digits.empty() || digits.size() > 6 ||
                digits.find_first_not_of("0123456789") != std::string::npos) {
                why = "\"" + path + "\": a list item is [N], N a whole number, or [*] for every item, e.g. "
                      "robots[0].count or objects[*].mass_g";
                return false;
            }
            steps.push_back({"", std::stoul(digits)});
            i = close + 1;
            continue;
        }
        if (!steps.empty()) {
            if (path[i] != '.') break;
            i++;
        }
        size_t start = i;
        while (i < path.size() && key_char(path[i])) i++;
        if (i == start) { // no key after a '.' or at the start
            i = path.size() + 1;
            break;
        }
        steps.push_back({path.substr(start, i - start), 0});
    }
    if (i == path.size() && !steps.empty() && !steps.back().key.empty()) return true;
    why = "\"" + path + "\" is not a place in a world: keys joined by '.', list items by [N], ending in a "
          "key, e.g. \"arena.width_mm\", \"robots[0].count\" or \"objects[*].mass_g\"";
    return false;
}

}  // namespace

std::string world_path_problem(const json &world, const std::string &path) {
    std::vector<Step> steps;
    std::string why;
    if (!parse(path, steps, why)) return why;
    const json *at = &world;
    std::string walked;
    for (const Step &step : steps) {
        if (step.every) { // the first item stands for all: the world file checks the rest
            if (!at->is_array() || at->empty())
                return "the world's " + walked + " has no items for [*] to set" +
                       (at->is_array() ? " (it is empty)" : " (it is not a list)");
            at = &(*at)[0];
            walked += "[*]";
            continue;
        }
        if (step.key.empty()) {
            if (!at->is_array() || step.index >= at->size())
                return "the world's " + walked + " has no item [" + std::to_string(step.index) + "]" +
                       (at->is_array() ? " (it holds " + std::to_string(at->size()) + ")" : " (it is not a list)");
            at = &(*at)[step.index];
            walked += "[" + std::to_string(step.index) + "]";
            continue;
        }
        if (!at->is_null() && !at->is_object())
            return "the world's " + walked + " is not an object, so it has no \"" + step.key + "\"";
        walked += (walked.empty() ? "" : ".") + step.key;
        static const json none;
        at = at->is_object() && at->contains(step.key) ? &(*at)[step.key] : &none;
    }
    return "";
}

namespace {

void set_from(json &at, const std::vector<Step> &steps, size_t k, const json &value) {
    if (k == steps.size()) {
        at = value;
        return;
    }
    const Step &step = steps[k];
    if (step.every)
        for (json &item : at) set_from(item, steps, k + 1, value);
    else
        set_from(step.key.empty() ? at[step.index] : at[step.key], steps, k + 1, value);
}

}  // namespace

void set_world_path(json &world, const std::string &path, const json &value) {
    std::vector<Step> steps;
    std::string why;
    parse(path, steps, why);
    set_from(world, steps, 0, value);
}

}  // namespace openswarm
