// The robots OpenSwarm builds for.
#pragma once

#include <string>
#include <vector>

namespace openswarm {

struct PortInfo {
    std::string name;
    std::string description;
    unsigned flash_bytes; // of the MCU, 0 for the host
    unsigned ram_bytes;
};

const std::vector<PortInfo> &ports();
std::vector<std::string> port_names();
bool is_port(const std::string &name);
const PortInfo &port_info(const std::string &name);

}  // namespace openswarm
