// Tests for gearkit/gear/thickness_tolerance.hpp.
#include <gearkit/gear/thickness_tolerance.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gg = gearkit::gear;

namespace {
constexpr double kAlpha = 20.0 * std::numbers::pi / 180.0;
}

// ISO/TR 10064-2 minimum backlash for industrial drives, by hand: a = 100 mm, m_n = 2 mm:
// 2/3 (0.06 + 0.05 + 0.06) = 0.11333 mm; a = 400 mm, m_n = 8 mm: 2/3 (0.06 + 0.2 + 0.24) = 0.3333 mm.
TEST(ThicknessTolerance, RecommendedMinimumBacklash) {
  EXPECT_NEAR(gg::recommended_min_backlash(100, 2), 0.113333, 1e-6);
  EXPECT_NEAR(gg::recommended_min_backlash(-400, 8), 0.333333, 1e-6);  // internal pairs: |a|
}

// Published worked tolerance sheet (qiqiwenku.com "齿轮公差计算", m_n = 3 mm, alpha_n = 20 deg):
// F_r = 63 um, b_r = 145 um -> T_s = 2 tan(alpha_n) sqrt(F_r^2 + b_r^2) = 115.1 um; with E_ss = -88 um,
// E_si = -176 um the span allowances E_wms = E_ss cos(alpha_n) - 0.72 F_r sin(alpha_n) = -98.207 um
// and E_wmi = E_si cos(alpha_n) + 0.72 F_r sin(alpha_n) = -149.872 um (DIN 3967 Appendix B form).
TEST(ThicknessTolerance, PublishedToleranceSheet) {
  EXPECT_NEAR(gg::tooth_thickness_tolerance(63, 145, kAlpha), 115.1, 0.05);
  const auto m = gg::measurement_allowances({-0.088, -0.176}, 0.063, kAlpha);
  EXPECT_NEAR(gg::span_allowance(m.A_sne, kAlpha), -0.0982070, 1e-6);
  EXPECT_NEAR(gg::span_allowance(m.A_sni, kAlpha), -0.1498719, 1e-6);
  // Its b_r = 145 um is 1.26 IT9 of a wheel between 180 and 250 mm (IT9 = 115 um), the grade 8 entry.
  EXPECT_NEAR(gg::radial_infeed_tolerance(8, 212), 144.9, 1e-9);
}

// The b_r table: 4: 1.26 IT7, 5: IT8, 6: 1.26 IT8, 7: IT9, 8: 1.26 IT9, 9: IT10, at d = 100 mm
// (IT7..IT10 = 35, 54, 87, 140 um, ISO 286-1 Table 1).
TEST(ThicknessTolerance, RadialInfeedTable) {
  EXPECT_NEAR(gg::radial_infeed_tolerance(4, 100), 1.26 * 35, 1e-9);
  EXPECT_NEAR(gg::radial_infeed_tolerance(5, 100), 54, 1e-9);
  EXPECT_NEAR(gg::radial_infeed_tolerance(6, 100), 1.26 * 54, 1e-9);
  EXPECT_NEAR(gg::radial_infeed_tolerance(7, 100), 87, 1e-9);
  EXPECT_NEAR(gg::radial_infeed_tolerance(8, 100), 1.26 * 87, 1e-9);
  EXPECT_NEAR(gg::radial_infeed_tolerance(9, 100), 140, 1e-9);
  for (int q = 0; q < 12; ++q) EXPECT_LT(gg::radial_infeed_tolerance(q, 100), gg::radial_infeed_tolerance(q + 1, 100));
  EXPECT_THROW(gg::radial_infeed_tolerance(-1, 100), std::domain_error);
  EXPECT_THROW(gg::radial_infeed_tolerance(13, 100), std::domain_error);
}

// Grade 0 exists in ISO 1328-1:1995 (0..12): the rule continued one 1.26 step below grade 1 = IT6
// (IT6 = 22 um at d = 100 mm, ISO 286-1 Table 1): 22 / 1.26 = 17.46 um; it used to be rejected.
TEST(ThicknessTolerance, RadialInfeedOfGradeZero) {
  EXPECT_NEAR(gg::radial_infeed_tolerance(0, 100), 22.0 / 1.26, 1e-9);
  EXPECT_NEAR(gg::radial_infeed_tolerance(0, 800) * 1.26, gg::radial_infeed_tolerance(1, 800), 1e-9);  // above 500 mm too
}
