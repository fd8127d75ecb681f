#include "group_comparison.hpp"

#include <cmath>

namespace openswarm {

namespace {

// The continued fraction of the regularised incomplete beta function
// (modified Lentz's method); converges fast for x < (a + 1) / (a + b + 2).
double beta_fraction(double a, double b, double x) {
    const double tiny = 1e-300;
    double c = 1, d = 1 - (a + b) * x / (a + 1);
    d = 1 / (std::fabs(d) < tiny ? tiny : d);
    double h = d;
    for (int m = 1; m <= 300; m++) {
        for (int odd = 0; odd < 2; odd++) {
            double numerator = odd ? -(a + m) * (a + b + m) * x / ((a + 2 * m) * (a + 2 * m + 1))
                                   : m * (b - m) * x / ((a + 2 * m - 1) * (a + 2 * m));
            d = 1 + numerator * d;
            d = 1 / (std::fabs(d) < tiny ? tiny : d);
            c = 1 + numerator / c;
            if (std::fabs(c) < tiny) c = tiny;
            h *= c * d;
        }
        if (std::fabs(c * d - 1) < 1e-15) break;
    }
    return h;
}

// I_x(a, b), the regularised incomplete beta function.
double incomplete_beta(double a, double b, double x) {
    if (x <= 0) return 0;
    if (x >= 1) return 1;
    double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) +
                            b * std::log1p(-x));
    if (x < (a + 1) / (a + b + 2)) return front * beta_fraction(a, b, x) / a;
    return 1 - front * beta_fraction(b, a, 1 - x) / b;
}

struct Moments {
    double n, mean, variance;
};

Moments moments(const std::vector<double> &v) {
    double sum = 0, squares = 0;
    for (double x : v) sum += x;
    double n = (double)v.size(), mean = sum / n;
    for (double x : v) squares += (x - mean) * (x - mean);
    return {n, mean, n > 1 ? squares / (n - 1) : 0};
}

}  // namespace

double student_two_sided_p(double t, double degrees) {
    return incomplete_beta(degrees / 2, 0.5, degrees / (degrees + t * t));
}

double student_quantile(double upper_tail, double degrees) {
    // p falls as t grows: halve [0, high] around the t whose two tails
    // hold twice upper_tail, after doubling high until it is past it.
    double low = 0, high = 1;
    while (student_two_sided_p(high, degrees) > 2 * upper_tail && high < 1e9) high *= 2;
    for (int step = 0; step < 100; step++) {
        double middle = (low + high) / 2;
        (student_two_sided_p(middle, degrees) > 2 * upper_tail ? low : high) = middle;
    }
    return (low + high) / 2;
}

Comparison compare_groups(const std::vector<double> &a, const std::vector<double> &b) {
    Comparison c;
    if (a.size() < 2 || b.size() < 2) return c;
    Moments x = moments(a), y = moments(b);
    double va = x.variance / x.n, vb = y.variance / y.n;
    if (va + vb <= 0) return c;
    c.t = (x.mean - y.mean) / std::sqrt(va + vb);
    c.degrees = (va + vb) * (va + vb) / (va * va / (x.n - 1) + vb * vb / (y.n - 1));
    c.p = student_two_sided_p(c.t, c.degrees);
    c.d = (x.mean - y.mean) / std::sqrt((x.variance + y.variance) / 2);
    c.detectable = (student_quantile(0.025, c.degrees) + student_quantile(0.2, c.degrees)) * std::sqrt(va + vb);
    c.valid = true;
    return c;
}

}  // namespace openswarm
