/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* world.json (docs/world.md): read, check and place, before anything runs.
 * Every mistake is reported once, as "file:line:column: key.path: what is
 * wrong; what to do", with the line and a caret under the place. nlohmann
 * keeps no positions, so the text is first scanned (world_json_text.cpp),
 * recording where each key and value starts by its JSON pointer; nlohmann
 * then builds the document from the same text, and the Reader walks it
 * (world_file_reader.hpp lists its pieces). This file holds the public
 * face (world_spec.h), the top level of the document and the report. */
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "suggest.hpp"
#include "world/world_file_reader.hpp"
#include "world/world_spec.h"

namespace world_file {

namespace {

template <typename T>
T *c_array(const std::vector<T> &v) {
    if (v.empty()) return nullptr;
    T *out = static_cast<T *>(calloc(v.size(), sizeof(T)));
    if (out == nullptr) throw std::bad_alloc();
    std::copy(v.begin(), v.end(), out);
    return out;
}

/* "file:line:column: message", the line, a caret under the column. Of a
 * long line, LINE_BYTES either side of the caret are shown, "..." marking
 * what is cut. */
void report(const std::string &path, const std::string &text, size_t byte, const std::string &message) {
    byte = std::min(byte, text.size());
    size_t line = 1, start = 0;
    for (size_t k = 0; k < byte; k++)
        if (text[k] == '\n') {
            line++;
            start = k + 1;
        }
    size_t end = std::min(text.find('\n', start), text.size());
    if (end > start && text[end - 1] == '\r') end--;
    size_t from = byte - start > LINE_BYTES ? byte - LINE_BYTES : start;
    while (from > start && continues_character(text[from])) from--;
    size_t to = end > byte && end - byte > LINE_BYTES ? byte + LINE_BYTES : end;
    while (to < end && continues_character(text[to])) to++;
    std::string source = (from > start ? "..." : "") + text.substr(from, to - from) + (to < end ? "..." : "");
    std::string caret = from > start ? "   " : "";
    size_t column = 1;
    for (size_t k = start; k < byte; k++) {
        if (continues_character(text[k])) continue;
        if (k >= from) caret += text[k] == '\t' ? '\t' : ' ';
        column++;
    }
    fprintf(stderr, "%s:%zu:%zu: %s\n", path.c_str(), line, column, message.c_str());
    if (!source.empty()) fprintf(stderr, "    %s\n    %s^\n", source.c_str(), caret.c_str());
}

}  // namespace

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
        fail(n, "unknown robot " + quote(k) + "; known: kilobot, epuck" +
                    openswarm::did_you_mean(k, {"kilobot", "epuck"}, '"'));
    }
}

/* "exact": the firmware's ELF in simavr (an e-puck's host program);
 * "native": the app built for the host (openswarm build --native), by the
 * thousand; "qemu": an e-puck's e-puck2 image under QEMU. */
int Reader::fidelity(const Node &n) {
    const std::string ex = "\"fidelity\": \"native\"";
    if (!n->is_string()) fail(n, "expected \"exact\", \"native\" or \"qemu\", found " + found(*n) + "; e.g. " + ex);
    std::string f = n->get<std::string>();
    if (f == "native") return WORLD_FIDELITY_NATIVE;
    if (f == "qemu" && kind_ != WORLD_ROBOT_EPUCK)
        fail(n, "\"qemu\" runs e-puck2 images, and this is a world of Kilobots: give \"robot\": \"epuck\" "
                "with images built by `openswarm build --qemu`, or \"exact\" or \"native\" for Kilobots");
    if (f == "qemu") return WORLD_FIDELITY_QEMU;
    if (f != "exact")
        fail(n, "unknown fidelity " + quote(f) + "; known: exact (the firmware in simavr, an e-puck's host "
                "program), native (the app built for the host), qemu (an e-puck's e-puck2 image under QEMU)" +
                    openswarm::did_you_mean(f, {"exact", "native", "qemu"}, '"'));
    return WORLD_FIDELITY_EXACT;
}

/* "ir": the channel's range and losses, and the distance estimates' error
 * (air/ir_distance_error.h). */
void Reader::ir(const Node &n, world_spec &w) {
    const std::string ex = "\"ir\": {\"range_mm\": 100, \"loss_pct\": 0, \"distance_bias_mm\": 2, \"distance_noise_mm\": 0.5}";
    object(n, {"range_mm", "loss_pct", "distance_bias_mm", "distance_noise_mm"}, ex);
    if (auto r = get(n, "range_mm"))
        w.ir_range_mm = (int)whole(*r, 10, 1000, "mm at which robots still hear each other", "\"range_mm\": 100");
    if (auto l = get(n, "loss_pct"))
        w.ir_loss_pct = number(*l, 0, 100, false, "percent of frames lost at the range's edge", "\"loss_pct\": 20");
    if (auto b = get(n, "distance_bias_mm"))
        w.ir_distance_bias_mm = number(*b, 0, 20, false,
                                       "mm within which each pair's distance estimates are off (0: exact)",
                                       "\"distance_bias_mm\": 2, real Kilobots' accuracy");
    if (auto s = get(n, "distance_noise_mm"))
        w.ir_distance_noise_mm = number(*s, 0, 20, false,
                                        "mm, the sd of each message's own distance error (0: none)",
                                        "\"distance_noise_mm\": 0.5, real Kilobots' precision");
}

world_spec Reader::load(const json &doc) {
    Node root{&doc, "", ""};
    const std::string example = "{\"arena\": {\"width_mm\": 600, \"height_mm\": 400}, \"robots\": [{\"count\": 10}]}";
    object(root, {"description", "robot", "arena", "seed", "duration_s", "sample_period_s", "fidelity", "ir",
                  "clock_spread_pct", "light", "noise", "camera", "obstacles", "objects", "robots", "eeprom"},
           example);
    world_spec w{};
    w.ir_range_mm = -1;
    w.ir_loss_pct = -1;
    w.ir_distance_bias_mm = IR_DISTANCE_BIAS_MM;
    w.ir_distance_noise_mm = IR_DISTANCE_NOISE_MM;
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
    if (auto i = get(root, "ir")) ir(*i, w);
    if (auto c = get(root, "clock_spread_pct"))
        w.clock_spread_pct = number(*c, 0, 5, false, "percent the robots' clocks differ by", "\"clock_spread_pct\": 0.5");
    if (auto l = get(root, "light")) light(*l, w);
    if (auto e = get(root, "eeprom")) eeprom(*e, w);
    if (auto n = get(root, "noise")) noise(*n, w);
    if (auto c = get(root, "camera")) camera(*c, w);
    auto list = [&](const char *key, const std::string &ex) -> std::optional<Node> {
        auto n = get(root, key);
        if (n && !n.value()->is_array()) fail(*n, "expected a list, found " + found(**n) + "; e.g. \"" + key + "\": [" + ex + "]");
        return n;
    };
    if (auto obs = list("obstacles", "{\"rect\": {\"x_mm\": 100, \"y_mm\": 100, \"width_mm\": 50, \"height_mm\": 20}}")) {
        list_within(*obs, "obstacles", WORLD_MAX_OBSTACLES,
                    "merge neighbouring obstacles into one polygon (up to " + std::to_string(WORLD_MAX_VERTICES) +
                        " vertices), or keep fewer");
        for (size_t k = 0; k < obs.value()->size(); k++) obstacle(item(*obs, k));
    }
    if (auto objs = list("objects", "{\"x_mm\": 200, \"y_mm\": 200, \"radius_mm\": 20}")) {
        list_within(*objs, "objects", WORLD_MAX_OBJECTS, "keep fewer");
        for (size_t k = 0; k < objs.value()->size(); k++) movable_object(item(*objs, k));
    }
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

/* The C arrays world_spec_free frees. */
void Reader::export_to(world_spec &w) const {
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

namespace {

/* Scans, parses and checks text into w: once made, its arrays are w's, for
 * world_spec_free to free whatever is thrown after. */
void read_world(const char *path, const std::string &text, world_spec &w) {
    TextPositions at = scan_json_text(text);
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::exception &e) {
        /* What the scanner lets through and nlohmann does not: invalid UTF-8. */
        throw Mistake{0, std::string("not readable as JSON: ") + e.what() + "; save the file as UTF-8"};
    }
    Reader reader(path, at);
    w = reader.load(doc);
    reader.export_to(w);
}

}  // namespace

}  // namespace world_file

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
    /* A UTF-8 byte order mark, as some Windows editors save: not part of
     * the JSON (nlohmann skips it too); dropped, so that columns on the
     * first line count from the '{'. */
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
    world_spec w{};
    try {
        world_file::read_world(path, text, w);
    } catch (const world_file::Mistake &m) {
        world_file::report(path, text, m.byte, m.text);
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
