// The linker's "region `data' overflowed by N bytes", said for a person:
// which memory, by how much, who holds most of it and what to change; and
// its "undefined reference" to the heap (malloc on a robot, which has none).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "app_config.hpp"

namespace openswarm {

// Collects a build's output, line by line, for what the linker said.
class LinkOverflows {
  public:
    void scan(const std::string &line);
    // The explanation, if the linker reported a region too small.
    std::optional<std::string> explain(const AppConfig &config,
                                       const std::filesystem::path &generated_config) const;

  private:
    long flash_over = 0, ram_over = 0;
    bool heap_wanted = false;
};

}  // namespace openswarm
