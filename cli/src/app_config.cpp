#include "app_config.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "json_checks.hpp"
#include "names.hpp"
#include "ports.hpp"
#include "regular_file.hpp"
#include "suggest.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace openswarm {

namespace {

bool continues_character(char c) { return ((unsigned char)c & 0xC0u) == 0x80u; }

// Characters (not bytes) in text[from, to): where the caret goes.
size_t characters(const std::string &text, size_t from, size_t to) {
    size_t n = 0;
    for (size_t i = from; i < to; i++) n += continues_character(text[i]) ? 0 : 1;
    return n;
}

}  // namespace

// The line with the place marked: at most 60 bytes either side of it, cut
// between UTF-8 characters (a 1 MB line is not echoed whole).
std::string located_message(const fs::path &file, const std::string &text, size_t byte,
                            const std::string &message) {
    constexpr size_t context = 60;
    byte = std::min(byte, text.size());
    size_t line = 1, line_start = 0;
    for (size_t i = 0; i < byte; i++) {
        if (text[i] == '\n') {
            line++;
            line_start = i + 1;
        }
    }
    size_t line_end = std::min(text.find('\n', line_start), text.size());
    size_t from = byte - line_start > context ? byte - context : line_start;
    while (from > line_start && continues_character(text[from])) from--;
    size_t to = line_end - byte > context ? byte + context : line_end;
    while (to < line_end && continues_character(text[to])) to++;
    std::ostringstream out;
    out << file.string() << ":" << line << ":" << characters(text, line_start, byte) + 1 << ": " << message
        << "\n    " << (from > line_start ? "..." : "") << text.substr(from, to - from)
        << (to < line_end ? "..." : "") << "\n    "
        << std::string((from > line_start ? 3 : 0) + characters(text, from, byte), ' ') << "^";
    return out.str();
}

namespace {

// The kernel settings openswarm.json may give, with their config.h names
// and allowed ranges.
struct KernelSetting {
    const char *key, *macro;
    long min, max;
};
const KernelSetting kernel_settings[] = {
    {"max_threads", "OS_CFG_MAX_THREADS", 2, 16},
    {"stack_pool", "OS_CFG_STACK_POOL_BYTES", 16, 60000},
    {"default_stack", "OS_CFG_DEFAULT_STACK_BYTES", 16, 4096},
    {"max_events", "OS_CFG_MAX_EVENTS", 2, 255},
    {"event_data", "OS_CFG_EVENT_DATA_BYTES", 0, 60000},
    {"max_subscriptions", "OS_CFG_MAX_SUBSCRIPTIONS", 1, 254},
    {"event_queue", "OS_CFG_EVENT_QUEUE_BYTES", 8, 255},
    {"max_devices", "OS_CFG_MAX_DEVICES", 1, 32},
    {"hal_max_value", "OS_CFG_HAL_MAX_VALUE", 1, 253},
};

// The kernel's optional features openswarm.json may turn off (true/false,
// written as 1/0): their flash goes with them.
const KernelSetting kernel_switches[] = {
    {"stack_check", "OS_CFG_STACK_CHECK", 0, 1},
    {"clock_event", "OS_CFG_CLOCK_EVENT", 0, 1},
    {"handler_context", "OS_CFG_HANDLER_CONTEXT", 0, 1},
    {"tickless", "OS_CFG_TICKLESS", 0, 1},
    {"kilolib_idle_loop", "KILOLIB_IDLE_LOOP", 0, 1},
};

const std::map<std::string, unsigned> payload_types = {
    {"none", 0}, {"int8", 1}, {"uint8", 1}, {"int16", 2}, {"uint16", 2}, {"int32", 4}, {"uint32", 4},
};

// An event's or a thread entry's name: a C identifier of at most
// identifier_max characters (C99 promises 63 significant ones; a thread's
// entry is also kept in flash as its name: one of 20000 characters was
// called valid and overflowed the Kilobot's flash, issue 30).
constexpr size_t identifier_max = 63;

std::string identifier_at(const fs::path &file, const std::string &path, const json &v) {
    std::string id = string_at(file, path, v, "a C identifier");
    if (!is_c_identifier(id)) fail(file, path, quoted_start(id) + " is not a C identifier (letters, digits, _)");
    if (id.size() > identifier_max)
        fail(file, path, quoted_start(id) + " is " + std::to_string(id.size()) + " characters long: a name is 1.." +
                             std::to_string(identifier_max) + " characters (C99's significant length); shorten it");
    return id;
}

void load_kernel(const fs::path &file, const json &k, AppConfig &c) {
    if (!k.is_object()) fail(file, "kernel", "expected an object { ... }, found " + found(k));
    std::vector<std::string> allowed = {"scheduler", "time_slice_ms"};
    for (const auto &s : kernel_settings) allowed.push_back(s.key);
    for (const auto &s : kernel_switches) allowed.push_back(s.key);
    check_keys(file, "kernel", k, allowed);
    for (const auto &s : kernel_settings)
        if (k.contains(s.key)) c.kernel[s.key] = number_at(file, std::string("kernel.") + s.key, k[s.key], s.min, s.max);
    for (const auto &s : kernel_switches) {
        if (!k.contains(s.key)) continue;
        const json &on = k[s.key];
        if (!on.is_boolean())
            fail(file, std::string("kernel.") + s.key, "expected true or false, found " + found(on));
        c.kernel[s.key] = on.get<bool>() ? 1 : 0;
    }
    if (k.contains("time_slice_ms")) c.time_slice_ms = number_at(file, "kernel.time_slice_ms", k["time_slice_ms"], 1, 1000);
    if (k.contains("scheduler")) {
        c.scheduler = string_at(file, "kernel.scheduler", k["scheduler"], "\"round-robin\" or \"priority\"");
        if (c.scheduler != "round-robin" && c.scheduler != "priority") {
            fail(file, "kernel.scheduler", "unknown scheduler \"" + c.scheduler +
                     "\"; expected \"round-robin\" or \"priority\"" +
                     did_you_mean(c.scheduler, {"round-robin", "priority"}));
        }
    }
}

std::string upper_case(std::string s) {
    for (char &ch : s) ch = (char)std::toupper((unsigned char)ch);
    return s;
}

void load_events(const fs::path &file, const json &list, AppConfig &c) {
    if (!list.is_array()) fail(file, "events", "expected a list [ {\"name\": ...}, ... ], found " + found(list));
    std::map<std::string, std::string> macros; // EV_ name -> the name that made it
    for (size_t i = 0; i < list.size(); i++) {
        std::string path = "events[" + std::to_string(i) + "]";
        const json &e = list[i];
        if (!e.is_object()) fail(file, path, "expected {\"name\": ..., \"type\": ...}, found " + found(e));
        check_keys(file, path, e, {"name", "type", "size"});
        EventConfig ev;
        ev.name = identifier_at(file, path + ".name", require(file, e, "name", path));
        auto [other, fresh] = macros.emplace(upper_case(ev.name), ev.name);
        if (!fresh)
            fail(file, path + ".name",
                 "\"" + ev.name + "\" is declared twice" +
                     (other->second == ev.name ? "" : " (as \"" + other->second + "\": both would be EV_" +
                                                          other->first + ")"));
        if (e.contains("type") && e.contains("size")) fail(file, path, "give \"type\" or \"size\", not both");
        if (e.contains("type")) {
            std::string t = string_at(file, path + ".type", e["type"], "a payload type");
            auto it = payload_types.find(t);
            if (it == payload_types.end()) {
                std::vector<std::string> names;
                for (const auto &[n, size] : payload_types) { (void)size; names.push_back(n); }
                fail(file, path + ".type", "unknown type \"" + t + "\"; expected one of " + join(names) +
                         did_you_mean(t, names));
            }
            ev.size = it->second;
            ev.type = t;
        } else if (e.contains("size")) {
            ev.size = (unsigned)number_at(file, path + ".size", e["size"], 0, 253);
        }
        c.events.push_back(ev);
    }
}

void load_threads(const fs::path &file, const json &list, AppConfig &c) {
    if (!list.is_array()) fail(file, "threads", "expected a list [ {\"entry\": ...}, ... ], found " + found(list));
    std::set<std::string> entries;
    for (size_t i = 0; i < list.size(); i++) {
        std::string path = "threads[" + std::to_string(i) + "]";
        const json &t = list[i];
        if (!t.is_object()) fail(file, path, "expected {\"entry\": ..., \"stack\": ...}, found " + found(t));
        check_keys(file, path, t, {"entry", "stack", "priority"});
        ThreadConfig th;
        th.entry = identifier_at(file, path + ".entry", require(file, t, "entry", path));
        if (!entries.insert(th.entry).second)
            fail(file, path + ".entry", "\"" + th.entry + "\" starts two threads: each thread's entry "
                     "is a function of its own (two threads running one loop: write two functions "
                     "that call it)");
        if (t.contains("stack")) th.stack = (unsigned)number_at(file, path + ".stack", t["stack"], 16, 4096);
        if (t.contains("priority")) th.priority = (unsigned)number_at(file, path + ".priority", t["priority"], 0, 255);
        c.threads.push_back(th);
    }
    auto max_threads = c.kernel.find("max_threads");
    if (max_threads != c.kernel.end() && (long)c.threads.size() + 1 > max_threads->second)
        fail(file, "threads", std::to_string(c.threads.size()) + " threads and the system thread need "
             "kernel.max_threads >= " + std::to_string(c.threads.size() + 1) + ", found " +
             std::to_string(max_threads->second));
}

// A list of [raw, value] pairs: how many the processor takes, each within
// its ranges, raw strictly increasing (the interpolation needs an order).
std::vector<std::pair<long, long>> points_at(const fs::path &file, const std::string &path, const json &v,
                                             const PointsParam &p) {
    std::string range = std::to_string(p.min_count) + ".." + std::to_string(p.max_count);
    if (!v.is_array())
        fail(file, path, "expected a list of " + range + " [raw, value] points, found " + found(v));
    if (v.size() < p.min_count || v.size() > p.max_count)
        fail(file, path, "expected " + range + " [raw, value] points, found a list of " + std::to_string(v.size()));
    std::vector<std::pair<long, long>> points;
    for (size_t i = 0; i < v.size(); i++) {
        std::string at = path + "[" + std::to_string(i) + "]";
        if (!v[i].is_array() || v[i].size() != 2)
            fail(file, at, "expected a [raw, value] pair of whole numbers, found " + found(v[i]));
        long raw = number_at(file, at + "[0]", v[i][0], p.raw_min, p.raw_max);
        long value = number_at(file, at + "[1]", v[i][1], p.value_min, p.value_max);
        if (!points.empty() && raw <= points.back().first)
            fail(file, at + "[0]", "expected a raw count above " + std::to_string(points.back().first) +
                                       " (raw counts must increase from point to point), found " + found(v[i][0]));
        points.emplace_back(raw, value);
    }
    return points;
}

std::vector<std::string> names_of(const std::vector<DeviceInfo> &all) {
    std::vector<std::string> n;
    for (const auto &d : all) n.push_back(d.name);
    return n;
}

// port_note: why the devices are checked for a port other than the file's
// ("" when they are not).
void load_devices(const fs::path &file, const json &devices, AppConfig &c, const std::string &port_note) {
    if (!devices.is_object())
        fail(file, "devices", "expected an object {\"motors\": {\"processor\": ...}}, found " + found(devices));
    const auto &known = devices_of(c.port);
    for (const auto &item : devices.items()) {
        const std::string name = item.key();
        const json &d = item.value();
        std::string path = "devices." + name;
        auto device = std::find_if(known.begin(), known.end(), [&](const DeviceInfo &i) { return i.name == name; });
        if (device == known.end()) {
            if (!port_note.empty())
                fail(file, path, "no device \"" + name + "\" on " + c.port + port_note +
                                     (known.empty() ? "" : "; " + c.port + "'s devices: " + join(names_of(known))));
            fail(file, path, "no device \"" + name + "\" on " + c.port + "; devices: " + join(names_of(known)) +
                                 did_you_mean(name, names_of(known)));
        }
        if (!d.is_object()) fail(file, path, "expected {\"processor\": ...}, found " + found(d));
        DeviceConfig dc;
        dc.device = name;
        dc.processor = string_at(file, path + ".processor", require(file, d, "processor", path), "a processor name");
        std::vector<std::string> processor_names;
        const ProcessorInfo *p = nullptr;
        for (const auto &candidate : device->processors) {
            processor_names.push_back(candidate.name);
            if (candidate.name == dc.processor) p = &candidate;
        }
        if (p == nullptr) {
            fail(file, path + ".processor", "unknown processor \"" + dc.processor + "\" for " + name +
                     "; processors: " + join(processor_names) + did_you_mean(dc.processor, processor_names));
        }
        std::vector<std::string> allowed = {"processor"};
        for (const auto &param : p->params) allowed.push_back(param.name);
        if (p->points) allowed.push_back(p->points->name);
        check_keys(file, path, d, allowed);
        for (const auto &param : p->params)
            dc.params[param.name] = number_at(file, path + "." + param.name, require(file, d, param.name, path), param.min, param.max);
        if (p->points)
            dc.points = points_at(file, path + "." + p->points->name, require(file, d, p->points->name, path), *p->points);
        c.devices.push_back(dc);
    }
}

std::vector<std::string> keys_of(const std::map<std::string, int> &m) {
    std::vector<std::string> keys;
    for (const auto &item : m) keys.push_back(item.first);
    return keys;
}

// The Kilobot's own settings, written for its port alone (another port's
// build ignores them, so `build --port` needs no edit).
void load_kilobot(const fs::path &file, const json &k, AppConfig &c) {
    if (!k.is_object())
        fail(file, "kilobot", "expected an object {\"overhead_controller\": ...}, found " + found(k));
    check_keys(file, "kilobot", k, {"overhead_controller"});
    if (!k.contains("overhead_controller")) return;
    const auto names = keys_of(overhead_controller_choices());
    std::string choice = string_at(file, "kilobot.overhead_controller", k["overhead_controller"],
                                   "\"port\", \"events\" or \"off\"");
    if (!overhead_controller_choices().count(choice))
        fail(file, "kilobot.overhead_controller",
             "unknown choice \"" + choice + "\"; expected \"port\" (the port answers KiloGUI), \"events\" "
             "(the app gets KILOBOT_EVENT_OHC) or \"off\" (the messages reach KILOBOT_EVENT_IR_RX)" +
                 did_you_mean(choice, names));
    c.overhead_controller = choice;
}

// The e-puck2's own settings, like the Kilobot's: checked in every build,
// used by the epuck2 port's alone.
void load_epuck2(const fs::path &file, const json &e, AppConfig &c) {
    if (!e.is_object())
        fail(file, "epuck2", "expected an object {\"bootloader\": \"none\" or \"aseba\"}, found " + found(e));
    check_keys(file, "epuck2", e, {"bootloader"});
    if (!e.contains("bootloader")) return;
    std::vector<std::string> names;
    for (const auto &p : epuck2_placements()) names.push_back(p.bootloader);
    std::string choice = string_at(file, "epuck2.bootloader", e["bootloader"], "\"none\" or \"aseba\"");
    if (std::find(names.begin(), names.end(), choice) == names.end())
        fail(file, "epuck2.bootloader",
             "unknown choice \"" + choice + "\"; expected \"none\" (the robot image at 0x08000000, the "
             "flash's start: a robot with GCtronic's standard firmware, flashed through its programmer) "
             "or \"aseba\" (at 0x08020000, after the Aseba bootloader's 128 KB)" +
                 did_you_mean(choice, names));
    c.epuck2_bootloader = choice;
}

}  // namespace

const FlashPlacement &robot_placement(const AppConfig &c) {
    return epuck2_placement(c.epuck2_bootloader.empty() ? "none" : c.epuck2_bootloader);
}

unsigned flash_budget(const AppConfig &c) {
    return c.port == "epuck2" ? robot_placement(c).bytes : port_info(c.port).flash_bytes;
}

std::string flash_budget_note(const AppConfig &c) {
    if (c.port != "epuck2") return port_info(c.port).flash_note;
    const FlashPlacement &p = robot_placement(c);
    if (p.bytes == port_info(c.port).flash_bytes) return "";
    return "of its 1 MB: openswarm.json's \"epuck2\": {\"bootloader\": \"" + p.bootloader +
           "\"} puts the robot image at " + hex_address(p.origin) + ", " + p.what;
}

const std::map<std::string, int> &overhead_controller_choices() {
    static const std::map<std::string, int> choices = {{"off", 0}, {"port", 1}, {"events", 2}};
    return choices;
}

const std::vector<std::pair<std::string, std::string>> &kernel_setting_macros() {
    static std::vector<std::pair<std::string, std::string>> all;
    if (all.empty()) {
        for (const auto &s : kernel_settings) all.emplace_back(s.key, s.macro);
        for (const auto &s : kernel_switches) all.emplace_back(s.key, s.macro);
    }
    return all;
}

bool is_kernel_switch(const std::string &key) {
    for (const auto &s : kernel_switches)
        if (key == s.key) return true;
    return false;
}

std::string port_given_or_app(const std::string &port, const fs::path &dir) {
    if (!port.empty()) return port;
    try {
        return load_app_config(dir).port;
    } catch (const std::exception &) {
        return "";
    }
}

AppConfig load_app_config(const fs::path &dir, const std::string &port) {
    AppConfig config;
    config.file = dir / "openswarm.json";
    std::error_code error;
    std::string kind = not_a_regular_file(config.file);
    if (!kind.empty())
        throw ConfigError(config.file.string() + ": " + kind + ", not a file; the app's configuration is a "
                          "JSON file of that name (move it away; `openswarm new` shows one)");
    if (!fs::exists(config.file, error))
        throw ConfigError(config.file.string() +
                          ": not found; run this in an app folder, or make one with "
                          "`openswarm new NAME --template blinky`");
    std::ifstream in(config.file);
    if (!in)
        throw ConfigError(config.file.string() + ": cannot be read (" + std::strerror(errno) +
                          "); check its permissions");
    std::stringstream buffer;
    buffer << in.rdbuf();
    std::string text = buffer.str();
    json doc = parse_json_file(config.file, text);
    const fs::path &file = config.file;
    if (!doc.is_object()) fail(file, "", "expected a JSON object { ... }, found " + found(doc));
    check_keys(file, "", doc, {"name", "port", "kernel", "events", "threads", "devices", "kilobot", "epuck2",
                               "parameters"});
    config.name = string_at(file, "name", require(file, doc, "name"), "the app's name");
    if (!is_app_name(config.name))
        fail(file, "name", quoted_start(config.name) + " is not a usable app name: letters, digits, - and _, "
                           "starting with a letter, at most " + std::to_string(app_name_max) +
                           " characters (it names the image file)");
    if (!taken_app_name(config.name).empty())
        fail(file, "name", "\"" + config.name + "\" cannot name an app: " + taken_app_name(config.name) +
                               "; choose another name");
    config.port = string_at(file, "port", require(file, doc, "port"), "a port name");
    if (!is_port(config.port)) {
        fail(file, "port", "unknown port \"" + config.port + "\"; known: " + join(port_names()) +
                               did_you_mean(config.port, port_names()));
    }
    std::string port_note;
    if (!port.empty() && port != config.port) {
        port_note = " (--port " + port + "; the file's \"port\" is " + config.port + "): build for " + config.port +
                    " (leave --port out), or remove this device for " + port;
        config.port = port;
    }
    if (doc.contains("kernel")) load_kernel(file, doc["kernel"], config);
    if (doc.contains("events")) load_events(file, doc["events"], config);
    if (doc.contains("threads")) load_threads(file, doc["threads"], config);
    if (doc.contains("devices")) load_devices(file, doc["devices"], config, port_note);
    if (doc.contains("kilobot")) load_kilobot(file, doc["kilobot"], config);
    if (doc.contains("epuck2")) load_epuck2(file, doc["epuck2"], config);
    if (doc.contains("parameters")) load_parameters(file, doc["parameters"], config);
    return config;
}

}  // namespace openswarm
