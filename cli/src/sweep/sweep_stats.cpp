#include "sweep_stats.hpp"

#include <cmath>

namespace openswarm {

double student_t975(size_t degrees) {
    // The 0.975 quantile of Student's t for 1..30 degrees of freedom, then
    // a few further points to interpolate between in 1/df.
    static const double first[30] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                     2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                     2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
    static const struct { double df, t; } further[] = {{30, 2.042}, {40, 2.021}, {60, 2.000},
                                                       {120, 1.980}, {1000, 1.962}};
    if (degrees == 0) return NAN;
    if (degrees <= 30) return first[degrees - 1];
    for (size_t k = 1; k < sizeof further / sizeof further[0]; k++)
        if (degrees <= further[k].df) {
            double a = 1 / further[k - 1].df, b = 1 / further[k].df, x = 1 / (double)degrees;
            return further[k - 1].t + (further[k].t - further[k - 1].t) * (x - a) / (b - a);
        }
    return 1.96;
}

Summary summarise(const std::vector<double> &values) {
    Summary s;
    s.n = values.size();
    if (s.n == 0) return s;
    double sum = 0;
    for (double v : values) sum += v;
    s.mean = sum / (double)s.n;
    s.low = s.high = s.mean;
    if (s.n < 2) return s;
    double squares = 0;
    for (double v : values) squares += (v - s.mean) * (v - s.mean);
    s.sd = std::sqrt(squares / (double)(s.n - 1));
    double half = student_t975(s.n - 1) * s.sd / std::sqrt((double)s.n);
    s.low = s.mean - half;
    s.high = s.mean + half;
    return s;
}

}  // namespace openswarm
