// Tests for gearkit/gear/cylindrical_gear.hpp.
#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/involute.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gg = gearkit::gear;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kAlpha = 20.0 * kDeg;
}  // namespace

TEST(CylindricalGear, HelicalTransverseQuantities) {
  // ISO 21771 example spreadsheet (scribd "Gear Generating Profile Shift Calculations",
  // "According to ISO 21771:2007"): m_n = 3.5, alpha_n = 20 deg, beta = 21 deg, z = 31 + 30:
  // alpha_t = 21.2990642859 deg, reference centre distance 114.3447280708 mm.
  const double beta = 21.0 * kDeg;
  const double alpha_t = gg::transverse_pressure_angle(kAlpha, beta);
  EXPECT_NEAR(alpha_t / kDeg, 21.2990642859, 1e-9);
  EXPECT_NEAR(0.5 * (gg::reference_diameter(31, 3.5, beta) + gg::reference_diameter(30, 3.5, beta)), 114.3447280708, 1e-9);
  EXPECT_NEAR(gg::normal_pressure_angle(alpha_t, beta), kAlpha, 1e-15);
  EXPECT_NEAR(gg::transverse_module(3.5, beta), 3.5 / std::cos(beta), 1e-15);
  // Identity cos(beta_b) cos(alpha_t) = cos(beta) cos(alpha_n) (ISO 21771 eq. for beta_b).
  EXPECT_NEAR(std::cos(gg::base_helix_angle(beta, kAlpha)) * std::cos(alpha_t), std::cos(beta) * std::cos(kAlpha), 1e-15);
}

TEST(CylindricalGear, DiametersOfTheKhkExample) {
  // bolsover.com (KHK example): m = 3, z = 12/24, x = 0.6/0.36, alpha = 20 deg:
  // d_b = 33.8289 / 67.6579, d_f = 32.100 / 66.660.
  const double d1 = gg::reference_diameter(12, 3.0, 0.0), d2 = gg::reference_diameter(24, 3.0, 0.0);
  EXPECT_DOUBLE_EQ(d1, 36.0);
  EXPECT_NEAR(gg::base_diameter(d1, kAlpha), 33.8289, 5e-5);
  EXPECT_NEAR(gg::base_diameter(d2, kAlpha), 67.6579, 5e-5);
  EXPECT_NEAR(gg::root_diameter(d1, 3.0, 1.25, 0.6), 32.100, 1e-12);
  EXPECT_NEAR(gg::root_diameter(d2, 3.0, 1.25, 0.36), 66.660, 1e-12);
  // OTM 2015 problem 3: r_c = r + m (1 + x), r_f = r - m (1.25 - x).
  EXPECT_NEAR(0.5 * gg::tip_diameter(90.0, 9.0, 1.0, 4.0 / 17.0, 0.0), 45.0 + 9.0 * (1.0 + 4.0 / 17.0), 1e-12);
}

TEST(CylindricalGear, InternalGearSignConvention) {
  // KHK/SDP internal gear formulas (x_KHK = -x_ISO): d_a2 = d2 - 2 (1 - x_KHK) m,
  // d_f2 = d2 + 2 (1.25 + x_KHK) m, s2 = pi m / 2 - 2 x_KHK m tan alpha (adams.thisaray.com
  // "Standard involute profile", internal gear). z2 = 96, m = 14, x_KHK = 0.5.
  const double d2 = gg::reference_diameter(-96, 14.0, 0.0);
  EXPECT_DOUBLE_EQ(d2, -1344.0);
  EXPECT_NEAR(-gg::tip_diameter(d2, 14.0, 1.0, -0.5, 0.0), 1344.0 - 2.0 * (1.0 - 0.5) * 14.0, 1e-12);
  EXPECT_NEAR(-gg::root_diameter(d2, 14.0, 1.25, -0.5), 1344.0 + 2.0 * (1.25 + 0.5) * 14.0, 1e-12);
  EXPECT_NEAR(gg::reference_tooth_thickness(14.0, -0.5, kAlpha), std::numbers::pi * 14.0 / 2.0 - 2.0 * 0.5 * 14.0 * std::tan(kAlpha), 1e-12);
}

TEST(CylindricalGear, ToothThickness) {
  // SDP/SI "Elements of Metric Gear Technology" Table 10-1: m = 10, z = 12, x = +0.3 -> s = 17.8918.
  EXPECT_NEAR(gg::reference_tooth_thickness(10.0, 0.3, kAlpha), 17.8918, 5e-5);
  // OTM 2015 problem 3: s = p/2 + 2 m x tan(alpha) = 15.68 for m = 9, x = 4/17.
  EXPECT_NEAR(gg::reference_tooth_thickness(9.0, 4.0 / 17.0, kAlpha), 15.68, 5e-3);
  // At the reference circle the thickness is s itself; at the base circle s_b = d_b (s/d + inv alpha)
  // (hand derivation: inv(0) = 0).
  const double d = 120.0, d_b = d * std::cos(kAlpha), s = 9.0;
  EXPECT_NEAR(gg::tooth_thickness_at(s, d, d_b, kAlpha, d), s, 1e-12);
  EXPECT_NEAR(gg::tooth_thickness_at(s, d, d_b, kAlpha, d_b), d_b * (s / d + gg::involute(kAlpha)), 1e-12);
  EXPECT_THROW(gg::tooth_thickness_at(s, d, d_b, kAlpha, d_b - 1.0), std::domain_error);
}

TEST(CylindricalGear, UndercutLimit) {
  // Textbook limit for a sharp-cornered rack, h* = 1: x_min = 1 - z sin^2(alpha)/2, z_min = 17.1.
  gg::Rack sharp;
  sharp.h_fP = 1.0;
  sharp.rho_fP = 0.0;
  EXPECT_NEAR(gg::min_shift_no_undercut(10, 0.0, sharp), 1.0 - 10.0 * std::pow(std::sin(kAlpha), 2) / 2.0, 1e-14);
  EXPECT_NEAR(gg::min_shift_no_undercut(17, 0.0, sharp), 0.0056, 1e-4);
  // ISO 53 A: h_fP - rho_fP (1 - sin alpha) = 0.99996, practically the same limit.
  EXPECT_NEAR(gg::min_shift_no_undercut(10, 0.0, gg::Rack{}), 0.4151, 1e-4);
  // Cross-check with the form roll length: it vanishes exactly at x_min.
  for (int z : {8, 12, 17, 30}) {
    const double x = gg::min_shift_no_undercut(z, 0.0, gg::Rack{});
    EXPECT_NEAR(gg::form_roll_length(z, 3.0, 0.0, x, gg::Rack{}), 0.0, 1e-12) << z;
    EXPECT_GT(gg::form_roll_length(z, 3.0, 0.0, x + 0.1, gg::Rack{}), 0.0);
    // The overloads from d, d_b and alpha_t give the same numbers.
    EXPECT_NEAR(gg::min_shift_no_undercut(z * 3.0, 3.0, kAlpha, gg::Rack{}), x, 1e-14);
    EXPECT_NEAR(gg::form_roll_length(z * 3.0 * std::cos(kAlpha), kAlpha, 3.0, x + 0.1, gg::Rack{}),
                gg::form_roll_length(z, 3.0, 0.0, x + 0.1, gg::Rack{}), 1e-12);
  }
}

TEST(CylindricalGear, PracticalUndercutLimit) {
  // OTM 2015 problem 3 (seed 000_bc94d104a9983772.txt), solution table: x = (14 - Z)/17 at 20 deg.
  for (int z : {5, 10, 14, 17, 40}) EXPECT_NEAR(gg::practical_min_shift(z, gg::Rack{}), (14.0 - z) / 17.0, 1e-15) << z;
  // The rule behind it (Niemann, Maschinenelemente II; DIN 3960): z_g = 2 h_aP / sin^2(alpha)
  // and z'_g = 5/6 z_g, to whole teeth: 15 deg gives 29.86 -> 30 and 25, so (25 - z)/30.
  gg::Rack r15;
  r15.alpha_P = 15.0 * kDeg;
  EXPECT_NEAR(gg::practical_min_shift(12, r15), (25.0 - 12.0) / 30.0, 1e-15);
  // Below ISO's no-undercut limit by about (z_g - z'_g)/z_g (a slight undercut accepted).
  EXPECT_LT(gg::practical_min_shift(10, gg::Rack{}), gg::min_shift_no_undercut(10, 0.0, gg::Rack{}));
}

TEST(CylindricalGear, VirtualNumberOfTeeth) {
  // ISO 21771: z_n = z / (cos^2 beta_b cos beta); equals z for spur gears. By hand for z = 16,
  // beta = 25 deg: sin beta_b = sin 25 cos 20 = 0.397131, z_n = 16 / (0.842287 * 0.906308) = 20.9597.
  EXPECT_DOUBLE_EQ(gg::virtual_number_of_teeth(20, 0.0, kAlpha), 20.0);
  EXPECT_NEAR(gg::virtual_number_of_teeth(16, 25.0 * kDeg, kAlpha), 20.9597, 1e-4);
}
