// "Did you mean ...?" for names a user mistyped.
#pragma once

#include <string>
#include <vector>

namespace openswarm {

// The closest of choices to word (by edit distance), or "" if none is close.
std::string nearest(const std::string &word, const std::vector<std::string> &choices);

// "a, b, c"
std::string join(const std::vector<std::string> &items, const std::string &sep = ", ");

}  // namespace openswarm
