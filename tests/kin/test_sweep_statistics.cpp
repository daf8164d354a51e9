// SweepStatistics: extremes with where they occur, the peak magnitude and the RMS over the input
// against closed forms.
#include <gearkit/kin/sweep_statistics.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gearkit::kin {
namespace {

constexpr double pi = std::numbers::pi;

// RMS of A cos(x) + B over a full period: sqrt(B^2 + A^2 / 2) (the mean of cos^2 is 1/2). The
// trapezoidal rule is exact for a trigonometric polynomial of degree below the number of
// intervals over a whole period, so 360 steps give it to round-off.
TEST(SweepStatistics, RmsOfAShiftedCosineOverAPeriod) {
  SweepStatistics s;
  const double A = 3.0, B = 1.5;
  for (int k = 0; k <= 360; ++k) s.add(2 * pi * k / 360, A * std::cos(2 * pi * k / 360) + B);
  EXPECT_NEAR(s.rms(), std::sqrt(B * B + A * A / 2), 1e-12);
  EXPECT_NEAR(s.max().value, A + B, 1e-12);
  EXPECT_NEAR(s.max().input, 0.0, 1e-12);  // the first of the two equal maxima (0 and 2 pi)
  EXPECT_NEAR(s.min().value, B - A, 1e-12);
  EXPECT_NEAR(s.min().input, pi, 1e-12);
  EXPECT_NEAR(s.peak().value, A + B, 1e-12);
  EXPECT_EQ(s.count(), 361u);
}

// RMS of v = x over [0, 1]: sqrt(1/3); the trapezoidal rule on h = 1/1000 errs by h^2/12 of the
// integral of (x^2)'' = 2, i.e. 1/6e6 in the mean square.
TEST(SweepStatistics, RmsOfARampTakesTheTrapezoidalError) {
  SweepStatistics s;
  for (int k = 0; k <= 1000; ++k) s.add(k / 1000.0, k / 1000.0);
  EXPECT_NEAR(s.rms() * s.rms(), 1.0 / 3.0 + 1.0 / 6e6, 1e-12);
}

// A decreasing input (a sweep from 360 to 0) covers the same range; the peak keeps its sign.
TEST(SweepStatistics, DecreasingInputAndNegativePeak) {
  SweepStatistics s;
  for (int k = 10; k >= 0; --k) s.add(k, -static_cast<double>(k * k));
  EXPECT_EQ(s.peak().value, -100.0);
  EXPECT_EQ(s.peak().input, 10.0);
  // The integral of x^4 over [0, 10] is 20000; the trapezoidal rule (h = 1) adds the
  // Euler-Maclaurin terms h^2/12 (f'(10) - f'(0)) - h^4/720 (f'''(10) - f'''(0)) = 4000/12 -
  // 240/720 exactly (f^(5) = 0): 20333 = the sum of k^4 less half the end values.
  EXPECT_NEAR(s.rms() * s.rms(), (20000.0 + 4000.0 / 12 - 240.0 / 720) / 10, 1e-9);
}

// Non-finite values are left out and break the integral: the gap's width is not covered.
TEST(SweepStatistics, NonFiniteValuesAreSkipped) {
  SweepStatistics s;
  s.add(0, 2);
  s.add(1, 2);
  s.add(2, std::numeric_limits<double>::infinity());
  s.add(3, 4);
  s.add(4, 4);
  EXPECT_EQ(s.count(), 4u);
  EXPECT_NEAR(s.rms(), std::sqrt((4.0 + 16.0) / 2), 1e-12);  // [0,1] at 2 and [3,4] at 4
  EXPECT_EQ(s.max().input, 3.0);
  SweepStatistics empty;
  EXPECT_TRUE(std::isnan(empty.rms()));
  SweepStatistics one;
  one.add(5, -3);
  EXPECT_EQ(one.rms(), 3.0);
}

}  // namespace
}  // namespace gearkit::kin
