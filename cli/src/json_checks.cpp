#include "json_checks.hpp"

#include <algorithm>
#include <cctype>
#include <map>

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

// In text, valid JSON, the second of a key given twice in one object (its
// first byte, the key and the first one's byte), or npos: nlohmann keeps
// the last silently, and a file that says a thing twice means one of them
// by mistake. A key is a string in an object followed by ':'.
size_t duplicate_key(const std::string &text, std::string &key, size_t &first) {
    struct Level {
        bool object;
        std::map<std::string, size_t> keys; // each key and where it is
    };
    std::vector<Level> levels;
    for (size_t i = 0; i < text.size(); i++) {
        char c = text[i];
        if (c == '"') {
            size_t start = i++;
            for (; i < text.size() && text[i] != '"'; i++)
                if (text[i] == '\\') i++;
            if (levels.empty() || !levels.back().object) continue;
            size_t after = i + 1;
            while (after < text.size() && std::isspace((unsigned char)text[after])) after++;
            if (after >= text.size() || text[after] != ':') continue;
            std::string name = json::parse(text.substr(start, i + 1 - start)).get<std::string>();
            auto [at, fresh] = levels.back().keys.emplace(name, start);
            if (fresh) continue;
            key = name;
            first = at->second;
            return start;
        }
        if (c == '{' || c == '[') levels.push_back({c == '{', {}});
        else if ((c == '}' || c == ']') && !levels.empty()) levels.pop_back();
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
        json doc = json::parse(text);
        std::string key;
        size_t first = 0, twice = duplicate_key(text, key, first);
        if (twice != std::string::npos)
            throw ConfigError(located_message(
                file, text, twice,
                quoted_start(key) + " is given twice in this object (also on line " +
                    std::to_string(std::count(text.begin(), text.begin() + (long)first, '\n') + 1) +
                    "): keep one"));
        return doc;
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
