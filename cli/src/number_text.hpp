// A number as the CSV files and the simulator's options take it: six
// significant digits, no trailing zeros ("%g").
#pragma once

#include <cstdio>
#include <string>

namespace openswarm {

inline std::string number_text(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

}  // namespace openswarm
