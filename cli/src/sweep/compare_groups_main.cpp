// openswarm-compare-groups A B: the two-point sweep's comparison
// (group_comparison.cpp) for two groups of values given on the command
// line, as JSON, so that scripts which run trials of their own (the bench's
// QEMU case study) report the same test the experiment prints, not one of
// their own.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "group_comparison.hpp"

namespace {

// "0.95,0.4,0.7" -> its numbers; false (and why) on anything else.
bool parse_values(const std::string &text, std::vector<double> &values, std::string &why) {
    size_t start = 0;
    while (start <= text.size()) {
        size_t comma = text.find(',', start);
        std::string field = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        char *end = nullptr;
        errno = 0;
        double value = std::strtod(field.c_str(), &end);
        if (field.empty() || *end != '\0' || errno != 0) {
            why = "'" + field + "' is not a number";
            return false;
        }
        values.push_back(value);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return true;
}

}  // namespace

int main(int argc, char **argv) {
    const char *usage = "give two groups of comma-separated numbers, e.g. openswarm-compare-groups 0.9,0.5,0.7 0.6,0.8,0.4";
    if (argc != 3) {
        std::fprintf(stderr, "openswarm-compare-groups: %d groups given; %s\n", argc - 1, usage);
        return 2;
    }
    std::vector<double> groups[2];
    for (int g = 0; g < 2; g++) {
        std::string why;
        if (!parse_values(argv[g + 1], groups[g], why)) {
            std::fprintf(stderr, "openswarm-compare-groups: group %d: %s; %s\n", g + 1, why.c_str(), usage);
            return 2;
        }
    }
    openswarm::Comparison c = openswarm::compare_groups(groups[0], groups[1]);
    if (!c.valid) {
        std::fprintf(stderr, "openswarm-compare-groups: no test: each group needs 2 values or more, and one group "
                             "a spread; give more trials\n");
        return 1;
    }
    std::printf("{\"t\": %.17g, \"degrees\": %.17g, \"p\": %.17g, \"d\": %.17g, \"detectable\": %.17g}\n", c.t,
                c.degrees, c.p, c.d, c.detectable);
    return 0;
}
