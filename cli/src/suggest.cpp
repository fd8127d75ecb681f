#include "suggest.hpp"

#include <algorithm>

namespace openswarm {

static size_t edit_distance(const std::string &a, const std::string &b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); j++) row[j] = j;
    for (size_t i = 1; i <= a.size(); i++) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); j++) {
            size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = up;
        }
    }
    return row[b.size()];
}

std::string nearest(const std::string &word, const std::vector<std::string> &choices) {
    std::string best;
    size_t best_distance = word.size() / 2 + 2; // farther than this is no suggestion
    for (const auto &c : choices) {
        size_t d = edit_distance(word, c);
        if (d < best_distance) {
            best = c;
            best_distance = d;
        }
    }
    return best;
}

std::string did_you_mean(const std::string &word, const std::vector<std::string> &choices, char quote) {
    std::string hint = nearest(word, choices);
    return hint.empty() ? "" : " (did you mean " + std::string(1, quote) + hint + quote + "?)";
}

std::string join(const std::vector<std::string> &items, const std::string &sep) {
    std::string out;
    for (const auto &i : items) out += (out.empty() ? "" : sep) + i;
    return out;
}

}  // namespace openswarm
