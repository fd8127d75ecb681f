#include "names.hpp"

#include <cctype>
#include <set>

namespace openswarm {

namespace {

bool is_letter(char c) { return std::isalpha((unsigned char)c) != 0; }
bool is_digit(char c) { return std::isdigit((unsigned char)c) != 0; }

bool starts_with(const std::string &s, const std::string &prefix) { return s.rfind(prefix, 0) == 0; }

// Keywords of C (C17) and C++ (C++17): the generated header is included
// from C++ too, where an event becomes openswarm::events::NAME.
const std::set<std::string> keywords = {
    "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else", "enum",
    "extern", "float", "for", "goto", "if", "inline", "int", "long", "register", "restrict", "return",
    "short", "signed", "sizeof", "static", "struct", "switch", "typedef", "union", "unsigned", "void",
    "volatile", "while", "_Alignas", "_Alignof", "_Atomic", "_Bool", "_Complex", "_Generic",
    "_Imaginary", "_Noreturn", "_Static_assert", "_Thread_local", "alignas", "alignof", "and", "and_eq",
    "asm", "bitand", "bitor", "bool", "catch", "char16_t", "char32_t", "class", "compl", "constexpr",
    "const_cast", "decltype", "delete", "dynamic_cast", "explicit", "export", "false", "friend",
    "mutable", "namespace", "new", "noexcept", "not", "not_eq", "nullptr", "operator", "or", "or_eq",
    "private", "protected", "public", "reinterpret_cast", "static_assert", "static_cast", "template",
    "this", "thread_local", "throw", "true", "try", "typeid", "typename", "using", "virtual", "wchar_t",
    "xor", "xor_eq"};

// Functions an app links with already: the C library's that the ports'
// code and kilolib programs call, and kilolib's own.
const std::set<std::string> library_functions = {
    "main", "printf", "sprintf", "snprintf", "puts", "putchar", "getchar", "exit", "abort", "malloc",
    "calloc", "realloc", "free", "memcpy", "memmove", "memset", "memcmp", "strlen", "strcpy", "strncpy",
    "strcmp", "strncmp", "strcat", "rand", "srand", "abs", "labs", "atoi", "sqrt", "sin", "cos", "atan2",
    "setup", "loop", "delay", "rand_hard", "rand_soft", "rand_seed", "set_motors", "spinup_motors",
    "set_color", "get_ambientlight", "get_voltage", "get_temperature", "estimate_distance",
    "message_crc", "debug_init"};

// Prefixes of the kernel's, the ports' and the generated code's names.
const char *const sdk_prefixes[] = {"Sys_", "SYS_", "os_", "OS_", "port_", "PORT_", "kilobot_", "KILOBOT_",
                                    "robot_", "ROBOT_", "epuck_", "EPUCK_", "openswarm_", "kilo_", "sim_"};

}  // namespace

bool is_c_identifier(const std::string &name) {
    if (name.empty() || is_digit(name[0])) return false;
    for (char c : name)
        if (!is_letter(c) && !is_digit(c) && c != '_') return false;
    return true;
}

bool is_app_name(const std::string &name) {
    if (name.empty() || name.size() > app_name_max || !is_letter(name[0])) return false;
    for (char c : name)
        if (!is_letter(c) && !is_digit(c) && c != '_' && c != '-') return false;
    return true;
}

std::string reserved_identifier(const std::string &name) {
    if (keywords.count(name)) return "a keyword of C or C++";
    if (starts_with(name, "__") || (name.size() > 1 && name[0] == '_' && std::isupper((unsigned char)name[1])))
        return "reserved by C (names starting with __ or _ and a capital)";
    return "";
}

std::string taken_identifier(const std::string &name) {
    std::string reserved = reserved_identifier(name);
    if (!reserved.empty()) return reserved;
    if (library_functions.count(name)) return "a function the app already links (C library or kilolib)";
    for (const char *prefix : sdk_prefixes)
        if (starts_with(name, prefix)) return std::string("the SDK's names start with ") + prefix;
    return "";
}

std::string taken_app_name(const std::string &name) {
    static const std::set<std::string> cmake_targets = {"all", "clean", "help", "install", "test",
                                                        "package", "package_source", "edit_cache",
                                                        "rebuild_cache", "depend", "list_install_components"};
    if (cmake_targets.count(name)) return "CMake's own target \"" + name + "\" has that name";
    return "";
}

}  // namespace openswarm
