#include "json_checks.hpp"

#include <algorithm>

#include "suggest.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace openswarm {

// Errors name the key's path, what was expected and what was found.
[[noreturn]] void fail(const fs::path &file, const std::string &path, const std::string &message) {
    throw ConfigError(file.string() + ": " + (path.empty() ? "" : "\"" + path + "\": ") + message);
}

std::string found(const json &v) {
    std::string text = v.dump();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return std::string(v.type_name()) + " " + text;
}

void check_keys(const fs::path &file, const std::string &path, const json &object,
                const std::vector<std::string> &allowed) {
    for (const auto &[key, value] : object.items()) {
        (void)value;
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
        fail(file, path.empty() ? key : path + "." + key,
             "unknown key; expected one of " + join(allowed) +
                 did_you_mean(key, allowed));
    }
}

const json &require(const fs::path &file, const json &doc, const std::string &key,
                    const std::string &parent) {
    if (!doc.contains(key))
        fail(file, parent.empty() ? key : parent + "." + key, "missing; add \"" + key + "\" there");
    return doc.at(key);
}

std::string string_at(const fs::path &file, const std::string &path, const json &v, const char *what) {
    if (!v.is_string()) fail(file, path, std::string("expected ") + what + ", found " + found(v));
    return v.get<std::string>();
}

long number_at(const fs::path &file, const std::string &path, const json &v, long min, long max) {
    if (!v.is_number_integer() || v.get<long>() < min || v.get<long>() > max)
        fail(file, path, "expected a whole number " + std::to_string(min) + ".." + std::to_string(max) +
                             ", found " + found(v));
    return v.get<long>();
}

json parse_json_file(const fs::path &file, const std::string &text) {
    try {
        return json::parse(text);
    } catch (const json::parse_error &e) {
        std::string what = e.what();
        size_t colon = what.rfind(": ");
        std::string reason = colon == std::string::npos ? what : what.substr(colon + 2);
        throw ConfigError(located_message(file, text, e.byte > 0 ? e.byte - 1 : 0, "invalid JSON: " + reason));
    } catch (const json::exception &e) { // a number beyond a double's range: no place given
        std::string what = e.what();
        size_t bracket = what.find("] ");
        throw ConfigError(file.string() + ": invalid JSON: " +
                          (bracket == std::string::npos ? what : what.substr(bracket + 2)) +
                          "; write a smaller number");
    }
}

double real_at(const fs::path &file, const std::string &path, const json &v, double min, double max) {
    if (!v.is_number() || v.get<double>() < min || v.get<double>() > max) {
        char range[64];
        std::snprintf(range, sizeof range, "%g..%g", min, max);
        fail(file, path, std::string("expected a number ") + range + ", found " + found(v));
    }
    return v.get<double>();
}

}  // namespace openswarm
