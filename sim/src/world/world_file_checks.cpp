/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The Reader's checks of single values, the same in every section of
 * world.json: an object with only its keys (a mistyped one gets "did you
 * mean"), a key that must be there, a number in its range. Each fails
 * with a Mistake at the value's place, naming its key path, what was
 * expected, what was found and an example. And the words messages are
 * made of: lengths, bounds, points, values as found. */
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "suggest.hpp"
#include "world/world_file_reader.hpp"

namespace world_file {

namespace {

std::string format(const char *fmt, double v) {
    char buf[64];
    snprintf(buf, sizeof buf, fmt, v);
    return buf;
}

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

}  // namespace

std::string mm(double v) { return format("%.1f", v); }
std::string num(double v) { return format("%g", v); }
std::string at_text(double x, double y) { return "(" + mm(x) + ", " + mm(y) + ")"; }

std::string mm_beside(double v, double bound) {
    double printed_bound = strtod(num(bound).c_str(), nullptr);
    for (int decimals = 1; decimals <= 12; decimals++) {
        char buf[64];
        snprintf(buf, sizeof buf, "%.*f", decimals, v);
        double printed = strtod(buf, nullptr);
        if (v < bound ? printed < printed_bound : printed > printed_bound) return buf;
    }
    return mm(v); /* bound itself prints rounded past v */
}

std::string clip(const std::string &text, size_t bytes) {
    if (text.size() <= bytes) return text;
    size_t cut = bytes - 3;
    while (cut > 0 && continues_character(text[cut])) cut--;
    return text.substr(0, cut) + "...";
}

std::string quote(const std::string &text) { return "\"" + clip(text) + "\""; }

std::string found(const json &v) {
    std::string text = clip(v.dump(), 40);
    const char *kind = v.is_number() ? "" : v.is_string() ? "text " : v.is_boolean() ? "" : v.is_null() ? "" :
                       v.is_array() ? "a list " : "an object ";
    return kind + text;
}

void Reader::fail(const Node &n, const std::string &message) const {
    auto at = at_.value_at.find(n.ptr);
    throw Mistake{at == at_.value_at.end() ? 0 : at->second, (n.name.empty() ? "" : n.name + ": ") + message};
}

void Reader::fail_key(const Node &n, const std::string &parent, const std::string &message) const {
    auto at = at_.key_at.find(n.ptr);
    throw Mistake{at == at_.key_at.end() ? 0 : at->second, (parent.empty() ? "" : parent + ": ") + message};
}

Node Reader::child(const Node &n, const std::string &key) const {
    return {&n->at(key), n.name.empty() ? key : n.name + "." + key, pointer_child(n.ptr, key)};
}

Node Reader::item(const Node &n, size_t k) const {
    return {&n->at(k), n.name + "[" + std::to_string(k) + "]", n.ptr + "/" + std::to_string(k)};
}

void Reader::object(const Node &n, const std::vector<std::string> &allowed, const std::string &example) const {
    if (!n->is_object()) fail(n, "expected an object, found " + found(*n) + "; e.g. " + example);
    /* The first unknown key in the file, not in nlohmann's (sorted) order. */
    std::optional<std::string> unknown;
    size_t unknown_at = 0;
    for (const auto &entry : n->items()) {
        if (std::find(allowed.begin(), allowed.end(), entry.key()) != allowed.end()) continue;
        auto at = at_.key_at.find(pointer_child(n.ptr, entry.key()));
        size_t byte = at == at_.key_at.end() ? 0 : at->second;
        if (!unknown || byte < unknown_at) {
            unknown = entry.key();
            unknown_at = byte;
        }
    }
    if (unknown) {
        const std::string &key = *unknown;
        std::string hint = openswarm::nearest(key, allowed);
        if (!alike(key, hint)) hint.clear();
        fail_key(child(n, key), n.name, "unknown key " + quote(key) + "; " +
                                    (hint.empty() ? "the keys here are " + openswarm::join(allowed)
                                                  : "did you mean \"" + hint + "\"?"));
    }
}

std::optional<Node> Reader::get(const Node &n, const std::string &key) const {
    if (!n->contains(key)) return std::nullopt;
    return child(n, key);
}

Node Reader::need(const Node &n, const std::string &key, const std::string &example) const {
    if (!n->contains(key))
        fail(n, "\"" + key + "\" is missing; add it, e.g. " + example);
    return child(n, key);
}

double Reader::number(const Node &n, double lo, double hi, bool lo_open, const std::string &what,
                      const std::string &example) const {
    bool ok = n->is_number() && !n->is_boolean();
    double v = ok ? n->get<double>() : 0;
    if (!ok || !(lo_open ? v > lo : v >= lo) || !(v <= hi)) {
        std::string range = lo_open ? "above " + num(lo) + ", at most " + num(hi) : num(lo) + ".." + num(hi);
        fail(n, "expected " + what + " " + range + ", found " + found(*n) + "; e.g. " + example);
    }
    return v;
}

long Reader::whole(const Node &n, long lo, long hi, const std::string &what, const std::string &example) const {
    bool ok = n->is_number_integer() && n->get<double>() >= (double)lo && n->get<double>() <= (double)hi;
    if (!ok)
        fail(n, "expected " + what + ", a whole number " + std::to_string(lo) + ".." + std::to_string(hi) +
                    ", found " + found(*n) + "; e.g. " + example);
    return n->get<long>();
}

}  // namespace world_file
