// How `openswarm build` reports what it built: the image's flash and RAM
// as bars, and the kernel's and the app's shares of them, as text or as
// --json on standard output.
#pragma once

#include <string>
#include <vector>

#include "../attribution.hpp"
#include "build.hpp"

namespace openswarm {

// The image's memory and shares as text; why: why shares is empty.
void print_build_summary(const BuildResult &r, const std::vector<Share> &shares, const std::string &why);
// The same as one line of JSON.
void print_build_json(const BuildResult &r, const std::vector<Share> &shares, const std::string &why);
// A failed build --json: its errors as JSON on standard output.
void print_build_json_failure();

}  // namespace openswarm
