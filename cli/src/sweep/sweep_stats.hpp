// What a sweep's trials at one point say together: mean, standard
// deviation, and a 95% confidence interval for the mean (Student's t,
// the trials taken as independent draws).
#pragma once

#include <cstddef>
#include <vector>

namespace openswarm {

struct Summary {
    size_t n = 0;
    double mean = 0, sd = 0;     // sd: n - 1 in the denominator; 0 for one value
    double low = 0, high = 0;    // the 95% interval; the mean itself for one value
};

Summary summarise(const std::vector<double> &values);

// t's 0.975 quantile for this many degrees of freedom (1.96 past 1000).
double student_t975(size_t degrees);

}  // namespace openswarm
