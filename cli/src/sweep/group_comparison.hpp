// Whether two groups of trials differ: Welch's t test (unequal variances,
// the trials taken as independent draws) and Cohen's d. The sweep prints
// it when its grid has two points, as the case study's two controllers.
#pragma once

#include <vector>

namespace openswarm {

struct Comparison {
    double t = 0, degrees = 0; // Welch's t (a - b) and its Welch-Satterthwaite degrees of freedom
    double p = 1;              // two-sided
    double d = 0;              // Cohen's d: the difference of the means over the root mean variance
    // The difference of the means this test finds 80% of the time at alpha
    // 0.05 (two-sided), with these spreads and numbers of trials:
    // (t(0.975) + t(0.8)) standard errors, at the test's degrees of freedom.
    double detectable = 0;
    bool valid = false;        // false with fewer than 2 values a group, or no spread in either
};

Comparison compare_groups(const std::vector<double> &a, const std::vector<double> &b);

// P(|T| >= |t|) for Student's t with this many degrees of freedom (> 0).
double student_two_sided_p(double t, double degrees);

// The t that Student's t with this many degrees of freedom (> 0) exceeds
// with probability upper_tail (0 < upper_tail <= 0.5): 2.228 for 0.025 at 10.
double student_quantile(double upper_tail, double degrees);

}  // namespace openswarm
