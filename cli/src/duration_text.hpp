// A wall-clock duration for progress lines: "42 s", "3m 07s", "2h 05m".
#pragma once

#include <cstdio>
#include <string>

namespace openswarm {

inline std::string duration_text(double seconds) {
    char text[32];
    if (seconds < 60) std::snprintf(text, sizeof text, "%.0f s", seconds);
    else if (seconds < 3600) std::snprintf(text, sizeof text, "%dm %02ds", (int)seconds / 60, (int)seconds % 60);
    else std::snprintf(text, sizeof text, "%dh %02dm", (int)seconds / 3600, (int)seconds / 60 % 60);
    return text;
}

}  // namespace openswarm
