// Tests for gearkit/gear/iso6336_load.hpp (ISO 6336-1:2019 formulas).
#include <gearkit/gear/iso6336_load.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace iso = gearkit::gear::iso6336;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}

TEST(NominalLoad, TangentialLoadAndSpeed) {
  // ISO/TR 6336-30 example 1: T_1 = 9000 N m, d_1 = 141.3402 mm, n_1 = 360/min.
  EXPECT_NEAR(iso::nominal_tangential_load(9000.0, 141.3402), 127352.0, 1.0);
  EXPECT_NEAR(iso::pitch_line_speed(141.3402, 360.0), 2.664, 0.0005);
}

TEST(Stiffness, BasicRackFactorAndLoadCorrection) {
  // h_fP = 1.4 m_n (ISO 53 D) at 20 deg: C_B = 1 + 0.5 (1.2 - 1.4) = 0.9 (ISO/TR 6336-30 ex. 1: c' / (c'_th 0.8 cos beta) = 0.900).
  EXPECT_NEAR(iso::basic_rack_factor(1.4, 20.0 * kDeg), 0.9, 1e-12);
  EXPECT_NEAR(iso::basic_rack_factor(1.25, 20.0 * kDeg), 0.975, 1e-12);
  EXPECT_NEAR(iso::basic_rack_factor(1.2, 25.0 * kDeg), 1.1, 1e-12);  // (1 - 0.02 (20 - 25))
  const double full = iso::single_stiffness(20.0, 0.8, 1.0, 1.0, 0.0, 100.0);
  EXPECT_DOUBLE_EQ(full, 16.0);
  EXPECT_NEAR(iso::single_stiffness(20.0, 0.8, 1.0, 1.0, 0.0, 50.0), 16.0 * std::pow(0.5, 0.25), 1e-12);
  EXPECT_DOUBLE_EQ(iso::gear_blank_factor(1.0, 10.0, 2.0), 1.0);
  EXPECT_LT(iso::gear_blank_factor(0.5, 2.0, 2.0), 1.0);
  // Table 9 at z_n -> infinity (rack against rack, x = 0): q' = C_1.
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_NEAR(iso::minimum_flank_deformation(inf, inf, 0.0, 0.0), 0.04723, 1e-12);
}

TEST(DynamicFactor, RangesAndContinuity) {
  EXPECT_EQ(iso::resonance_range(0.5, 0.85), iso::ResonanceRange::subcritical);
  EXPECT_EQ(iso::resonance_range(1.0, 0.85), iso::ResonanceRange::main_resonance);
  EXPECT_EQ(iso::resonance_range(1.3, 0.85), iso::ResonanceRange::intermediate);
  EXPECT_EQ(iso::resonance_range(2.0, 0.85), iso::ResonanceRange::supercritical);
  EXPECT_NEAR(iso::resonance_lower_limit(25.0), 0.5 + 0.35 * 0.5, 1e-12);
  const auto C = iso::dynamic_coefficients(1.6);
  const iso::DeviationTerms B{0.4, 0.3, 0.2};
  // Eq. 17 joins Eq. 15 at N = 1.15 and Eq. 16 at N = 1.5.
  EXPECT_NEAR(iso::dynamic_factor(1.15 + 1e-12, 0.85, C, B), iso::dynamic_factor(1.15, 0.85, C, B), 1e-9);
  EXPECT_NEAR(iso::dynamic_factor(1.5 - 1e-12, 0.85, C, B), iso::dynamic_factor(1.5, 0.85, C, B), 1e-9);
  // Sub-critical: K_v = N (C_v1 B_p + C_v2 B_f + C_v3 B_k) + 1 with Table 6 for eps_gamma <= 2.
  EXPECT_NEAR(iso::dynamic_factor(0.5, 0.85, C, B), 0.5 * (0.32 * 0.4 + 0.34 * 0.3 + 0.23 * 0.2) + 1.0, 1e-12);
  // C_v7 of Table 6 is continuous at eps_gamma = 1.5 and 2.5.
  EXPECT_NEAR(iso::dynamic_coefficients(1.5 + 1e-12).C_v7, 0.75, 1e-9);
  EXPECT_NEAR(iso::dynamic_coefficients(2.5).C_v7, 1.0, 1e-12);
  // Tip relief by running-in for sigma_Hlim = 1500 MPa: (1500/97 - 18.45)^2 / 18 + 1.5.
  EXPECT_NEAR(iso::tip_relief_by_running_in(1500.0), std::pow(1500.0 / 97.0 - 18.45, 2) / 18.0 + 1.5, 1e-12);
}

TEST(RunningIn, AllowancesAndTheirLimits) {
  EXPECT_DOUBLE_EQ(iso::running_in_allowance_alpha(20.0, 1500.0, true, false, 2.0), 1.5);
  EXPECT_DOUBLE_EQ(iso::running_in_allowance_alpha(60.0, 1500.0, true, false, 2.0), 3.0);
  EXPECT_DOUBLE_EQ(iso::running_in_allowance_alpha(20.0, 800.0, false, false, 2.0), 4.0);
  EXPECT_DOUBLE_EQ(iso::running_in_allowance_alpha(100.0, 800.0, false, false, 12.0), 8.0);
  EXPECT_DOUBLE_EQ(iso::running_in_allowance_beta(20.0, 1500.0, true, false, 2.0), 3.0);
  EXPECT_DOUBLE_EQ(iso::running_in_allowance_beta(100.0, 1500.0, true, false, 2.0), 6.0);
  EXPECT_DOUBLE_EQ(iso::running_in_allowance_beta(20.0, 800.0, false, false, 2.0), 8.0);
}

TEST(FaceLoadFactor, MethodCAndExponent) {
  // Eq. 35 below 2, Eq. 36 above; both give 2 at the switch.
  EXPECT_NEAR(iso::face_load_factor_H(20.0, 10.0, 200.0), 1.5, 1e-12);
  EXPECT_NEAR(iso::face_load_factor_H(20.0, 20.0, 200.0), 2.0, 1e-12);
  EXPECT_NEAR(iso::face_load_factor_H(20.0, 40.0, 200.0), std::sqrt(8.0), 1e-12);
  // N_F for b/h = 100/19.2: 27.13 / 33.34; b/h below 3 counts as 3.
  const double r = 100.0 / 19.2;
  EXPECT_NEAR(iso::face_load_exponent(r), r * r / (1.0 + r + r * r), 1e-12);
  EXPECT_DOUBLE_EQ(iso::face_load_exponent(1.0), 9.0 / 13.0);
  EXPECT_NEAR(iso::face_load_factor_F(1.16, iso::face_load_exponent(r)), 1.1284, 0.0001);
  EXPECT_DOUBLE_EQ(iso::initial_equivalent_misalignment(0.0, 0.0, 1000.0, 0.0), 5.0);  // F_betax,min = 0.005 F_m/b
  EXPECT_NEAR(iso::shaft_deflection_misalignment(1000.0, 50.0, 100.0, 0.0, 0.0, 0.0, 0.0), 1000.0 * 0.023 * 0.25, 1e-12);
}

TEST(TransverseLoadFactor, FormulaAndLimits) {
  EXPECT_NEAR(iso::transverse_load_factor(1.6, 20.0, 10.0, 400.0), 0.8 * (0.9 + 0.4 * 0.5), 1e-12);
  EXPECT_NEAR(iso::transverse_load_factor(2.5, 20.0, 10.0, 400.0), 0.9 + 0.4 * std::sqrt(2.0 * 1.5 / 2.5) * 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(iso::limit_K_Halpha(0.9, 1.6, 1.6, 0.9), 1.0);
  EXPECT_NEAR(iso::limit_K_Halpha(5.0, 1.6, 1.6, 0.9), 1.0 / 0.81, 1e-12);
  EXPECT_NEAR(iso::limit_K_Falpha(5.0, 1.6, 1.6), 1.6 / (0.4 + 0.75), 1e-12);
}

// ISO 6336-1:2019 6.5.9 (as DIN 3990-1): for two materials C_ay = 0.5 (C_ay1 + C_ay2), the mean,
// like the running-in allowances y_alpha and y_beta. By hand: case-carburized 1500 MPa:
// (1500/97 - 18.45)^2/18 + 1.5 = 1.9954 um; through-hardened 700 MPa: (700/97 - 18.45)^2/18 + 1.5
// = 8.5106 um; mean 5.2530 um (the larger value, used before, is 8.5106 um).
TEST(DynamicFactor, TipReliefByRunningInOfTwoMaterials) {
  EXPECT_NEAR(iso::tip_relief_by_running_in(1500.0), 1.9954, 1e-4);
  EXPECT_NEAR(iso::tip_relief_by_running_in(700.0), 8.5106, 1e-4);
  EXPECT_NEAR(iso::mesh_tip_relief_by_running_in(1500.0, 700.0), 5.2530, 1e-4);
  EXPECT_DOUBLE_EQ(iso::mesh_tip_relief_by_running_in(1500.0, 1500.0), iso::tip_relief_by_running_in(1500.0));
}

// ISO 6336-1:2019 7.6.4, Eq. 43 with Eq. 44 (spur and single helical), written out here on its own:
// f_sh = F_m/b 0.023 (|B* + K' l s / d_1^2 (d_1/d_sh)^4 - 0.3| + 0.3) (b/d_1)^2.
namespace {
double f_sh_eq43(double F_m_per_b, double b, double d_1, double K_prime, double l, double s, double d_sh, double B_star) {
  const double bending = K_prime * l * s / (d_1 * d_1) * std::pow(d_1 / d_sh, 4.0);
  return F_m_per_b * 0.023 * (std::fabs(B_star + bending - 0.3) + 0.3) * std::pow(b / d_1, 2.0);
}
}  // namespace

TEST(FaceLoadMethodC, ShaftDeflectionByHand) {
  // F_m/b = 300 N/mm, b = 60, d_1 = 80, l = 200, s = 30, d_sh = 60 mm; arrangement a with
  // stiffening (d_1/d_sh = 1.33 >= 1.15): K' = 0.48. By hand: K' l s/d_1^2 (d_1/d_sh)^4 =
  // 0.48 * 0.9375 * 256/81 = 1.42222; gamma = (1 + 1.42222) * 0.5625 = 1.3625;
  // f_sh = 300 * 0.023 * 1.3625 = 9.40125 um.
  const double K = iso::shaft_constant_K_prime(iso::ShaftArrangement::a, true);
  EXPECT_DOUBLE_EQ(K, 0.48);
  EXPECT_NEAR(iso::shaft_deflection_misalignment(300.0, 60.0, 80.0, K, 200.0, 30.0, 60.0), 9.40125, 1e-9);
  EXPECT_NEAR(iso::shaft_deflection_misalignment(300.0, 60.0, 80.0, K, 200.0, 30.0, 60.0), f_sh_eq43(300.0, 60.0, 80.0, K, 200.0, 30.0, 60.0, 1.0), 1e-12);
  // Power split k = 50 %: B* = 1 + 2 (100 - 50)/50 = 3; gamma = (3 + 1.42222) * 0.5625 = 2.4875,
  // f_sh = 300 * 0.023 * 2.4875 = 17.16375 um.
  EXPECT_DOUBLE_EQ(iso::power_split_factor(100.0), 1.0);
  EXPECT_DOUBLE_EQ(iso::power_split_factor(50.0), 3.0);
  EXPECT_NEAR(iso::shaft_deflection_misalignment(300.0, 60.0, 80.0, K, 200.0, 30.0, 60.0, iso::power_split_factor(50.0)), 17.16375, 1e-9);
  // Arrangement b (K' = -0.48): the offset works against torsion: |1 - 1.42222 - 0.3| + 0.3 = 1.02222,
  // gamma = 0.575, f_sh = 300 * 0.023 * 0.575 = 3.9675 um.
  EXPECT_NEAR(iso::shaft_deflection_misalignment(300.0, 60.0, 80.0, iso::shaft_constant_K_prime(iso::ShaftArrangement::b, true), 200.0,
                                                 30.0, 60.0),
              3.9675, 1e-9);
}

TEST(FaceLoadMethodC, FigureThirteenConstants) {
  // ISO 6336-1 Figure 13: K' with / without stiffening, and the s/l range of each arrangement.
  const std::pair<iso::ShaftArrangement, std::array<double, 3>> table[] = {
      {iso::ShaftArrangement::a, {0.48, 0.8, 0.3}}, {iso::ShaftArrangement::b, {-0.48, -0.8, 0.3}},
      {iso::ShaftArrangement::c, {1.33, 1.33, 0.5}}, {iso::ShaftArrangement::d, {-0.36, -0.6, 0.5}},
      {iso::ShaftArrangement::e, {-0.6, -1.0, 0.5}}};
  for (const auto& [arrangement, v] : table) {
    EXPECT_DOUBLE_EQ(iso::shaft_constant_K_prime(arrangement, true), v[0]) << iso::to_string(arrangement);
    EXPECT_DOUBLE_EQ(iso::shaft_constant_K_prime(arrangement, false), v[1]) << iso::to_string(arrangement);
    EXPECT_DOUBLE_EQ(iso::shaft_offset_limit(arrangement), v[2]) << iso::to_string(arrangement);
  }
}

TEST(FaceLoadMethodC, LargerOffsetLargerMisalignmentForPositiveK) {
  // For K' > 0 the bending term adds to torsion: f_sh grows with s/l (0 .. the Figure 13 limit).
  double previous = 0.0;
  for (double s = 0.0; s <= 60.0; s += 5.0) {
    const double f = iso::shaft_deflection_misalignment(300.0, 60.0, 80.0, 0.8, 200.0, s, 60.0);
    EXPECT_GT(f, previous) << "s = " << s;
    previous = f;
  }
  // s = 0: no bending term whatever K' (the pinion in the middle of the span).
  EXPECT_DOUBLE_EQ(iso::shaft_deflection_misalignment(300.0, 60.0, 80.0, 0.8, 200.0, 0.0, 60.0),
                   iso::shaft_deflection_misalignment(300.0, 60.0, 80.0, 0.0, 0.0, 0.0, 0.0));
}

TEST(FaceLoadMethodC, HelixModificationConstants) {
  // ISO 6336-1:2019 Table 10 (2006: Table 8): B_1, B_2 of Eq. 38.
  const std::pair<iso::HelixModification, std::array<double, 2>> table[] = {
      {iso::HelixModification::none, {1.0, 1.0}}, {iso::HelixModification::helix_correction, {0.1, 1.0}},
      {iso::HelixModification::helix_correction_and_crowning, {0.1, 0.5}}, {iso::HelixModification::crowning, {0.5, 0.5}},
      {iso::HelixModification::end_relief, {0.7, 0.7}}};
  for (const auto& [m, B] : table) {
    EXPECT_DOUBLE_EQ(iso::misalignment_constants(m).B_1, B[0]) << iso::to_string(m);
    EXPECT_DOUBLE_EQ(iso::misalignment_constants(m).B_2, B[1]) << iso::to_string(m);
  }
  // F_betax = 1.33 B_1 f_sh + B_2 f_ma: helix correction, f_sh = 10, f_ma = 8 -> 1.33 + 8 = 9.33 um.
  EXPECT_NEAR(iso::initial_equivalent_misalignment(10.0, 8.0, 100.0, 0.0, iso::misalignment_constants(iso::HelixModification::helix_correction)),
              9.33, 1e-12);
  // Crowning: 0.5 (13.3 + 8) = 10.65 um.
  EXPECT_NEAR(iso::initial_equivalent_misalignment(10.0, 8.0, 100.0, 0.0, iso::misalignment_constants(iso::HelixModification::crowning)),
              10.65, 1e-12);
}
