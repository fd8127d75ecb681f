// The names openswarm.json gives become C identifiers, file names and a
// CMake target: what each may be, and which names are already taken.
#pragma once

#include <string>

namespace openswarm {

// The longest app name: it names the folder's image files and a CMake
// target, and file systems cut names at 255 bytes.
constexpr size_t app_name_max = 64;

// Letters, digits and _, not starting with a digit (no regex: a name of
// 40 000 characters overflowed std::regex's recursion).
bool is_c_identifier(const std::string &name);
// Letters, digits, - and _, starting with a letter, at most app_name_max.
bool is_app_name(const std::string &name);

// Why no C or C++ code may use name ("" if it may): keywords, and names C
// reserves (__x, _X).
std::string reserved_identifier(const std::string &name);
// Why an app may not use name as a function or macro stem ("" if it may):
// C and C++ keywords, main, names C reserves (__x, _X), the SDK's and the
// C library's own names.
std::string taken_identifier(const std::string &name);
// Why name cannot be an app's ("" if it can): CMake's own targets.
std::string taken_app_name(const std::string &name);

}  // namespace openswarm
