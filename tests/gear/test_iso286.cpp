// Tests for gearkit/gear/iso286.hpp.
#include <gearkit/gear/iso286.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace gg = gearkit::gear;

// ISO 286-1:2010 Table 1 (reproduced e.g. in Wikipedia "IT Grade"); ranges include their upper limit.
TEST(Iso286, TabulatedValues) {
  EXPECT_DOUBLE_EQ(gg::standard_tolerance(6, 3.0), 6.0);
  EXPECT_DOUBLE_EQ(gg::standard_tolerance(7, 50.0), 25.0);    // over 30 up to 50
  EXPECT_DOUBLE_EQ(gg::standard_tolerance(7, 50.01), 30.0);   // over 50 up to 80
  EXPECT_DOUBLE_EQ(gg::standard_tolerance(8, 150.0), 63.0);
  EXPECT_DOUBLE_EQ(gg::standard_tolerance(9, 200.0), 115.0);
  EXPECT_DOUBLE_EQ(gg::standard_tolerance(5, 400.0), 25.0);
  EXPECT_DOUBLE_EQ(gg::standard_tolerance(10, 90.0), 140.0);
  EXPECT_DOUBLE_EQ(gg::standard_tolerance(7, 700.0), 80.0);
  EXPECT_DOUBLE_EQ(gg::standard_tolerance(11, 3150.0), 1350.0);
  EXPECT_DOUBLE_EQ(gg::js_limit_deviation(8, 150.0), 0.0315);
}

// Cross-check of the table against the rule it was built from (ISO 286-1 Annex A): IT = k i with
// i = 0.45 D^(1/3) + 0.001 D up to 500 mm and i = 0.004 D + 2.1 above, D the geometric mean of the
// range, k = 7, 10, 16, 25, 40, 64, 100 for IT5..IT11. The tabulated values are rounded, within 10 %
// (the first range, up to 3 mm, is rounded up further by the standard and is left out).
TEST(Iso286, TableFollowsTheStandardToleranceFactor) {
  const double upper[] = {6, 10, 18, 30, 50, 80, 120, 180, 250, 315, 400, 500, 630, 800, 1000, 1250, 1600, 2000, 2500, 3150};
  const double lower[] = {3, 6, 10, 18, 30, 50, 80, 120, 180, 250, 315, 400, 500, 630, 800, 1000, 1250, 1600, 2000, 2500};
  const double k[] = {7, 10, 16, 25, 40, 64, 100};
  for (int j = 0; j < 20; ++j) {
    const double D = std::sqrt(lower[j] * upper[j]);
    const double i = upper[j] <= 500 ? 0.45 * std::cbrt(D) + 0.001 * D : 0.004 * D + 2.1;
    for (int it = upper[j] <= 500 ? 5 : 6; it <= 11; ++it) {
      const double table = gg::standard_tolerance(it, upper[j]);
      EXPECT_NEAR(table / (k[it - 5] * i), 1.0, 0.10) << "IT" << it << " up to " << upper[j];
    }
  }
}

TEST(Iso286, OutsideTheTableIsAnError) {
  EXPECT_THROW(gg::standard_tolerance(7, 0.0), std::domain_error);
  EXPECT_THROW(gg::standard_tolerance(7, 3200.0), std::domain_error);
  EXPECT_THROW(gg::standard_tolerance(4, 100.0), std::domain_error);
  EXPECT_THROW(gg::standard_tolerance(12, 100.0), std::domain_error);
  EXPECT_THROW(gg::standard_tolerance(5, 600.0), std::domain_error);
}
