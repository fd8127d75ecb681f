// An app's parameters (openswarm.json's "parameters"): whole numbers the
// build defines as macros in the app's sources, each with a default and a
// range; `build`/`run -D NAME=VALUE` and a sweep's "app.NAME" places give
// other values, each set built in a folder of its own.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace openswarm {

struct AppConfig;

struct AppParameter {
    std::string name; // the macro: upper-case letters, digits and _
    long value = 0;   // the default
    long min = 0, max = 0;
    std::string doc;
    // "at": "eeprom": the firmware reads the value from the EEPROM at
    // eeprom_address, so a run sets it without a build.
    bool in_eeprom = false;
    unsigned eeprom_address = 0;
};

// Where the app's EEPROM values go on a Kilobot: kilolib keeps OSCCAL,
// the motor calibration, the distance tables, the IR mask and the uid
// below 0x100 (ports/kilobot/include/openswarm/kilobot.h); the rest of the
// 1 KB is the app's. Each value takes 4 bytes.
constexpr unsigned eeprom_parameters_start = 0x100, eeprom_bytes = 1024, eeprom_parameter_bytes = 4;

// Values set for some parameters, by name (the others keep their defaults).
using ParameterValues = std::map<std::string, long>;

// The most parameters an app declares.
constexpr size_t max_app_parameters = 64;

// Reads "parameters" of openswarm.json (file) into c; a ConfigError names
// the place and the fix.
void load_parameters(const std::filesystem::path &file, const nlohmann::json &list, AppConfig &c);

// Why value cannot be parameter name's ("" if it can): no such parameter,
// not a whole number, out of its range - each with the fix.
std::string parameter_problem(const AppConfig &c, const std::string &name, const nlohmann::json &value);

// "NAME=VALUE" (from -D) into values; false with why (the syntax only:
// parameter_problem checks the value against the app).
bool parse_parameter_setting(const std::string &text, ParameterValues &values, std::string &why);

// The parameter the app declares by name (nullptr: none).
const AppParameter *find_parameter(const AppConfig &c, const std::string &name);

// The 4 bytes the EEPROM holds for value of p (little-endian, value - min:
// an erased EEPROM, 0xFF bytes, reads as out of range, the default).
std::vector<unsigned> eeprom_parameter_bytes_of(const AppParameter &p, long value);

// The values that differ from the defaults (those make another build).
ParameterValues changed_parameters(const AppConfig &c, const ParameterValues &values);

// "" for no values, else "-p" and a fingerprint of them: the build
// folder's suffix, so each set is built once and kept.
std::string parameters_folder_suffix(const ParameterValues &values);

// The values as CMake's OPENSWARM_PARAMETERS list, "SPEED=80;TURN=3".
std::string parameters_cmake_list(const ParameterValues &values);

// openswarm_parameters.h: each parameter's default, unless the build
// defines it (-D), and its doc.
std::string parameters_header(const AppConfig &c);

}  // namespace openswarm
