#include "app_parameters.hpp"

#include <cctype>
#include <cerrno>
#include <climits>
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

AppParameter parameter_at(const fs::path &file, const std::string &name, const json &p) {
    std::string path = "parameters." + name;
    if (!p.is_object())
        fail(file, path, std::string("expected {\"default\": N, \"min\": N, \"max\": N, \"doc\": \"...\"}, found ") +
                             found(p) + "; " + example);
    check_keys(file, path, p, {"default", "min", "max", "doc"});
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
    return a;
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
}

std::string parameter_problem(const AppConfig &c, const std::string &name, const json &value) {
    const AppParameter *p = nullptr;
    for (const auto &candidate : c.parameters)
        if (candidate.name == name) p = &candidate;
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

std::string parameters_header(const AppConfig &c) {
    std::string h = "/* Generated by `openswarm build` from openswarm.json's \"parameters\": edit that, not this.\n"
                    " * Each is a macro in the app's sources; a build given other values\n"
                    " * (openswarm build -D NAME=VALUE, a sweep's \"app.NAME\") defines them first. */\n"
                    "#ifndef OPENSWARM_PARAMETERS_H\n#define OPENSWARM_PARAMETERS_H\n";
    for (const auto &p : c.parameters) {
        h += "\n/* " + (p.doc.empty() ? p.name : p.doc) + " (" + std::to_string(p.min) + ".." +
             std::to_string(p.max) + ") */\n#ifndef " + p.name + "\n#define " + p.name + " " +
             (p.value < 0 ? "(" + std::to_string(p.value) + ")" : std::to_string(p.value)) + "\n#endif\n";
    }
    return h + "\n#endif\n";
}

}  // namespace openswarm
