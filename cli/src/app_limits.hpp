// What openswarm.json may declare and still build and run as declared:
// the names the generated code makes from it, and the limits config.h, the
// kernel and the robot's RAM set. `config check` and `build` ask the same.
#pragma once

#include <map>
#include <string>

#include "app_config.hpp"
#include "ports.hpp"

namespace openswarm {

// A ConfigError naming the key and the fix for the first thing the
// generated code, config.h or the linker would refuse.
void check_app_limits(const AppConfig &config, const PortInfo &port, const Libraries &libraries);

// The RAM the pools need (max_threads, stack_pool, max_events and
// event_data as the build generates them; the port's own where it sets
// none) fits the robot, with room for the main stack's minimum; a
// ConfigError naming the biggest stack, or the biggest event, if not.
void check_declared_ram(const AppConfig &config, const PortInfo &port, const std::map<std::string, long> &pools);

// A stack_pool the file gives is whole stack blocks (after the check that
// it holds the threads' stacks, which says more).
void check_stack_pool_blocks(const AppConfig &config, const PortInfo &port);

}  // namespace openswarm
