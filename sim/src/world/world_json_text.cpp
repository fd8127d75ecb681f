/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* world.json's text, scanned as strict JSON before nlohmann builds the
 * document from it: nlohmann keeps no positions, and its syntax messages
 * name no fix. The scanner records where each key and value starts, by
 * its JSON pointer, so every later message points at its place; it
 * refuses what JSON does not allow (comments, single quotes, trailing
 * commas, a key given twice in one object, ...) saying what to write
 * instead. */
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <utility>

#include "world/world_file_reader.hpp"

namespace world_file {

std::string pointer_child(const std::string &ptr, const std::string &key) {
    std::string escaped;
    for (char c : key) escaped += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    return ptr + "/" + escaped;
}

namespace {

class Scanner {
  public:
    explicit Scanner(const std::string &text) : t(text) {}
    TextPositions at;

    void run() {
        skip();
        if (i >= t.size()) throw Mistake{0, "the file is empty; a world is an object, e.g. "
                                            "{\"arena\": {\"width_mm\": 600, \"height_mm\": 400}}"};
        value("", 0);
        skip();
        if (i < t.size())
            throw Mistake{i, "text after the end of the world's object: remove it (or, if it "
                             "belongs inside, the '}' before it closes the world too early)"};
    }

  private:
    const std::string &t;
    size_t i = 0;

    char peek() const { return i < t.size() ? t[i] : '\0'; }

    void skip() {
        for (;;) {
            while (i < t.size() && strchr(" \t\r\n", t[i]) != nullptr) i++;
            if (t.compare(i, 2, "//") == 0 || t.compare(i, 2, "/*") == 0)
                throw Mistake{i, "JSON has no comments: remove it (a \"description\" key at the "
                                 "top may hold a note)"};
            return;
        }
    }

    [[noreturn]] void eof(const char *what) {
        throw Mistake{t.size(), std::string("the file ends ") + what +
                                    ": a closing '}' or ']' is missing (or the file was cut short)"};
    }

    /* What stands at i, for "found ..." */
    std::string found() const {
        if (i >= t.size()) return "the end of the file";
        size_t end = i;
        if (t[i] == '"') {
            end = t.find_first_of("\"\n", i + 1);
            end = end == std::string::npos ? t.size() : end + 1;
        } else {
            while (end < t.size() && (isalnum((unsigned char)t[end]) || strchr("+-._", t[end]))) end++;
            if (end == i) end = i + 1;
        }
        std::string s = t.substr(i, std::min<size_t>(end - i, 30));
        return "'" + s + "'";
    }

    void value(const std::string &ptr, int depth) {
        if (depth > 64) throw Mistake{i, "nested more than 64 deep: a world is a few levels of objects and lists"};
        at.value_at[ptr] = i;
        char c = peek();
        if (c == '{') return object(ptr, depth);
        if (c == '[') return array(ptr, depth);
        if (c == '"') return (void)string();
        if (c == '-' || isdigit((unsigned char)c)) return number();
        for (const char *word : {"true", "false", "null"}) {
            size_t n = strlen(word);
            if (t.compare(i, n, word) == 0 && !isalnum((unsigned char)(i + n < t.size() ? t[i + n] : ' '))) {
                i += n;
                return;
            }
        }
        if (i >= t.size()) eof("where a value should be");
        if (c == '\'') throw Mistake{i, "JSON strings take double quotes: write \"...\", not '...'"};
        if (c == '+' || c == '.')
            throw Mistake{i, "found " + found() + ": a JSON number starts with a digit or '-', e.g. 0.5, not .5 or +5"};
        if (c == '}' || c == ']')
            throw Mistake{i, "expected a value before '" + std::string(1, c) +
                                 "': remove the ',' before it, or give the value"};
        throw Mistake{i, "expected a value (a number, \"text\", true, false, null, [...] or {...}), found " +
                             found() + (isalpha((unsigned char)c) ? ": put text in double quotes" : "")};
    }

    void object(const std::string &ptr, int depth) {
        i++; /* { */
        skip();
        if (peek() == '}') {
            i++;
            return;
        }
        std::map<std::string, size_t> seen;
        for (;;) {
            skip();
            if (peek() != '"') {
                if (i >= t.size()) eof("inside an object");
                if (peek() == '}') throw Mistake{i, "a ',' before '}': remove the last ','"};
                if (peek() == '\'') throw Mistake{i, "JSON keys take double quotes: write \"key\", not 'key'"};
                throw Mistake{i, "expected a key in double quotes, found " + found() +
                                     (isalpha((unsigned char)peek()) ? ": write \"" + found().substr(1, found().size() - 2) + "\"" : "")};
            }
            size_t key_start = i;
            std::string key = string();
            auto before = seen.find(key);
            if (before != seen.end())
                throw Mistake{key_start, quote(key) + " is given twice in this object (also on line " +
                                             std::to_string(line_of(before->second)) + "): keep one"};
            seen[key] = key_start;
            std::string child = pointer_child(ptr, key);
            at.key_at[child] = key_start;
            skip();
            if (peek() != ':') {
                if (i >= t.size()) eof("after a key");
                throw Mistake{i, "expected ':' after " + quote(key) + ", found " + found()};
            }
            i++;
            skip();
            value(child, depth + 1);
            skip();
            if (peek() == ',') {
                i++;
                continue;
            }
            if (peek() == '}') {
                i++;
                return;
            }
            if (i >= t.size()) eof("inside an object");
            throw Mistake{i, "expected ',' or '}' after the value of " + quote(key) + ", found " + found() +
                                 (peek() == '"' ? ": a ',' is missing before it" : "")};
        }
    }

    size_t line_of(size_t byte) const { return (size_t)std::count(t.begin(), t.begin() + (long)byte, '\n') + 1; }

    void array(const std::string &ptr, int depth) {
        i++; /* [ */
        skip();
        if (peek() == ']') {
            i++;
            return;
        }
        for (size_t n = 0;; n++) {
            skip();
            value(ptr + "/" + std::to_string(n), depth + 1);
            skip();
            if (peek() == ',') {
                i++;
                continue;
            }
            if (peek() == ']') {
                i++;
                return;
            }
            if (i >= t.size()) eof("inside a list");
            throw Mistake{i, "expected ',' or ']' after item " + std::to_string(n) + " of the list, found " +
                                 found() + (strchr("\"{[-0123456789", peek()) ? ": a ',' is missing before it" : "")};
        }
    }

    static void utf8(std::string &out, unsigned cp) {
        if (cp < 0x80) {
            out += (char)cp;
        } else if (cp < 0x800) {
            out += (char)(0xC0 | cp >> 6);
            out += (char)(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += (char)(0xE0 | cp >> 12);
            out += (char)(0x80 | (cp >> 6 & 0x3F));
            out += (char)(0x80 | (cp & 0x3F));
        } else {
            out += (char)(0xF0 | cp >> 18);
            out += (char)(0x80 | (cp >> 12 & 0x3F));
            out += (char)(0x80 | (cp >> 6 & 0x3F));
            out += (char)(0x80 | (cp & 0x3F));
        }
    }

    unsigned hex4() {
        unsigned v = 0;
        for (int k = 0; k < 4; k++, i++) {
            char c = peek();
            if (!isxdigit((unsigned char)c)) throw Mistake{i, "expected four hex digits after \\u, e.g. \\u00b0"};
            v = v * 16 + (unsigned)(isdigit((unsigned char)c) ? c - '0' : tolower(c) - 'a' + 10);
        }
        return v;
    }

    /* The string at i, decoded as nlohmann decodes it (keys must match). */
    std::string string() {
        size_t start = i++;
        std::string out;
        for (;;) {
            if (i >= t.size())
                throw Mistake{start, "this string is never closed: add the '\"' that ends it"};
            char c = t[i];
            if (c == '"') {
                i++;
                return out;
            }
            if ((unsigned char)c < 0x20)
                throw Mistake{i, c == '\n' ? "a line break inside a string: close the string with '\"' before it"
                                           : "a control character inside a string: write it as \\t or \\u00XX"};
            if (c != '\\') {
                out += c;
                i++;
                continue;
            }
            i++;
            if (i >= t.size()) throw Mistake{start, "this string is never closed: add the '\"' that ends it"};
            char e = peek();
            const char *from = "\"\\/bfnrt", *to = "\"\\/\b\f\n\r\t";
            const char *k = e != '\0' ? strchr(from, e) : nullptr;
            if (k != nullptr) {
                out += to[k - from];
                i++;
            } else if (e == 'u') {
                i++;
                unsigned cp = hex4();
                if (cp >= 0xD800 && cp < 0xDC00 && t.compare(i, 2, "\\u") == 0) {
                    i += 2;
                    unsigned low = hex4();
                    cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
                }
                utf8(out, cp);
            } else {
                throw Mistake{i - 1, "unknown escape '\\" + std::string(1, e) +
                                         "': write \\\\ for a backslash (or / in paths)"};
            }
        }
    }

    void number() {
        size_t start = i;
        if (peek() == '-') i++;
        if (!isdigit((unsigned char)peek())) throw Mistake{start, "expected a number after '-', e.g. -5"};
        if (peek() == '0' && i + 1 < t.size() && isdigit((unsigned char)t[i + 1]))
            throw Mistake{start, "a JSON number has no leading zeros: write " +
                                     std::to_string(std::atol(t.c_str() + start))};
        while (isdigit((unsigned char)peek())) i++;
        if (peek() == '.') {
            i++;
            if (!isdigit((unsigned char)peek()))
                throw Mistake{start, "expected digits after the '.', e.g. 2.0 or 2"};
            while (isdigit((unsigned char)peek())) i++;
        }
        if (peek() == 'e' || peek() == 'E') {
            i++;
            if (peek() == '+' || peek() == '-') i++;
            if (!isdigit((unsigned char)peek())) throw Mistake{start, "expected the exponent's digits, e.g. 1e3"};
            while (isdigit((unsigned char)peek())) i++;
        }
        if (!std::isfinite(strtod(t.substr(start, i - start).c_str(), nullptr)))
            throw Mistake{start, "this number is too large for any world: check it"};
        if (isalpha((unsigned char)peek()))
            throw Mistake{start, "found " + found() + " after a number: units go in the key's name "
                                                      "(\"x_mm\": 50), not after the value"};
    }
};

}  // namespace

TextPositions scan_json_text(const std::string &text) {
    Scanner scanner(text);
    scanner.run();
    return std::move(scanner.at);
}

}  // namespace world_file
