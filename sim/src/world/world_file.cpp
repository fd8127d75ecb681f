/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* world.json (docs/world.md): read, check and place, before anything runs.
 * Every mistake is reported once, as "file:line:column: key.path: what is
 * wrong; what to do", with the line and a caret under the place. nlohmann
 * keeps no positions, so the text is first scanned here (strict JSON, its
 * own syntax messages), recording where each key and value starts by its
 * JSON pointer; nlohmann then builds the document from the same text. */
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

#include "suggest.hpp"
#include "world/world_spec.h"
#include "world/world_random.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr double FAR_MM = 100000.0;           /* 100 m: beyond any table, a typo */
constexpr long MAX_COUNT = 10000;             /* more robots in a group: a typo */
/* Random placement gives up on a robot after this many draws in a row
 * found no room: near jamming a region takes only a few more. */
constexpr int TRIES_PER_ROBOT = 20000;
constexpr double EPS = 1e-9; /* touching is not overlapping */

struct Mistake {
    size_t byte;
    std::string text;
};

std::string format(const char *fmt, double v) {
    char buf[64];
    snprintf(buf, sizeof buf, fmt, v);
    return buf;
}
std::string mm(double v) { return format("%.1f", v); }  /* a measured length */
std::string num(double v) { return format("%g", v); }   /* a bound, as written */
std::string at_text(double x, double y) { return "(" + mm(x) + ", " + mm(y) + ")"; }

std::string pointer_child(const std::string &ptr, const std::string &key) {
    std::string escaped;
    for (char c : key) escaped += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    return ptr + "/" + escaped;
}

/* ---- The scanner: strict JSON, with positions ------------------------ */

class Scanner {
  public:
    explicit Scanner(const std::string &text) : t(text) {}
    std::map<std::string, size_t> value_at, key_at;

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
        value_at[ptr] = i;
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
                throw Mistake{key_start, "\"" + key + "\" is given twice in this object (also on line " +
                                             std::to_string(line_of(before->second)) + "): keep one"};
            seen[key] = key_start;
            std::string child = pointer_child(ptr, key);
            key_at[child] = key_start;
            skip();
            if (peek() != ':') {
                if (i >= t.size()) eof("after a key");
                throw Mistake{i, "expected ':' after \"" + key + "\", found " + found()};
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
            throw Mistake{i, "expected ',' or '}' after the value of \"" + key + "\", found " + found() +
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

/* ---- Geometry -------------------------------------------------------- */

using P = world_point;

double cross(P o, P a, P b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

bool on_segment(P p, P a, P b) {
    return std::min(a.x, b.x) - EPS <= p.x && p.x <= std::max(a.x, b.x) + EPS &&
           std::min(a.y, b.y) - EPS <= p.y && p.y <= std::max(a.y, b.y) + EPS;
}

/* Whether segments ab and cd share a point (touching counts). */
bool segments_meet(P a, P b, P c, P d) {
    double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
    if (((d1 > EPS && d2 < -EPS) || (d1 < -EPS && d2 > EPS)) && ((d3 > EPS && d4 < -EPS) || (d3 < -EPS && d4 > EPS)))
        return true;
    return (std::fabs(d1) <= EPS && on_segment(a, c, d)) || (std::fabs(d2) <= EPS && on_segment(b, c, d)) ||
           (std::fabs(d3) <= EPS && on_segment(c, a, b)) || (std::fabs(d4) <= EPS && on_segment(d, a, b));
}

double segment_distance(P p, P a, P b) {
    double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
    double s = len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(p.x - (a.x + s * dx), p.y - (a.y + s * dy));
}

bool inside(P p, const world_obstacle &o) {
    bool in = false;
    for (int k = 0, j = o.n - 1; k < o.n; j = k++) {
        const P &a = o.v[k], &b = o.v[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
    }
    return in;
}

/* How far p lies from the obstacle's outline; 0 inside it. */
double obstacle_distance(P p, const world_obstacle &o) {
    if (inside(p, o)) return 0;
    double d = INFINITY;
    for (int k = 0; k < o.n; k++) d = std::min(d, segment_distance(p, o.v[k], o.v[(k + 1) % o.n]));
    return d;
}

/* ---- Random draws: the same on every machine ------------------------- */

/* The placement's own stream (world_random.h). */
struct Draws {
    uint64_t state;
    uint32_t seed; /* the world's, for messages */
    double next() { return world_random_uniform(&state); }
};

/* Whether a suggested key shares most of its letters with the mistyped
 * one: the nearest by edit distance may be no kin at all ("colour" and
 * "robots"), and then the list of keys helps more. */
bool alike(const std::string &typed, const std::string &hint) {
    if (hint.empty()) return false;
    std::string a = typed, b = hint, common;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
    return (double)common.size() >= 0.6 * (double)std::max(a.size(), b.size());
}

/* ---- The document, walked with names and positions ------------------- */

/* A value in the document: its key path for messages ("robots[1].region")
 * and its JSON pointer for the scanner's positions. */
struct Node {
    const json *v;
    std::string name, ptr;
    const json &operator*() const { return *v; }
    const json *operator->() const { return v; }
};

std::string found(const json &v) {
    std::string text = v.dump();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    const char *kind = v.is_number() ? "" : v.is_string() ? "text " : v.is_boolean() ? "" : v.is_null() ? "" :
                       v.is_array() ? "a list " : "an object ";
    return kind + text;
}

template <typename T>
T *c_array(const std::vector<T> &v) {
    if (v.empty()) return nullptr;
    T *out = static_cast<T *>(calloc(v.size(), sizeof(T)));
    if (out == nullptr) throw std::bad_alloc();
    std::copy(v.begin(), v.end(), out);
    return out;
}

/* Where a robot came from, to name it in messages. */
struct Origin {
    int group, k;        /* robots[group], its k-th robot */
    std::string how;     /* ".poses[3]", ".grid column 1 row 0", ", placed at random" */
};

class Reader {
  public:
    Reader(const std::string &path, const Scanner &s) : path_(path), s_(s) {}

    [[noreturn]] void fail(const Node &n, const std::string &message) const {
        auto at = s_.value_at.find(n.ptr);
        throw Mistake{at == s_.value_at.end() ? 0 : at->second, (n.name.empty() ? "" : n.name + ": ") + message};
    }
    /* At n's key; the message names the object holding it (parent). */
    [[noreturn]] void fail_key(const Node &n, const std::string &parent, const std::string &message) const {
        auto at = s_.key_at.find(n.ptr);
        throw Mistake{at == s_.key_at.end() ? 0 : at->second, (parent.empty() ? "" : parent + ": ") + message};
    }

    Node child(const Node &n, const std::string &key) const {
        return {&n->at(key), n.name.empty() ? key : n.name + "." + key, pointer_child(n.ptr, key)};
    }
    Node item(const Node &n, size_t k) const {
        return {&n->at(k), n.name + "[" + std::to_string(k) + "]", n.ptr + "/" + std::to_string(k)};
    }

    /* An object with only these keys. */
    void object(const Node &n, const std::vector<std::string> &allowed, const std::string &example) const {
        if (!n->is_object()) fail(n, "expected an object, found " + found(*n) + "; e.g. " + example);
        /* The first unknown key in the file, not in nlohmann's (sorted) order. */
        std::optional<std::string> unknown;
        size_t unknown_at = 0;
        for (const auto &entry : n->items()) {
            if (std::find(allowed.begin(), allowed.end(), entry.key()) != allowed.end()) continue;
            auto at = s_.key_at.find(pointer_child(n.ptr, entry.key()));
            size_t byte = at == s_.key_at.end() ? 0 : at->second;
            if (!unknown || byte < unknown_at) {
                unknown = entry.key();
                unknown_at = byte;
            }
        }
        if (unknown) {
            const std::string &key = *unknown;
            std::string hint = openswarm::nearest(key, allowed);
            if (!alike(key, hint)) hint.clear();
            fail_key(child(n, key), n.name, "unknown key \"" + key + "\"; " +
                                        (hint.empty() ? "the keys here are " + openswarm::join(allowed)
                                                      : "did you mean \"" + hint + "\"?"));
        }
    }

    std::optional<Node> get(const Node &n, const std::string &key) const {
        if (!n->contains(key)) return std::nullopt;
        return child(n, key);
    }
    Node need(const Node &n, const std::string &key, const std::string &example) const {
        if (!n->contains(key))
            fail(n, "\"" + key + "\" is missing; add it, e.g. " + example);
        return child(n, key);
    }

    /* A number in lo..hi (above lo when lo_open). */
    double number(const Node &n, double lo, double hi, bool lo_open, const std::string &what,
                  const std::string &example) const {
        bool ok = n->is_number() && !n->is_boolean();
        double v = ok ? n->get<double>() : 0;
        if (!ok || !(lo_open ? v > lo : v >= lo) || !(v <= hi)) {
            std::string range = lo_open ? "above " + num(lo) + ", at most " + num(hi) : num(lo) + ".." + num(hi);
            fail(n, "expected " + what + " " + range + ", found " + found(*n) + "; e.g. " + example);
        }
        return v;
    }
    long whole(const Node &n, long lo, long hi, const std::string &what, const std::string &example) const {
        bool ok = n->is_number_integer() && n->get<double>() >= (double)lo && n->get<double>() <= (double)hi;
        if (!ok)
            fail(n, "expected " + what + ", a whole number " + std::to_string(lo) + ".." + std::to_string(hi) +
                        ", found " + found(*n) + "; e.g. " + example);
        return n->get<long>();
    }

    world_spec load(const json &doc);

    /* The C arrays world_spec_free frees. */
    void export_to(world_spec &w) const {
        w.path = strdup(path_.c_str());
        w.obstacles = c_array(obstacles_);
        w.n_obstacles = (int)obstacles_.size();
        w.objects = c_array(objects_);
        w.n_objects = (int)objects_.size();
        w.lights = c_array(lights_);
        w.n_lights = (int)lights_.size();
        w.robots = c_array(robots_);
        w.n_robots = (int)robots_.size();
        if (!firmware_.empty()) {
            w.firmware = static_cast<char **>(calloc(firmware_.size(), sizeof(char *)));
            if (w.firmware == nullptr) throw std::bad_alloc();
            for (const std::string &f : firmware_) {
                w.firmware[w.n_firmware] = strdup(f.c_str());
                if (w.firmware[w.n_firmware++] == nullptr) throw std::bad_alloc();
            }
        }
        if (w.path == nullptr) throw std::bad_alloc();
    }

  private:
    std::string path_;
    const Scanner &s_;

    /* The world under construction. */
    int kind_ = WORLD_ROBOT_KILOBOT;
    double ROBOT_R = KILOBOT_RADIUS_MM;
    double BODY = 2 * KILOBOT_RADIUS_MM; /* two centres closer overlap */
    std::string robot_ = "a Kilobot", robots_plural_ = "Kilobots"; /* for messages */
    double w_ = 0, h_ = 0;
    std::vector<world_obstacle> obstacles_;
    std::vector<world_object> objects_;
    std::vector<world_light> lights_;
    std::vector<world_robot> robots_;
    std::vector<Origin> origins_;
    std::vector<std::string> firmware_;
    std::unordered_map<int64_t, std::vector<int>> cells_; /* robots by 33 mm square, for overlap */
    std::map<int, int> uids_;                             /* uid -> robot */

    void robot_kind(const Node &n);
    int fidelity(const Node &n);
    void arena(const Node &n);
    void obstacle(const Node &n);
    void object_(const Node &n);
    void light(const Node &n, world_spec &w);
    void group(const Node &n, int g, Draws &draws, long &next_uid);

    std::string robot_name(int r) const {
        const Origin &o = origins_[(size_t)r];
        const world_robot &b = robots_[(size_t)r];
        return "robot " + std::to_string(r) + " (robots[" + std::to_string(o.group) + "]" + o.how + ", at " +
               at_text(b.at.x, b.at.y) + ")";
    }

    struct Conflict {
        std::string what, fix;
    };
    std::optional<Conflict> robot_conflict(P c) const;
    std::optional<Conflict> round_conflict(P c, double r) const; /* an object's */
    std::optional<Conflict> obstacle_conflict(P c, double r, const std::string &radius) const;
    std::optional<Conflict> object_conflict(P c, double r, const std::string &needed) const;
    void add_robot(const world_robot &r, const Origin &o);
    static int64_t cell_key(int64_t cx, int64_t cy) { return cx * 4000037 + cy; }
};

/* "robot": "kilobot" (default) or "epuck": every robot of the world is one
 * (their size places them; the e-pucks' "firmware" is a controller built
 * for the world, ports/epuck/host). */
void Reader::robot_kind(const Node &n) {
    const std::string ex = "\"robot\": \"epuck\"";
    if (!n->is_string()) fail(n, "expected \"kilobot\" or \"epuck\", found " + found(*n) + "; e.g. " + ex);
    std::string k = n->get<std::string>();
    if (k == "epuck") {
        kind_ = WORLD_ROBOT_EPUCK;
        ROBOT_R = EPUCK_RADIUS_MM;
        BODY = 2 * EPUCK_RADIUS_MM;
        robot_ = "an e-puck";
        robots_plural_ = "e-pucks";
    } else if (k != "kilobot") {
        fail(n, "unknown robot \"" + k + "\"; known: kilobot, epuck" +
                    openswarm::did_you_mean(k, {"kilobot", "epuck"}, '"'));
    }
}

/* "exact": the firmware's ELF in simavr; "native": the app built for the
 * host (openswarm build --native), by the thousand. */
int Reader::fidelity(const Node &n) {
    const std::string ex = "\"fidelity\": \"native\"";
    if (!n->is_string()) fail(n, "expected \"exact\" or \"native\", found " + found(*n) + "; e.g. " + ex);
    std::string f = n->get<std::string>();
    if (f == "native") return WORLD_FIDELITY_NATIVE;
    if (f != "exact")
        fail(n, "unknown fidelity \"" + f + "\"; known: exact (the firmware in simavr), native (the app "
                "built for the host)" + openswarm::did_you_mean(f, {"exact", "native"}, '"'));
    return WORLD_FIDELITY_EXACT;
}

void Reader::arena(const Node &n) {
    const std::string example = "\"arena\": {\"width_mm\": 600, \"height_mm\": 400}";
    object(n, {"width_mm", "height_mm"}, example);
    w_ = number(need(n, "width_mm", example), BODY, FAR_MM, false, "the arena's width in mm", "\"width_mm\": 600");
    h_ = number(need(n, "height_mm", example), BODY, FAR_MM, false, "the arena's height in mm", "\"height_mm\": 400");
}

void Reader::obstacle(const Node &n) {
    const std::string example = "{\"rect\": {\"x_mm\": 100, \"y_mm\": 100, \"width_mm\": 50, \"height_mm\": 20}} "
                                "or {\"polygon\": [[300, 50], [350, 50], [325, 90]]}";
    object(n, {"rect", "polygon"}, example);
    if (n->contains("rect") == n->contains("polygon"))
        fail(n, std::string(n->contains("rect") ? "\"rect\" and \"polygon\" both given: an obstacle is one shape; "
                                                  "split it into two obstacles"
                                                : "expected a \"rect\" or a \"polygon\"; e.g. ") +
                    (n->contains("rect") ? "" : example));
    world_obstacle o{};
    std::vector<Node> where; /* each vertex's node, for messages */
    Node shape = n;
    if (n->contains("rect")) {
        shape = child(n, "rect");
        const std::string ex = "\"rect\": {\"x_mm\": 100, \"y_mm\": 100, \"width_mm\": 50, \"height_mm\": 20}";
        object(shape, {"x_mm", "y_mm", "width_mm", "height_mm"}, ex);
        double x = number(need(shape, "x_mm", ex), -FAR_MM, FAR_MM, false, "the left edge's x in mm", "\"x_mm\": 100");
        double y = number(need(shape, "y_mm", ex), -FAR_MM, FAR_MM, false, "the bottom edge's y in mm", "\"y_mm\": 100");
        double rw = number(need(shape, "width_mm", ex), 0, FAR_MM, true, "a width in mm", "\"width_mm\": 50");
        double rh = number(need(shape, "height_mm", ex), 0, FAR_MM, true, "a height in mm", "\"height_mm\": 20");
        o.n = 4;
        o.v[0] = {x, y};
        o.v[1] = {x + rw, y};
        o.v[2] = {x + rw, y + rh};
        o.v[3] = {x, y + rh};
        where.assign(4, shape);
    } else {
        shape = child(n, "polygon");
        const std::string ex = "\"polygon\": [[300, 50], [350, 50], [325, 90]]";
        if (!shape->is_array() || shape->size() < 3 || shape->size() > WORLD_MAX_VERTICES)
            fail(shape, "expected a list of 3.." + std::to_string(WORLD_MAX_VERTICES) + " vertices [x_mm, y_mm], found " +
                            (shape->is_array() ? std::to_string(shape->size()) + " vertices" : found(*shape)) + "; e.g. " + ex +
                            (shape->is_array() && shape->size() > WORLD_MAX_VERTICES ? " (split a larger shape into several obstacles)" : ""));
        o.n = (int)shape->size();
        for (int k = 0; k < o.n; k++) {
            Node v = item(shape, (size_t)k);
            if (!v->is_array() || v->size() != 2 || !(*v)[0].is_number() || !(*v)[1].is_number())
                fail(v, "expected a vertex [x_mm, y_mm], two numbers, found " + found(*v) + "; e.g. [300, 50]");
            o.v[k] = {number(item(v, 0), -FAR_MM, FAR_MM, false, "x in mm", "[300, 50]"),
                      number(item(v, 1), -FAR_MM, FAR_MM, false, "y in mm", "[300, 50]")};
            where.push_back(v);
        }
    }
    for (int k = 0; k < o.n; k++) {
        const P &p = o.v[k];
        if (p.x < -EPS || p.x > w_ + EPS || p.y < -EPS || p.y > h_ + EPS)
            fail(where[(size_t)k], (o.n == 4 && n->contains("rect") ? "its corner " : "vertex ") + at_text(p.x, p.y) +
                                       " lies outside the arena (x 0.." + num(w_) + ", y 0.." + num(h_) +
                                       "): move the obstacle inside, or enlarge the arena");
    }
    for (int k = 0; k < o.n; k++) {
        P a = o.v[k], b = o.v[(k + 1) % o.n], c = o.v[(k + 2) % o.n];
        if (std::hypot(b.x - a.x, b.y - a.y) <= EPS)
            fail(where[(size_t)(k + 1) % o.n], "vertex " + std::to_string((k + 1) % o.n) + " repeats vertex " +
                                                   std::to_string(k) + ": remove one of them");
        double turn = cross(a, b, c), dot = (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y);
        if (std::fabs(turn) <= EPS && dot < 0)
            fail(shape, "the outline doubles back on itself at vertex " + std::to_string((k + 1) % o.n) +
                            " (a zero-width spike, or all vertices on one line): list the vertices in order "
                            "around a shape with area");
    }
    for (int k = 0; k < o.n; k++)
        for (int j = k + 2; j < o.n; j++) {
            if (k == 0 && j == o.n - 1) continue; /* neighbours through vertex 0 */
            if (segments_meet(o.v[k], o.v[k + 1], o.v[j], o.v[(j + 1) % o.n]))
                fail(shape, "the edges from vertex " + std::to_string(k) + " to " + std::to_string(k + 1) +
                                " and from vertex " + std::to_string(j) + " to " + std::to_string((j + 1) % o.n) +
                                " cross: list the vertices in order around the shape (or split it into "
                                "several obstacles)");
        }
    obstacles_.push_back(o);
}

/* The first obstacle a disc at c, radius r, reaches into; `radius` says
 * what r is ("its radius 20 mm"). */
std::optional<Reader::Conflict> Reader::obstacle_conflict(P c, double r, const std::string &radius) const {
    for (size_t k = 0; k < obstacles_.size(); k++) {
        double d = obstacle_distance(c, obstacles_[k]);
        if (d < r - EPS)
            return Conflict{d == 0 ? "has its centre inside obstacles[" + std::to_string(k) + "]"
                                   : "overlaps obstacles[" + std::to_string(k) + "]: its centre is " + mm(d) +
                                         " mm from it, " + radius,
                            "move it at least " + num(r) + " mm clear of the obstacle"};
    }
    return std::nullopt;
}

/* The first object a disc at c, radius r, overlaps; `needed` says why the
 * centres must be that far apart ("(the radii added)"). */
std::optional<Reader::Conflict> Reader::object_conflict(P c, double r, const std::string &needed) const {
    for (size_t k = 0; k < objects_.size(); k++) {
        const world_object &b = objects_[k];
        double d = std::hypot(c.x - b.at.x, c.y - b.at.y);
        if (d < r + b.radius_mm - EPS)
            return Conflict{"overlaps objects[" + std::to_string(k) + "] at " + at_text(b.at.x, b.at.y) + ": centres " +
                                mm(d) + " mm apart, at least " + num(r + b.radius_mm) + " needed " + needed,
                            "move them apart"};
    }
    return std::nullopt;
}

/* Whether a round thing (an object) at c, radius r, fits: in the arena,
 * clear of obstacles and of the objects before it. */
std::optional<Reader::Conflict> Reader::round_conflict(P c, double r) const {
    if (c.x - r < -EPS || c.x + r > w_ + EPS || c.y - r < -EPS || c.y + r > h_ + EPS)
        return Conflict{"reaches past the arena's walls (x 0.." + num(w_) + ", y 0.." + num(h_) + ")",
                        "keep its centre within x " + num(r) + ".." + num(w_ - r) + " and y " + num(r) + ".." +
                            num(h_ - r)};
    if (auto hit = obstacle_conflict(c, r, "its radius " + num(r) + " mm")) return hit;
    return object_conflict(c, r, "(the radii added)");
}

void Reader::object_(const Node &n) {
    const std::string example = "{\"x_mm\": 200, \"y_mm\": 200, \"radius_mm\": 20, \"mass_g\": 10, \"friction\": 0.5}";
    object(n, {"x_mm", "y_mm", "radius_mm", "mass_g", "friction"}, example);
    world_object o{};
    o.at.x = number(need(n, "x_mm", example), -FAR_MM, FAR_MM, false, "x in mm", "\"x_mm\": 200");
    o.at.y = number(need(n, "y_mm", example), -FAR_MM, FAR_MM, false, "y in mm", "\"y_mm\": 200");
    o.radius_mm = number(need(n, "radius_mm", example), 1, 1000, false, "a radius in mm", "\"radius_mm\": 20");
    o.mass_g = n->contains("mass_g")
                   ? number(child(n, "mass_g"), 0, 100000, true, "a mass in grams", "\"mass_g\": 10")
                   : 10;
    o.friction = n->contains("friction")
                     ? number(child(n, "friction"), 0, 2, false, "a friction coefficient", "\"friction\": 0.5")
                     : 0.5;
    if (auto c = round_conflict(o.at, o.radius_mm)) fail(n, "this object " + c->what + ": " + c->fix);
    objects_.push_back(o);
}

void Reader::light(const Node &n, world_spec &w) {
    const std::string example = "\"light\": {\"ambient_mv\": 300, \"sources\": [{\"x_mm\": 500, \"y_mm\": 200, "
                                "\"intensity_mv\": 2000}]}";
    object(n, {"ambient_mv", "sources"}, example);
    if (auto a = get(n, "ambient_mv"))
        w.ambient_light_mv = number(*a, 0, 5000, false, "the light sensor's input with no source near, in mV",
                                    "\"ambient_mv\": 300");
    auto sources = get(n, "sources");
    if (!sources) return;
    const std::string ex = "{\"x_mm\": 500, \"y_mm\": 200, \"intensity_mv\": 2000}";
    if (!sources.value()->is_array())
        fail(*sources, "expected a list of light sources, found " + found(**sources) + "; e.g. [" + ex + "]");
    for (size_t k = 0; k < sources.value()->size(); k++) {
        Node s = item(*sources, k);
        object(s, {"x_mm", "y_mm", "intensity_mv"}, ex);
        world_light l{};
        /* A lamp may stand beyond the arena's walls, as beside a table. */
        l.at.x = number(need(s, "x_mm", ex), -FAR_MM, FAR_MM, false, "x in mm", "\"x_mm\": 500");
        l.at.y = number(need(s, "y_mm", ex), -FAR_MM, FAR_MM, false, "y in mm", "\"y_mm\": 200");
        l.intensity_mv = number(need(s, "intensity_mv", ex), 0, 100000, false,
                                "what it adds to a light sensor 100 mm away, in mV", "\"intensity_mv\": 2000");
        lights_.push_back(l);
    }
}

/* Whether a robot centred at c fits: in the arena, clear of obstacles,
 * objects and every robot placed so far. */
std::optional<Reader::Conflict> Reader::robot_conflict(P c) const {
    const char *walls[4] = {"left", "right", "bottom", "top"};
    double gaps[4] = {c.x, w_ - c.x, c.y, h_ - c.y};
    for (int k = 0; k < 4; k++)
        if (gaps[k] < ROBOT_R - EPS)
            return Conflict{std::string("reaches past the arena's ") + walls[k] + " wall: its centre is " +
                                (gaps[k] < 0 ? "outside, " + mm(-gaps[k]) + " mm beyond it" : mm(gaps[k]) + " mm from it") +
                                ", " + robot_ + "'s radius is " + num(ROBOT_R) + " mm",
                            "keep robots' centres within x " + num(ROBOT_R) + ".." + num(w_ - ROBOT_R) + " and y " +
                                num(ROBOT_R) + ".." + num(h_ - ROBOT_R)};
    if (auto hit = obstacle_conflict(c, ROBOT_R, robot_ + "'s radius is " + num(ROBOT_R) + " mm"))
        return hit;
    if (auto hit = object_conflict(c, ROBOT_R, "(the object's radius + " + robot_ + "'s " + num(ROBOT_R) + ")"))
        return hit;
    auto cx = (int64_t)std::floor(c.x / BODY), cy = (int64_t)std::floor(c.y / BODY);
    int nearest = -1;
    double nearest_d = BODY;
    for (int64_t i = cx - 1; i <= cx + 1; i++)
        for (int64_t j = cy - 1; j <= cy + 1; j++) {
            auto cell = cells_.find(cell_key(i, j));
            if (cell == cells_.end()) continue;
            for (int r : cell->second) {
                const P &o = robots_[(size_t)r].at;
                double d = std::hypot(c.x - o.x, c.y - o.y);
                if (d < BODY - EPS && (nearest < 0 || r < nearest)) {
                    nearest = r;
                    nearest_d = d;
                }
            }
        }
    if (nearest >= 0)
        return Conflict{"overlaps " + robot_name(nearest) + ": centres " + mm(nearest_d) + " mm apart, " + robots_plural_ + " are " +
                            num(BODY) + " mm across",
                        "move them at least " + num(BODY) + " mm apart"};
    return std::nullopt;
}

void Reader::add_robot(const world_robot &r, const Origin &o) {
    int index = (int)robots_.size();
    robots_.push_back(r);
    origins_.push_back(o);
    cells_[cell_key((int64_t)std::floor(r.at.x / BODY), (int64_t)std::floor(r.at.y / BODY))].push_back(index);
}

void Reader::group(const Node &n, int g, Draws &draws, long &next_uid) {
    const std::string example = "{\"count\": 10, \"region\": {\"x_mm\": 250, \"y_mm\": 150, \"width_mm\": 100, "
                                "\"height_mm\": 100}}";
    object(n, {"poses", "count", "region", "grid", "uid", "firmware", "calibration"}, example);

    /* What every robot of the group shares. */
    world_robot base{};
    base.firmware = -1;
    for (int &c : base.calibration) c = -2;
    if (auto f = get(n, "firmware")) {
        if (!f.value()->is_string() || f.value()->get<std::string>().empty())
            fail(*f, "expected the path of an ELF (relative to this file's folder), found " + found(**f) +
                         "; e.g. \"firmware\": \"build/app.elf\"");
        std::string given = f.value()->get<std::string>();
        fs::path file(given);
        if (file.is_relative()) file = fs::path(path_).parent_path() / file;
        file = file.lexically_normal();
        std::error_code ec;
        if (!fs::is_regular_file(file, ec))
            fail(*f, "\"" + given + "\": " + (fs::exists(file, ec) ? "not a file" : "no such file") + " (looked for " +
                         fs::absolute(file, ec).string() + "); a firmware path is relative to the world file's folder: build the "
                         "firmware, or correct the path");
        auto known = std::find(firmware_.begin(), firmware_.end(), file.string());
        base.firmware = (int)(known - firmware_.begin());
        if (known == firmware_.end()) firmware_.push_back(file.string());
    }
    if (auto c = get(n, "calibration")) {
        const std::string ex = "\"calibration\": [70, 70, 65, 68] (turn left, turn right, straight left, "
                               "straight right) or \"calibration\": \"erased\"";
        if (c.value()->is_string()) {
            std::string s = c.value()->get<std::string>();
            if (s != "erased")
                fail(*c, "unknown calibration \"" + s + "\"; expected \"erased\" or four duties: " + ex);
            for (int &d : base.calibration) d = -1;
        } else {
            if (!c.value()->is_array() || c.value()->size() != 4)
                fail(*c, "expected four motor duties 0..255 or \"erased\", found " + found(**c) + "; e.g. " + ex);
            for (size_t k = 0; k < 4; k++)
                base.calibration[k] = (int)whole(item(*c, k), 0, 255, "a motor duty", ex);
        }
    }
    std::optional<Node> uid_node = get(n, "uid");
    if (uid_node) next_uid = whole(*uid_node, 0, 65535, "the group's first uid", "\"uid\": 100");

    /* One way of placing. */
    const char *ways[] = {"poses", "grid", "region"};
    const char *first = nullptr;
    for (const char *way : ways) {
        if (!n->contains(way)) continue;
        if (first != nullptr)
            fail_key(child(n, way), n.name, "\"" + std::string(first) + "\" and \"" + way +
                                        "\" each place the group's robots: give one of them, and put "
                                        "the other robots in a group of their own");
        first = way;
    }
    std::optional<Node> count_node = get(n, "count");
    if (count_node && first != nullptr && std::string(first) != "region")
        fail_key(*count_node, n.name, std::string("\"count\" goes with \"region\" or alone; \"") + first +
                                  "\" already says how many robots: remove \"count\"");
    if (!count_node && first == nullptr)
        fail(n, "where do its robots stand? give \"poses\" (a list), a \"grid\", \"count\" with a \"region\" "
                "(at random in it), or \"count\" alone (at random in the arena); e.g. " + example);
    if (!count_node && std::string(first) == "region")
        fail(n, "\"region\" needs a \"count\": how many robots to place at random in it; e.g. \"count\": 10");

    size_t start = robots_.size();
    auto place = [&](P at, double heading, const std::string &how) {
        world_robot r = base;
        r.at = at;
        r.heading_deg = heading;
        add_robot(r, Origin{g, (int)(robots_.size() - start), how});
    };

    if (first != nullptr && std::string(first) == "poses") {
        Node poses = child(n, "poses");
        const std::string ex = "{\"x_mm\": 50, \"y_mm\": 50, \"heading_deg\": 90}";
        if (!poses->is_array() || poses->empty() || poses->size() > (size_t)MAX_COUNT)
            fail(poses, "expected a list of 1.." + std::to_string(MAX_COUNT) + " poses, found " + found(*poses) +
                            "; e.g. \"poses\": [" + ex + "]");
        for (size_t k = 0; k < poses->size(); k++) {
            Node p = item(poses, k);
            object(p, {"x_mm", "y_mm", "heading_deg"}, ex);
            P at{number(need(p, "x_mm", ex), -FAR_MM, FAR_MM, false, "x in mm", "\"x_mm\": 50"),
                 number(need(p, "y_mm", ex), -FAR_MM, FAR_MM, false, "y in mm", "\"y_mm\": 50")};
            double heading = p->contains("heading_deg")
                                 ? number(child(p, "heading_deg"), -360, 360, false,
                                          "degrees counter-clockwise from the x axis", "\"heading_deg\": 90")
                                 : 0;
            if (auto c = robot_conflict(at)) fail(p, "this robot " + c->what + ": " + c->fix);
            place(at, std::fmod(heading + 360, 360), ".poses[" + std::to_string(k) + "]");
        }
    } else if (first != nullptr && std::string(first) == "grid") {
        Node grid = child(n, "grid");
        const std::string ex = "\"grid\": {\"x_mm\": 400, \"y_mm\": 100, \"columns\": 3, \"rows\": 2, \"spacing_mm\": 50}";
        object(grid, {"x_mm", "y_mm", "columns", "rows", "spacing_mm"}, ex);
        double x = number(need(grid, "x_mm", ex), -FAR_MM, FAR_MM, false, "the first robot's x in mm", "\"x_mm\": 400");
        double y = number(need(grid, "y_mm", ex), -FAR_MM, FAR_MM, false, "the first robot's y in mm", "\"y_mm\": 100");
        long columns = whole(need(grid, "columns", ex), 1, MAX_COUNT, "robots along x", "\"columns\": 3");
        long rows = whole(need(grid, "rows", ex), 1, MAX_COUNT, "robots along y", "\"rows\": 2");
        Node spacing_node = need(grid, "spacing_mm", ex);
        double spacing = number(spacing_node, BODY, FAR_MM, false,
                                "mm between neighbouring centres (" + robot_ + " is " + num(BODY) + " mm across)",
                                "\"spacing_mm\": 50");
        if (columns * rows > MAX_COUNT)
            fail(grid, std::to_string(columns) + " x " + std::to_string(rows) + " robots: more than " +
                           std::to_string(MAX_COUNT) + ", likely a typo; lower columns or rows");
        for (long row = 0; row < rows; row++)
            for (long col = 0; col < columns; col++) {
                P at{x + (double)col * spacing, y + (double)row * spacing};
                if (auto c = robot_conflict(at))
                    fail(grid, "its robot at column " + std::to_string(col) + ", row " + std::to_string(row) + " " +
                                   at_text(at.x, at.y) + " " + c->what + ": " + c->fix +
                                   " (or move the grid, or change its columns, rows or spacing)");
                place(at, 0, ".grid column " + std::to_string(col) + " row " + std::to_string(row));
            }
    } else {
        long count = whole(*count_node, 1, MAX_COUNT, "how many robots",
                           "\"count\": 10 (more than " + std::to_string(MAX_COUNT) + " is taken for a typo)");
        /* Centres are drawn from the region (the arena by default), kept a
         * radius from the walls. */
        double x0 = ROBOT_R, y0 = ROBOT_R, x1 = w_ - ROBOT_R, y1 = h_ - ROBOT_R;
        Node blame = *count_node;
        std::string room = "the arena";
        if (auto r = get(n, "region")) {
            blame = *r;
            room = "the region";
            const std::string ex = "\"region\": {\"x_mm\": 250, \"y_mm\": 150, \"width_mm\": 100, \"height_mm\": 100}";
            object(*r, {"x_mm", "y_mm", "width_mm", "height_mm"}, ex);
            double rx = number(need(*r, "x_mm", ex), 0, w_, false, "the left edge's x in mm, in the arena", "\"x_mm\": 250");
            double ry = number(need(*r, "y_mm", ex), 0, h_, false, "the bottom edge's y in mm, in the arena", "\"y_mm\": 150");
            double rw = number(need(*r, "width_mm", ex), 0, FAR_MM, true, "a width in mm", "\"width_mm\": 100");
            double rh = number(need(*r, "height_mm", ex), 0, FAR_MM, true, "a height in mm", "\"height_mm\": 100");
            if (rx + rw > w_ + EPS || ry + rh > h_ + EPS)
                fail(*r, "reaches past the arena's " + std::string(rx + rw > w_ + EPS ? "right" : "top") +
                             " wall (x 0.." + num(w_) + ", y 0.." + num(h_) + "): x_mm + width_mm is " + num(rx + rw) +
                             ", y_mm + height_mm " + num(ry + rh) + "; move or shrink the region");
            x0 = std::max(x0, rx);
            y0 = std::max(y0, ry);
            x1 = std::min(x1, rx + rw);
            y1 = std::min(y1, ry + rh);
        }
        for (long k = 0; k < count; k++) {
            int tries = 0;
            for (;; tries++) {
                if (tries == TRIES_PER_ROBOT || x1 < x0 || y1 < y0)
                    fail(blame, "found room for " + std::to_string(k) + " of " + std::to_string(count) +
                                    " robots at random without overlap (" + std::to_string(TRIES_PER_ROBOT) +
                                    " draws for the next found none): " + room + " holds at most about " +
                                    std::to_string(k) + " robots (seed " + std::to_string(draws.seed) +
                                    "); enlarge " + room + " or lower count to " + std::to_string(k));
                /* Three draws per try, whatever happens, so the first k
                 * robots stand where they stood with a larger count. */
                P at{x0 + draws.next() * (x1 - x0), y0 + draws.next() * (y1 - y0)};
                double heading = draws.next() * 360;
                if (robot_conflict(at)) continue;
                place(at, heading, ", placed at random");
                break;
            }
        }
    }

    /* Uids: the group's first is "uid" or the one after the last robot's. */
    size_t n_robots = robots_.size() - start;
    if (next_uid + (long)n_robots - 1 > 65535)
        fail(uid_node ? *uid_node : n, "its " + std::to_string(n_robots) + " robots would get uids " +
                                           std::to_string(next_uid) + ".." + std::to_string(next_uid + (long)n_robots - 1) +
                                           ", past 65535: give the group a \"uid\" of at most " +
                                           std::to_string(65536 - (long)n_robots));
    for (size_t k = start; k < robots_.size(); k++) {
        int uid = (int)next_uid++;
        auto taken = uids_.find(uid);
        if (taken != uids_.end()) {
            long highest = uids_.rbegin()->first;
            fail(uid_node ? *uid_node : n,
                 "robot " + std::to_string(k) + " (this group's robot " + std::to_string(k - start) + ") would get uid " +
                     std::to_string(uid) + ", which " + robot_name(taken->second) + " has; uids are unique: give " +
                     "this group a \"uid\" clear of the others, e.g. \"uid\": " + std::to_string(highest + 1));
        }
        uids_[uid] = (int)k;
        robots_[k].uid = uid;
    }
}

world_spec Reader::load(const json &doc) {
    Node root{&doc, "", ""};
    const std::string example = "{\"arena\": {\"width_mm\": 600, \"height_mm\": 400}, \"robots\": [{\"count\": 10}]}";
    object(root, {"description", "robot", "arena", "seed", "duration_s", "sample_period_s", "fidelity", "ir",
                  "clock_spread_pct", "light", "obstacles", "objects", "robots"},
           example);
    world_spec w{};
    w.ir_range_mm = -1;
    w.ir_loss_pct = -1;
    w.clock_spread_pct = -1;
    w.duration_s = -1;
    w.sample_period_s = 0.1;
    w.seed = 1;
    if (auto d = get(root, "description"))
        if (!d.value()->is_string()) fail(*d, "expected a text, found " + found(**d) + "; e.g. \"description\": \"ten robots packed\"");
    if (auto k = get(root, "robot")) robot_kind(*k);
    if (auto f = get(root, "fidelity")) w.fidelity = fidelity(*f);
    if (!doc.contains("arena")) fail(root, "\"arena\" is missing; every world has one, e.g. " + example);
    arena(child(root, "arena"));
    if (auto s = get(root, "seed")) w.seed = (uint32_t)whole(*s, 0, 4294967295L, "the random seed", "\"seed\": 7");
    if (auto d = get(root, "duration_s"))
        w.duration_s = number(*d, 0, 1e6, true, "simulated seconds", "\"duration_s\": 120");
    if (auto p = get(root, "sample_period_s"))
        w.sample_period_s = number(*p, 0.001, 3600, false, "seconds between trajectory samples", "\"sample_period_s\": 0.1");
    if (auto ir = get(root, "ir")) {
        const std::string ex = "\"ir\": {\"range_mm\": 100, \"loss_pct\": 0}";
        object(*ir, {"range_mm", "loss_pct"}, ex);
        if (auto r = get(*ir, "range_mm"))
            w.ir_range_mm = (int)whole(*r, 10, 1000, "mm at which robots still hear each other", "\"range_mm\": 100");
        if (auto l = get(*ir, "loss_pct"))
            w.ir_loss_pct = number(*l, 0, 100, false, "percent of frames lost at the range's edge", "\"loss_pct\": 20");
    }
    if (auto c = get(root, "clock_spread_pct"))
        w.clock_spread_pct = number(*c, 0, 5, false, "percent the robots' clocks differ by", "\"clock_spread_pct\": 0.5");
    if (auto l = get(root, "light")) light(*l, w);
    auto list = [&](const char *key, const std::string &ex) -> std::optional<Node> {
        auto n = get(root, key);
        if (n && !n.value()->is_array()) fail(*n, "expected a list, found " + found(**n) + "; e.g. \"" + key + "\": [" + ex + "]");
        return n;
    };
    if (auto obs = list("obstacles", "{\"rect\": {\"x_mm\": 100, \"y_mm\": 100, \"width_mm\": 50, \"height_mm\": 20}}"))
        for (size_t k = 0; k < obs.value()->size(); k++) obstacle(item(*obs, k));
    if (auto objs = list("objects", "{\"x_mm\": 200, \"y_mm\": 200, \"radius_mm\": 20}"))
        for (size_t k = 0; k < objs.value()->size(); k++) object_(item(*objs, k));
    if (auto groups = list("robots", "{\"count\": 10}")) {
        /* Placement has a stream of its own, from the seed, so the physics'
         * draws do not move the robots. */
        Draws draws{(uint64_t)w.seed * 0x9E3779B97F4A7C15ull ^ 0x706C61636521ull, w.seed};
        long next_uid = 1;
        for (size_t g = 0; g < groups.value()->size(); g++) group(item(*groups, g), (int)g, draws, next_uid);
    }
    w.width_mm = w_;
    w.height_mm = h_;
    w.robot_kind = kind_;
    w.robot_radius_mm = ROBOT_R;
    return w;
}

/* "file:line:column: message", the line, a caret under the column. */
void report(const std::string &path, const std::string &text, size_t byte, const std::string &message) {
    byte = std::min(byte, text.size());
    size_t line = 1, start = 0;
    for (size_t k = 0; k < byte; k++)
        if (text[k] == '\n') {
            line++;
            start = k + 1;
        }
    size_t end = text.find('\n', start);
    std::string source = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (!source.empty() && source.back() == '\r') source.pop_back();
    std::string caret;
    size_t column = 1;
    for (size_t k = start; k < byte; k++) {
        if (((unsigned char)text[k] & 0xC0) == 0x80) continue; /* a UTF-8 character's tail */
        caret += text[k] == '\t' ? '\t' : ' ';
        column++;
    }
    fprintf(stderr, "%s:%zu:%zu: %s\n", path.c_str(), line, column, message.c_str());
    if (!source.empty()) fprintf(stderr, "    %s\n    %s^\n", source.c_str(), caret.c_str());
}

}  // namespace

extern "C" int world_spec_load(const char *path, world_spec *out) {
    std::string text;
    {
        std::ifstream in(path, std::ios::binary);
        if (!in) {
            fprintf(stderr, "openswarm-sim: --world %s: %s; give a world.json file (docs/world.md describes it)\n",
                    path, strerror(errno));
            return -1;
        }
        std::stringstream buffer;
        buffer << in.rdbuf();
        text = buffer.str();
    }
    world_spec w{};
    try {
        Scanner scanner(text);
        scanner.run();
        json doc;
        try {
            doc = json::parse(text);
        } catch (const json::exception &e) {
            /* What the scanner lets through and nlohmann does not: invalid UTF-8. */
            throw Mistake{0, std::string("not readable as JSON: ") + e.what() + "; save the file as UTF-8"};
        }
        Reader reader(path, scanner);
        w = reader.load(doc);
        reader.export_to(w);
    } catch (const Mistake &m) {
        report(path, text, m.byte, m.text);
        world_spec_free(&w);
        return -1;
    } catch (const std::bad_alloc &) {
        fprintf(stderr, "openswarm-sim: %s: out of memory while reading it; lower the robots' counts\n", path);
        world_spec_free(&w);
        return -1;
    }
    *out = w;
    return 0;
}

extern "C" void world_spec_free(world_spec *w) {
    if (w == nullptr) return;
    free(const_cast<char *>(w->path));
    free(w->obstacles);
    free(w->objects);
    free(w->lights);
    free(w->robots);
    for (int k = 0; k < w->n_firmware; k++) free(w->firmware[k]);
    free(w->firmware);
    memset(w, 0, sizeof *w);
}
