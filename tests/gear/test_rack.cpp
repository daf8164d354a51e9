// Tests for gearkit/gear/rack.hpp.
#include <gearkit/gear/rack.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gg = gearkit::gear;

TEST(Rack, Iso53ProfileADefaults) {
  // ISO 53:1998 profile A: alpha_P = 20 deg, h_aP = 1 m, h_fP = 1.25 m, rho_fP = 0.38 m.
  const gg::Rack r;
  EXPECT_DOUBLE_EQ(r.alpha_P, 20.0 * std::numbers::pi / 180.0);
  EXPECT_DOUBLE_EQ(r.h_aP, 1.0);
  EXPECT_DOUBLE_EQ(r.h_fP, 1.25);
  EXPECT_DOUBLE_EQ(r.rho_fP, 0.38);
  // Bottom clearance c_P = 0.25 m (OTM 2015 problem 3 solution: c = 0.25 m = 2.25 mm for m = 9).
  EXPECT_DOUBLE_EQ(gg::clearance_coefficient(r), 0.25);
  EXPECT_NO_THROW(gg::validate(r));
}

TEST(Rack, FullRadiusTipLimit) {
  // Hand derivation: the tip rounding touches both flanks at the tooth centre line when
  // pi/4 - (h_fP - rho) tan a - rho / cos a = 0; for ISO 53 proportions
  // rho_max = (0.785398 - 0.454963) / (1.064178 - 0.363970) = 0.47191.
  const gg::Rack r;
  const double rho = gg::max_fillet_radius_coefficient(r);
  const double a = r.alpha_P;
  EXPECT_NEAR(std::numbers::pi / 4 - (r.h_fP - rho) * std::tan(a) - rho / std::cos(a), 0.0, 1e-14);
  EXPECT_NEAR(rho, 0.47191, 1e-5);
}

TEST(Rack, ValidateRejectsImpossibleTools) {
  gg::Rack r;
  r.alpha_P = 0.0;
  EXPECT_THROW(gg::validate(r), std::invalid_argument);
  r = gg::Rack{};
  r.h_fP = 0.9;  // dedendum below addendum
  EXPECT_THROW(gg::validate(r), std::invalid_argument);
  r = gg::Rack{};
  r.rho_fP = 0.6;
  EXPECT_THROW(gg::validate(r), std::invalid_argument);
}
