// Welch's t test and Cohen's d (cli/src/sweep/group_comparison.cpp), the
// comparison a two-point sweep prints: t, its degrees of freedom and d
// worked out by hand, p against Student's t tables.
#include <gtest/gtest.h>

#include <vector>

#include "../../cli/src/sweep/group_comparison.hpp"

namespace {

using openswarm::compare_groups;
using openswarm::student_quantile;
using openswarm::student_two_sided_p;

TEST(GroupComparison, PValuesMatchStudentsTables) {
    // The tables' 0.975 quantiles: each leaves 5% in the two tails.
    EXPECT_NEAR(student_two_sided_p(12.706, 1), 0.05, 1e-4);
    EXPECT_NEAR(student_two_sided_p(2.228, 10), 0.05, 1e-4);
    EXPECT_NEAR(student_two_sided_p(-2.042, 30), 0.05, 1e-4);
    EXPECT_NEAR(student_two_sided_p(1.96, 1e6), 0.05, 1e-4);
    EXPECT_NEAR(student_two_sided_p(2.576, 1e6), 0.01, 1e-4);
    EXPECT_DOUBLE_EQ(student_two_sided_p(0, 5), 1.0);
}

TEST(GroupComparison, WelchsTestByHand) {
    // Means 3 and 6, variances 2.5 and 10: t = -3 / sqrt(0.5 + 2) = -1.897,
    // df = 2.5^2 / (0.5^2 / 4 + 2^2 / 4) = 5.882, d = -3 / sqrt(6.25) = -1.2.
    auto c = compare_groups({1, 2, 3, 4, 5}, {2, 4, 6, 8, 10});
    ASSERT_TRUE(c.valid);
    EXPECT_NEAR(c.t, -1.8974, 1e-4);
    EXPECT_NEAR(c.degrees, 5.8824, 1e-4);
    EXPECT_NEAR(c.d, -1.2, 1e-12);
    EXPECT_GT(c.p, 0.10);
    EXPECT_LT(c.p, 0.115) << "between df 5's 0.115 and df 6's 0.105 at this t";
}

TEST(GroupComparison, QuantilesMatchStudentsTables) {
    EXPECT_NEAR(student_quantile(0.025, 10), 2.228, 1e-3);
    EXPECT_NEAR(student_quantile(0.2, 10), 0.879, 1e-3);
    EXPECT_NEAR(student_quantile(0.025, 1), 12.706, 1e-3);
    EXPECT_NEAR(student_quantile(0.025, 1e6), 1.960, 1e-3);
    EXPECT_NEAR(student_quantile(0.2, 1e6), 0.842, 1e-3);
}

TEST(GroupComparison, DetectableDifferenceByHand) {
    // 0..10 and 3..13: variances 11 each, so standard error sqrt(11/11 +
    // 11/11) = 1.4142 and df = 20 exactly; t(0.975) = 2.086 and t(0.8) =
    // 0.860 at 20 (the tables): 2.946 x 1.4142 = 4.166.
    std::vector<double> a, b;
    for (int k = 0; k <= 10; k++) {
        a.push_back(k);
        b.push_back(k + 3);
    }
    auto c = compare_groups(a, b);
    ASSERT_TRUE(c.valid);
    EXPECT_NEAR(c.degrees, 20, 1e-9);
    EXPECT_NEAR(c.detectable, 4.166, 2e-3);
}

TEST(GroupComparison, TooFewOrNoSpreadIsNotATest) {
    EXPECT_FALSE(compare_groups({1}, {2, 3}).valid);
    EXPECT_FALSE(compare_groups({1, 1, 1}, {1, 1}).valid);
}

}  // namespace
