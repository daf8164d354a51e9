// Tests for gearkit/gear/din3967.hpp.
#include <gearkit/gear/din3967.hpp>

#include <gtest/gtest.h>

#include <stdexcept>

namespace gg = gearkit::gear;

// DIN 3967:1978 clause 3.1, the standard's own example: designation 27cd at d = 100 mm gives
// A_sne = -70 um (Table 1) and T_sn = 100 um (Table 2), A_sni = -170 um.
TEST(Din3967, TheStandardsExample27cd) {
  const auto a = gg::din3967_allowances(gg::parse_din3967("27cd"), 100.0);
  EXPECT_NEAR(a.A_sne, -0.070, 1e-12);
  EXPECT_NEAR(a.A_sni, -0.170, 1e-12);
}

// Table entries at the range limits ("over ... up to"): a at 10 mm is the first row, above it the
// second; the table's corners; series h is zero everywhere (DIN 3967 Tables 1 and 2, as transcribed
// in a public gear-geometry service pinned to the example above).
TEST(Din3967, RangeLimitsAndCorners) {
  EXPECT_NEAR(gg::din3967_upper_allowance("a", 10.0), -0.100, 1e-12);
  EXPECT_NEAR(gg::din3967_upper_allowance("a", 10.001), -0.135, 1e-12);
  EXPECT_NEAR(gg::din3967_upper_allowance("cd", 50.0), -0.054, 1e-12);
  EXPECT_NEAR(gg::din3967_upper_allowance("a", 10000.0), -2.000, 1e-12);
  EXPECT_NEAR(gg::din3967_thickness_tolerance(21, 5.0), 0.003, 1e-12);
  EXPECT_NEAR(gg::din3967_thickness_tolerance(30, 10000.0), 2.400, 1e-12);
  for (double d : {5.0, 100.0, 9000.0}) EXPECT_EQ(gg::din3967_upper_allowance("h", d), 0.0);
  EXPECT_NEAR(gg::din3967_upper_allowance("cd", -82.0), -0.070, 1e-12);  // ring: |d|
}

// The series are ordered: each deviation series is tighter than the one before it, each tolerance
// series wider than the one before, in every diameter range.
TEST(Din3967, SeriesAreMonotonic) {
  const char* series[] = {"a", "ab", "b", "bc", "c", "cd", "d", "e", "f", "g", "h"};
  for (double d : {5.0, 30.0, 100.0, 200.0, 400.0, 800.0, 1200.0, 2000.0, 3000.0, 5000.0, 8000.0}) {
    for (int i = 1; i < 11; ++i) EXPECT_GT(gg::din3967_upper_allowance(series[i], d), gg::din3967_upper_allowance(series[i - 1], d));
    for (int t = 22; t <= 30; ++t) EXPECT_GT(gg::din3967_thickness_tolerance(t, d), gg::din3967_thickness_tolerance(t - 1, d));
  }
}

TEST(Din3967, BadDesignations) {
  EXPECT_THROW(gg::parse_din3967("27x"), std::invalid_argument);   // no such deviation series
  EXPECT_THROW(gg::parse_din3967("20cd"), std::invalid_argument);  // tolerance series 21..30
  EXPECT_THROW(gg::parse_din3967("cd27"), std::invalid_argument);
  EXPECT_THROW(gg::parse_din3967("27"), std::invalid_argument);
  EXPECT_THROW(gg::parse_din3967(""), std::invalid_argument);
  EXPECT_THROW(gg::din3967_upper_allowance("cd", 20000.0), std::domain_error);
  EXPECT_EQ(gg::parse_din3967("25e").tolerance_series, 25);
  EXPECT_EQ(gg::parse_din3967("25e").deviation_series, "e");
}
