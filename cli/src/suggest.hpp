// "Did you mean ...?" for names a user mistyped.
#pragma once

#include <string>
#include <vector>

namespace openswarm {

// The closest of choices to word (by edit distance), or "" if none is close.
std::string nearest(const std::string &word, const std::vector<std::string> &choices);

// " (did you mean "x"?)" for the nearest choice, "" if none is close.
std::string did_you_mean(const std::string &word, const std::vector<std::string> &choices,
                         char quote = '"');

// "a, b, c"
std::string join(const std::vector<std::string> &items, const std::string &sep = ", ");

}  // namespace openswarm
