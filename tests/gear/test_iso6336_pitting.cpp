// Tests for gearkit/gear/iso6336_pitting.hpp (ISO 6336-2:2019 formulas).
#include <gearkit/gear/iso6336_pitting.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace iso = gearkit::gear::iso6336;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}

TEST(Pitting, ZoneElasticityContactRatioHelix) {
  // Spur, x1 + x2 = 0, 20 deg: Z_H = sqrt(2 / (cos 20 sin 20)) = 2.495 (ISO 6336-2 Figure 2).
  EXPECT_NEAR(iso::zone_factor(0.0, 20.0 * kDeg, 20.0 * kDeg), 2.4946, 0.0001);
  // Steel on steel, E = 206000 MPa, nu = 0.3: Z_E = 189.8 sqrt(MPa) (ISO 6336-2 Table 4).
  EXPECT_NEAR(iso::elasticity_factor(206000, 0.3, 206000, 0.3), 189.81, 0.01);
  EXPECT_NEAR(iso::contact_ratio_factor(1.6, 0.0), std::sqrt(2.4 / 3.0), 1e-12);
  EXPECT_NEAR(iso::contact_ratio_factor(1.6, 1.2), std::sqrt(1.0 / 1.6), 1e-12);
  // eps_beta < 1 blends both: at eps_beta -> 1 it meets sqrt(1/eps_alpha).
  EXPECT_NEAR(iso::contact_ratio_factor(1.6, 1.0 - 1e-12), std::sqrt(1.0 / 1.6), 1e-9);
  EXPECT_NEAR(iso::helix_angle_factor_H(15.8 * kDeg), 1.01944, 0.00001);  // ISO/TR 6336-30 ex. 1
}

TEST(Pitting, SinglePairFactors) {
  EXPECT_DOUBLE_EQ(iso::single_pair_contact_factor(0.95, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(iso::single_pair_contact_factor(1.1, 0.0), 1.1);
  EXPECT_DOUBLE_EQ(iso::single_pair_contact_factor(1.1, 1.2), 1.0);
  EXPECT_NEAR(iso::single_pair_contact_factor(1.1, 0.5), 1.05, 1e-12);
  // A low-ratio spur pinion: M_1 > 1 (single contact below the pitch point).
  const double a_wt = 20.0 * kDeg;
  const double d_b1 = 36.0 * std::cos(a_wt), d_b2 = 108.0 * std::cos(a_wt);
  EXPECT_GT(iso::single_pair_parameter(a_wt, 40.0, d_b1, 18, 112.0, d_b2, 54, 1.6), 1.0);
}

TEST(Pitting, LubricationSpeedRoughness) {
  // ISO/TR 6336-30 ex. 1: sigma_Hlim = 1500, VG 320, v = 2.664 m/s, R_z = 6 um, rho_red from the pair.
  const double C_ZL = iso::lubricant_constant(1500.0);
  EXPECT_DOUBLE_EQ(C_ZL, 0.91);
  EXPECT_NEAR(iso::lubricant_factor(C_ZL, 320.0), 1.04739, 0.00001);
  EXPECT_NEAR(iso::velocity_factor(C_ZL, 2.664), 0.96911, 0.00001);
  EXPECT_DOUBLE_EQ(iso::lubricant_constant(800.0), 0.83);
  EXPECT_NEAR(iso::lubricant_constant(1000.0), 1000.0 / 4375.0 + 0.6357, 1e-12);
  EXPECT_DOUBLE_EQ(iso::roughness_Rz_from_Ra(1.0), 6.0);
  EXPECT_NEAR(iso::roughness_factor(3.0, 1500.0), 1.0, 1e-12);
  EXPECT_NEAR(iso::roughness_Rz10(6.0, 10.0), 6.0, 1e-12);
  EXPECT_NEAR(iso::relative_radius_of_curvature(100.0, 300.0, 20.0 * kDeg, false),
              0.5 * std::tan(20.0 * kDeg) * 100.0 * 300.0 / 400.0, 1e-12);
  EXPECT_NEAR(iso::relative_radius_of_curvature(100.0, 300.0, 20.0 * kDeg, true),
              0.5 * std::tan(20.0 * kDeg) * 100.0 * 300.0 / 200.0, 1e-12);
  EXPECT_DOUBLE_EQ(iso::work_hardening_factor(130.0), 1.2);
  EXPECT_DOUBLE_EQ(iso::work_hardening_factor(470.0), 1.0);
}

TEST(Pitting, NominalStress) {
  const double s = iso::nominal_contact_stress(2.5, 189.8, 0.9, 1.0, 10000.0, 50.0, 20.0, 3.0, false);
  EXPECT_NEAR(s, 2.5 * 189.8 * 0.9 * std::sqrt(10000.0 / 1000.0 * 4.0 / 3.0), 1e-9);
  const double s_int = iso::nominal_contact_stress(2.5, 189.8, 0.9, 1.0, 10000.0, 50.0, 20.0, 3.0, true);
  EXPECT_NEAR(s_int / s, std::sqrt(2.0 / 4.0), 1e-12);
  EXPECT_NEAR(iso::contact_stress(1.0, 1000.0, 1.0, 1.0, 1.21, 1.0, 1.0), 1100.0, 1e-9);
}
