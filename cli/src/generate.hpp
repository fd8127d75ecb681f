// What openswarm.json turns into: a configuration header for the kernel's
// pools, and the app's event ids and start-up code (static tables; nothing
// is allocated at run time).
#pragma once

#include <filesystem>

#include "app_config.hpp"

namespace openswarm {

// Write out_dir/openswarm_config.h, openswarm_app.h and openswarm_app.c
// (only the files whose content changed, so builds stay incremental).
void generate_app_files(const AppConfig &config, const std::filesystem::path &out_dir);

}  // namespace openswarm
