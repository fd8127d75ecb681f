#include "experiment_failures.hpp"

namespace openswarm {

namespace {

// Each failure as "TRIAL LENGTH\n" and then LENGTH bytes of its reason:
// the reason is taken whole, whatever it holds. (Tab- and newline-ended
// records cut a simulator's message at its first newline, and rank 0
// died on std::stoul of the line after it.)
void append_failure(std::string &text, size_t trial, const std::string &reason) {
    text += std::to_string(trial) + ' ' + std::to_string(reason.size()) + '\n' + reason;
}

// A whole number of at most 19 digits (no overflow) from text[at] up to
// the character stop, which at then moves past.
bool number_until(const std::string &text, size_t &at, char stop, size_t &value) {
    size_t end = text.find(stop, at);
    if (end == std::string::npos || end == at || end - at > 19) return false;
    value = 0;
    for (size_t i = at; i < end; i++) {
        if (text[i] < '0' || text[i] > '9') return false;
        value = value * 10 + (size_t)(text[i] - '0');
    }
    at = end + 1;
    return true;
}

}  // namespace

std::string encode_failures(const std::vector<TrialOutcome> &outcomes) {
    std::string text;
    for (size_t k = 0; k < outcomes.size(); k++)
        if (outcomes[k].here && !outcomes[k].failure.empty()) append_failure(text, k, outcomes[k].failure);
    return text;
}

bool decode_failures(const std::string &text, std::vector<TrialOutcome> &outcomes, std::string &why) {
    for (size_t at = 0; at < text.size();) {
        const std::string where = "at byte " + std::to_string(at) + " of " + std::to_string(text.size());
        size_t trial = 0, length = 0;
        if (!number_until(text, at, ' ', trial) || !number_until(text, at, '\n', length)) {
            why = where + ": expected \"TRIAL LENGTH\\n\"";
            return false;
        }
        if (trial >= outcomes.size()) {
            why = where + ": trial " + std::to_string(trial) + ", of " + std::to_string(outcomes.size());
            return false;
        }
        if (length > text.size() - at) {
            why = where + ": a reason of " + std::to_string(length) + " bytes, " +
                  std::to_string(text.size() - at) + " left";
            return false;
        }
        outcomes[trial].failure = text.substr(at, length);
        at += length;
    }
    return true;
}

}  // namespace openswarm
