#include "ports.hpp"

#include <stdexcept>

namespace openswarm {

const std::vector<PortInfo> &ports() {
    static const std::vector<PortInfo> all = {
        {"kilobot", "Kilobot: ATmega328P at 8 MHz, run in simavr", 32768, 2048, 6, 6 + 4 * 16, 4, 12, 96, 16},
    };
    return all;
}

std::vector<std::string> port_names() {
    std::vector<std::string> names;
    for (const auto &p : ports()) names.push_back(p.name);
    return names;
}

bool is_port(const std::string &name) {
    for (const auto &p : ports())
        if (p.name == name) return true;
    return false;
}

const PortInfo &port_info(const std::string &name) {
    for (const auto &p : ports())
        if (p.name == name) return p;
    throw std::out_of_range(name);
}

}  // namespace openswarm
