#include "suggest.hpp"

#include <algorithm>

namespace openswarm {

// Edits from a to b, two neighbours swapped counting as one: the typo
// "unit16" is one from "uint16", where plain Levenshtein makes it two and
// suggests "int16" instead (issue 31).
static size_t edit_distance(const std::string &a, const std::string &b) {
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); i++) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); j++) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); i++) {
        for (size_t j = 1; j <= b.size(); j++) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    }
    return d[a.size()][b.size()];
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
