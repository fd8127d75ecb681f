// Reading an Intel HEX file (what avr-objcopy -O ihex writes) into the
// flash bytes it describes: what `openswarm upload` sends to a Kilobot.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace openswarm {

// A malformed file: "FILE:LINE: what is wrong; the fix".
struct HexError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Flash from address 0 to the last byte the file sets; bytes it leaves
// unset are 0xFF, as erased flash reads. Checks every record's checksum.
std::vector<uint8_t> read_intel_hex(const std::filesystem::path &file);

}  // namespace openswarm
