#include "app_parameters.hpp"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>

#include "app_config.hpp"
#include "fingerprint.hpp"
#include "json_checks.hpp"
#include "names.hpp"
#include "suggest.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace openswarm {

namespace {

// A long on every port: the Kilobot's and the e-puck's long is 32 bits.
constexpr long value_min = -2147483647L - 1, value_max = 2147483647L;

const char *example = "e.g. \"parameters\": {\"SPEED\": {\"default\": 50, \"min\": 0, \"max\": 255}}";

// Upper case, as macros are: a parameter reads as a constant in the code.
bool is_macro_name(const std::string &name) {
    if (name.empty() || !std::isupper((unsigned char)name[0])) return false;
    for (char c : name)
        if (!std::isupper((unsigned char)c) && !std::isdigit((unsigned char)c) && c != '_') return false;
    return true;
}

std::string name_at(const fs::path &file, const std::string &name) {
    std::string path = "parameters." + name;
    if (!is_macro_name(name) || name.size() > 63)
        fail(file, path, quoted_start(name) + " cannot name a parameter: upper-case letters, digits and _, "
                                              "starting with a letter, at most 63 characters (it is a macro in "
                                              "the app's sources), e.g. \"SPEED\"");
    for (const char *prefix : {"EV_", "OPENSWARM_"})
        if (name.rfind(prefix, 0) == 0)
            fail(file, path, "\"" + name + "\" cannot name a parameter: the build's own macros start with " +
                                 prefix + "; choose another");
    std::string taken = taken_identifier(name);
    if (!taken.empty()) fail(file, path, "\"" + name + "\" cannot name a parameter: " + taken + "; choose another");
    return name;
}

// "at": "eeprom" (else "build", the default): refused where the EEPROM
// cannot tell an erased value from a set one, the full 32-bit range.
void at_eeprom(const fs::path &file, const std::string &path, const json &at, AppParameter &a) {
    std::string where = string_at(file, path + ".at", at, "\"build\" or \"eeprom\"");
    if (where == "build") return;
    if (where != "eeprom")
        fail(file, path + ".at", "unknown choice \"" + where + "\"; expected \"build\" (a macro built in, the "
                                 "default) or \"eeprom\" (read from the EEPROM at start, set per run by the world)" +
                                     did_you_mean(where, {"build", "eeprom"}));
    if ((unsigned long)(a.max - a.min) >= 0xFFFFFFFFul)
        fail(file, path + ".at", "a value read from the EEPROM needs a range narrower than every 32-bit number "
                                 "(an erased EEPROM must read as out of it, so as the default): give \"min\" and "
                                 "\"max\"");
    a.in_eeprom = true; // placed once every parameter is read
}

AppParameter parameter_at(const fs::path &file, const std::string &name, const json &p) {
    std::string path = "parameters." + name;
    if (!p.is_object())
        fail(file, path, std::string("expected {\"default\": N, \"min\": N, \"max\": N, \"doc\": \"...\"}, found ") +
                             found(p) + "; " + example);
    check_keys(file, path, p, {"default", "min", "max", "doc", "at"});
    AppParameter a;
    a.name = name;
    a.min = p.contains("min") ? number_at(file, path + ".min", p["min"], value_min, value_max) : value_min;
    a.max = p.contains("max") ? number_at(file, path + ".max", p["max"], value_min, value_max) : value_max;
    if (a.min > a.max)
        fail(file, path + ".max", "the range is empty: \"max\" " + std::to_string(a.max) + " is below \"min\" " +
                                      std::to_string(a.min) + "; swap them");
    a.value = number_at(file, path + ".default", require(file, p, "default", path), a.min, a.max);
    if (p.contains("doc")) a.doc = string_at(file, path + ".doc", p["doc"], "a sentence for people");
    if (a.doc.find("*/") != std::string::npos)
        fail(file, path + ".doc", "\"*/\" would end the generated header's comment: write it another way");
    if (p.contains("at")) at_eeprom(file, path, p["at"], a);
    return a;
}

// The EEPROM values one after another from eeprom_parameters_start, in
// the order of their names: every parameter fits.
static_assert(eeprom_parameters_start + max_app_parameters * eeprom_parameter_bytes <= eeprom_bytes,
              "the app's part of the EEPROM holds a value of every parameter");
void place_in_eeprom(const fs::path &file, AppConfig &c) {
    unsigned next = eeprom_parameters_start;
    for (auto &p : c.parameters) {
        if (!p.in_eeprom) continue;
        if (c.port != "kilobot")
            fail(file, "parameters." + p.name + ".at", "\"eeprom\": only a Kilobot's values are read from its "
                                                      "EEPROM, and this app's port is " + c.port +
                                                      "; drop \"at\" (the value is built in)");
        p.eeprom_address = next;
        next += eeprom_parameter_bytes;
    }
}

std::vector<std::string> names_of(const AppConfig &c) {
    std::vector<std::string> names;
    for (const auto &p : c.parameters) names.push_back(p.name);
    return names;
}

}  // namespace

void load_parameters(const fs::path &file, const json &list, AppConfig &c) {
    if (!list.is_object())
        fail(file, "parameters", "expected an object {\"NAME\": {\"default\": N, ...}, ...}, found " + found(list) +
                                     "; " + example);
    if (list.size() > max_app_parameters)
        fail(file, "parameters", std::to_string(list.size()) + " parameters: at most " +
                                     std::to_string(max_app_parameters) + "; keep the ones a run varies");
    for (const auto &[name, p] : list.items()) c.parameters.push_back(parameter_at(file, name_at(file, name), p));
    place_in_eeprom(file, c);
}

const AppParameter *find_parameter(const AppConfig &c, const std::string &name) {
    for (const auto &p : c.parameters)
        if (p.name == name) return &p;
    return nullptr;
}

std::vector<unsigned> eeprom_parameter_bytes_of(const AppParameter &p, long value) {
    unsigned long stored = (unsigned long)(value - p.min);
    return {unsigned(stored & 0xFF), unsigned(stored >> 8 & 0xFF), unsigned(stored >> 16 & 0xFF),
            unsigned(stored >> 24 & 0xFF)};
}

std::string parameter_problem(const AppConfig &c, const std::string &name, const json &value) {
    const AppParameter *p = find_parameter(c, name);
    if (p == nullptr)
        return c.file.string() + " declares no parameter \"" + name + "\"" +
               (c.parameters.empty() ? "" : " (it declares " + join(names_of(c)) + ")") +
               did_you_mean(name, names_of(c)) + "; declare it under \"parameters\" there, " + example;
    if (!value.is_number_integer() || value.get<long>() < p->min || value.get<long>() > p->max)
        return "parameter " + name + " takes a whole number " + std::to_string(p->min) + ".." +
               std::to_string(p->max) + " (" + c.file.string() + "), found " + found(value) +
               "; give one in its range, or widen \"min\"/\"max\" there";
    return "";
}

bool parse_parameter_setting(const std::string &text, ParameterValues &values, std::string &why) {
    size_t eq = text.find('=');
    std::string name = text.substr(0, eq), number = eq == std::string::npos ? "" : text.substr(eq + 1);
    errno = 0;
    char *end = nullptr;
    long value = number.empty() ? 0 : std::strtol(number.c_str(), &end, 10);
    if (eq == std::string::npos || name.empty() || number.empty() || *end != '\0' || errno == ERANGE ||
        std::isspace((unsigned char)number[0])) {
        why = "-D " + quoted_start(text) + ": expected NAME=VALUE, a parameter openswarm.json declares and a "
              "whole number, e.g. -D SPEED=80";
        return false;
    }
    if (values.count(name)) {
        why = "-D " + name + " is given twice: keep one";
        return false;
    }
    values[name] = value;
    return true;
}

ParameterValues changed_parameters(const AppConfig &c, const ParameterValues &values) {
    ParameterValues changed;
    for (const auto &p : c.parameters) {
        auto it = values.find(p.name);
        if (it != values.end() && it->second != p.value) changed[p.name] = it->second;
    }
    return changed;
}

std::string parameters_cmake_list(const ParameterValues &values) {
    std::string list;
    for (const auto &[name, value] : values) list += (list.empty() ? "" : ";") + name + "=" + std::to_string(value);
    return list;
}

std::string parameters_folder_suffix(const ParameterValues &values) {
    return values.empty() ? "" : "-p" + fingerprint(parameters_cmake_list(values));
}

namespace {

// A number as C reads it with the type long on every port: the least
// long is no literal of its own.
std::string c_long(long v) {
    if (v == value_min) return "(-2147483647L - 1)";
    return v < 0 ? "(" + std::to_string(v) + "L)" : std::to_string(v) + "L";
}

// The reader of "at": "eeprom" values: the EEPROM holds value - min as a
// little-endian 32-bit number; anything above max - min (an erased
// EEPROM's 0xFFFFFFFF) reads as the default.
const char *eeprom_reader =
    "\n#include <avr/eeprom.h>\n#include <stdint.h>\n\n"
    "/* A value the world sets per run (\"at\": \"eeprom\"): value - min at address. */\n"
    "static inline long openswarm_eeprom_parameter(uint16_t address, long min, uint32_t span, long fallback) {\n"
    "    uint32_t stored = eeprom_read_dword((const uint32_t *)(uintptr_t)address);\n"
    "    return stored > span ? fallback : (long)(int32_t)((uint32_t)min + stored);\n"
    "}\n";

std::string eeprom_definition(const AppParameter &p) {
    char address[16];
    std::snprintf(address, sizeof address, "0x%03X", p.eeprom_address);
    return "#define " + p.name + "_EEPROM_ADDRESS " + address + "\n#ifndef " + p.name + "\n#define " + p.name +
           " openswarm_eeprom_parameter(" + p.name + "_EEPROM_ADDRESS, " + c_long(p.min) + ", " +
           std::to_string((unsigned long)(p.max - p.min)) + "UL, " + c_long(p.value) + ")\n#endif\n";
}

}  // namespace

std::string parameters_header(const AppConfig &c) {
    std::string h = "/* Generated by `openswarm build` from openswarm.json's \"parameters\": edit that, not this.\n"
                    " * Each is a macro in the app's sources; a build given other values\n"
                    " * (openswarm build -D NAME=VALUE, a sweep's \"app.NAME\") defines them first.\n"
                    " * One \"at\": \"eeprom\" reads the robot's EEPROM where it is used, its\n"
                    " * default when the EEPROM holds none (docs/openswarm-json.md). */\n"
                    "#ifndef OPENSWARM_PARAMETERS_H\n#define OPENSWARM_PARAMETERS_H\n";
    bool reader = false;
    for (const auto &p : c.parameters) {
        if (p.in_eeprom && !reader) h += eeprom_reader;
        reader = reader || p.in_eeprom;
        h += "\n/* " + (p.doc.empty() ? p.name : p.doc) + " (" + std::to_string(p.min) + ".." +
             std::to_string(p.max) + (p.in_eeprom ? "; from the EEPROM" : "") + ") */\n";
        if (p.in_eeprom)
            h += eeprom_definition(p);
        else
            h += "#ifndef " + p.name + "\n#define " + p.name + " " +
                 (p.value < 0 ? "(" + std::to_string(p.value) + ")" : std::to_string(p.value)) + "\n#endif\n";
    }
    return h + "\n#endif\n";
}

}  // namespace openswarm
