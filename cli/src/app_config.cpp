#include "app_config.hpp"

#include <fstream>
#include <sstream>

#include "ports.hpp"
#include "suggest.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace openswarm {

std::string located_message(const fs::path &file, const std::string &text, size_t byte,
                            const std::string &message) {
    size_t line = 1, line_start = 0;
    for (size_t i = 0; i < byte && i < text.size(); i++) {
        if (text[i] == '\n') {
            line++;
            line_start = i + 1;
        }
    }
    size_t line_end = text.find('\n', line_start);
    std::string source = text.substr(line_start, line_end == std::string::npos ? std::string::npos
                                                                                : line_end - line_start);
    size_t column = byte >= line_start ? byte - line_start + 1 : 1;
    std::ostringstream out;
    out << file.string() << ":" << line << ":" << column << ": " << message << "\n"
        << "    " << source << "\n"
        << "    " << std::string(column > 0 ? column - 1 : 0, ' ') << "^";
    return out.str();
}

static const json &require(const json &doc, const fs::path &file, const char *key,
                           json::value_t type, const char *what) {
    if (!doc.contains(key))
        throw ConfigError(file.string() + ": missing \"" + key + "\": expected " + what +
                          "; add it, e.g. \"" + key + "\": " +
                          (type == json::value_t::string ? "\"...\"" : "..."));
    const json &v = doc.at(key);
    if (v.type() != type)
        throw ConfigError(file.string() + ": \"" + key + "\" is " + v.type_name() + ", expected " +
                          what);
    return v;
}

AppConfig load_app_config(const fs::path &dir) {
    AppConfig config;
    config.file = dir / "openswarm.json";
    std::ifstream in(config.file);
    if (!in)
        throw ConfigError(config.file.string() +
                          ": not found; run this in an app folder, or make one with "
                          "`openswarm new NAME --template blinky`");
    std::stringstream buffer;
    buffer << in.rdbuf();
    std::string text = buffer.str();
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::parse_error &e) {
        std::string what = e.what();
        size_t colon = what.rfind(": ");
        std::string reason = colon == std::string::npos ? what : what.substr(colon + 2);
        throw ConfigError(located_message(config.file, text, e.byte > 0 ? e.byte - 1 : 0,
                                          "invalid JSON: " + reason));
    }
    if (!doc.is_object())
        throw ConfigError(config.file.string() + ": expected a JSON object { ... }, found " +
                          std::string(doc.type_name()));
    config.name = require(doc, config.file, "name", json::value_t::string, "the app's name")
                      .get<std::string>();
    config.port = require(doc, config.file, "port", json::value_t::string, "a port name")
                      .get<std::string>();
    if (!is_port(config.port)) {
        std::string hint = nearest(config.port, port_names());
        throw ConfigError(config.file.string() + ": \"port\": unknown port \"" + config.port +
                          "\"; known: " + join(port_names()) +
                          (hint.empty() ? "" : " (did you mean \"" + hint + "\"?)"));
    }
    return config;
}

}  // namespace openswarm
