// The end of what a program wrote, for a message that says why it failed.
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace openswarm {

// The last `count` lines of text (without their line breaks).
inline std::vector<std::string> last_lines(const std::string &text, size_t count) {
    std::vector<std::string> all;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) all.push_back(line);
    if (all.size() > count) all.erase(all.begin(), all.end() - (long)count);
    return all;
}

}  // namespace openswarm
