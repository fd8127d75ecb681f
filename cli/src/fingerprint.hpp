// A short fingerprint of bytes: enough to tell two builds, two worlds or
// two parameter sets apart (not a cryptographic hash).
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

namespace openswarm {

// FNV-1a, 64 bits, as 16 hex digits.
inline std::string fingerprint(const std::string &bytes) {
    uint64_t h = 0xcbf29ce484222325ull;
    for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ull;
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", (unsigned long long)h);
    return text;
}

}  // namespace openswarm
