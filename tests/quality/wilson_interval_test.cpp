// The Wilson score interval behind P(held) (core/wilson_interval.h).
#include <gtest/gtest.h>

#include <stdexcept>

#include "cordgrasp/core/wilson_interval.h"

namespace cordgrasp {
namespace {

/// Newcombe's tables give four decimals.
constexpr double kTableTol = 5e-5;
constexpr double kExactTol = 1e-12;

TEST(WilsonInterval, MatchesNewcombesPublishedValues) {
  // R. G. Newcombe, "Two-sided confidence intervals for the single proportion: comparison of
  // seven methods", Statistics in Medicine 17 (1998), Table II, method 3 (score, no correction).
  struct Case {
    int k, n;
    double low, high;
  };
  for (const Case c : {Case{81, 263, 0.2553, 0.3662}, Case{15, 148, 0.0624, 0.1605},
                       Case{0, 20, 0.0, 0.1611}, Case{1, 29, 0.0061, 0.1718}}) {
    const ProportionInterval i = wilson_interval(c.k, c.n);
    EXPECT_NEAR(i.low, c.low, kTableTol) << c.k << " / " << c.n;
    EXPECT_NEAR(i.high, c.high, kTableTol) << c.k << " / " << c.n;
    EXPECT_DOUBLE_EQ(i.p, static_cast<double>(c.k) / c.n);
  }
}

TEST(WilsonInterval, AllHeldIsExactlyOneAboveAndNeedsSixteenDrawsToClearEightyPercent) {
  // n / (n + z²) is the lower end of n of n: above 0.8 from n = 16 on.
  const ProportionInterval fifteen = wilson_interval(15, 15), sixteen = wilson_interval(16, 16);
  EXPECT_DOUBLE_EQ(sixteen.high, 1.0);
  EXPECT_NEAR(sixteen.low, 16.0 / (16.0 + kZ95 * kZ95), kExactTol);
  EXPECT_LT(fifteen.low, 0.8);
  EXPECT_GT(sixteen.low, 0.8);
}

TEST(WilsonInterval, FailuresMirrorSuccesses) {
  for (int n = 1; n <= 30; ++n)
    for (int k = 0; k <= n; ++k) {
      const ProportionInterval a = wilson_interval(k, n), b = wilson_interval(n - k, n);
      EXPECT_NEAR(a.low, 1.0 - b.high, kExactTol);
      EXPECT_NEAR(a.high, 1.0 - b.low, kExactTol);
      EXPECT_LE(a.low, a.p);
      EXPECT_GE(a.high, a.p);
    }
}

TEST(WilsonInterval, NoTrialsGiveTheWholeRangeAndBadCountsThrow) {
  const ProportionInterval none = wilson_interval(0, 0);
  EXPECT_EQ(none.low, 0.0);
  EXPECT_EQ(none.high, 1.0);
  EXPECT_THROW(wilson_interval(3, 2), std::invalid_argument);
  EXPECT_THROW(wilson_interval(-1, 2), std::invalid_argument);
  EXPECT_THROW(wilson_interval(1, 2, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace cordgrasp
