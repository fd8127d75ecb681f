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

std::string text_start(const std::string &text, size_t bytes) {
    if (text.size() <= bytes) return text;
    size_t cut = bytes;
    while (cut > 0 && ((unsigned char)text[cut] & 0xC0u) == 0x80u) cut--; // not inside a character
    return text.substr(0, cut) + "...";
}

std::string quoted_start(const std::string &text) { return "\"" + text_start(text, 40) + "\""; }

// "number 7", "string \"x\"", "object {...}"; null is its own name, not "null null".
std::string found(const json &v) {
    if (v.is_null()) return "null";
    return std::string(v.type_name()) + " " + text_start(v.dump(), 37);
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

namespace {

// The first byte nested deeper than max_depth (outside strings), or npos:
// the checks print and copy values recursively, and no file we read needs
// more than a few levels.
size_t too_deep(const std::string &text, size_t max_depth) {
    size_t depth = 0;
    bool in_string = false, escaped = false;
    for (size_t i = 0; i < text.size(); i++) {
        char c = text[i];
        if (in_string) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > max_depth) return i;
        } else if ((c == ']' || c == '}') && depth > 0) {
            depth--;
        }
    }
    return std::string::npos;
}

}  // namespace

json parse_json_file(const fs::path &file, const std::string &text) {
    size_t nul = text.find('\0');
    if (nul != std::string::npos)
        throw ConfigError(located_message(file, text, nul, "a NUL byte: a JSON file is text; "
                                                           "remove it (and whatever was written after it)"));
    size_t deep = too_deep(text, max_json_depth);
    if (deep != std::string::npos)
        throw ConfigError(located_message(file, text, deep, "nested more than " + std::to_string(max_json_depth) +
                                                                " levels deep; the file needs a few at most"));
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
