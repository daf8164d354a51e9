// Tests for gearkit/gear/agma.hpp against Shigley's "Mechanical Engineering Design" (9th ed.),
// Example 14-4: 17-tooth 20 deg spur pinion at 1800 rev/min transmitting 4 hp to a 52-tooth gear,
// P_d = 10 teeth/in, F = 1.5 in, Q_v = 6, straddle-mounted, uncrowned, commercial enclosed unit;
// grade 1 through-hardened steel 240 HB (pinion) and 200 HB (gear); J_P = 0.30, J_G = 0.40;
// 1e8 pinion cycles, R = 0.90. Published: V = 801.1 ft/min, W_t = 164.8 lbf, K_v = 1.377,
// K_s = 1.043 (pinion) / 1.052 (gear), K_m = 1.22, sigma = 6417 / 4854 psi, S_F = 5.62 / 6.82;
// I = 0.121, sigma_c = 70 360 / 70 660 psi, S_H = 1.69 / 1.52.
#include <gearkit/gear/agma.hpp>

#include <gearkit/gear/lewis_hertz.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gg = gearkit::gear;
namespace agma = gearkit::gear::agma;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kInch = 25.4, kLbf = 4.4482216, kPsi = 6.894757e-3;  // mm, N, MPa

gg::Material through_hardened(double HB) {
  gg::Material m = gg::material_of_class(gg::MaterialClass::through_hardened_alloy, gg::QualityGrade::MQ, HB / 0.95);
  m.HB = HB;
  m.E = 30e6 * kPsi;
  m.nu = 0.3;
  return m;
}
}  // namespace

TEST(ShigleyExample14_4, FactorByFactor) {
  EXPECT_NEAR(agma::dynamic_factor_ft_min(6, 801.1), 1.377, 0.0005);
  const double m = kInch / 10.0, b = 1.5 * kInch;
  EXPECT_NEAR(agma::size_factor(m, b, 0.303), 1.043, 0.0005);
  EXPECT_NEAR(agma::size_factor(m, b, gg::lewis::form_factor(52)), 1.052, 0.0005);
  EXPECT_NEAR(agma::load_distribution_factor(b, 1.7 * kInch, gg::AgmaMounting::commercial, false), 1.22, 0.0005);
  EXPECT_NEAR(agma::surface_geometry_factor(20.0 * kDeg, 52.0 / 17.0, 1.0, false), 0.121, 0.0005);
  EXPECT_NEAR(agma::bending_cycle_factor(1e8), 0.977, 0.0005);
  EXPECT_NEAR(agma::contact_cycle_factor(1e8), 0.948, 0.0005);
  EXPECT_DOUBLE_EQ(agma::reliability_factor(0.90), 0.85);
  EXPECT_NEAR(agma::bending_strength_through_hardened(240, 1) / kPsi, 31350.0, 15.0);
  EXPECT_NEAR(agma::contact_strength_through_hardened(240, 1) / kPsi, 106400.0, 0.0015 * 106400.0);  // metric line of Fig. 14-5
  EXPECT_NEAR(agma::hardness_ratio_factor(240, 200, 52.0 / 17.0), 1.005, 0.0005);
  const double sigma = agma::bending_stress(164.8 * kLbf, 1.0, 1.377, 1.043, 1.22, 1.0, b, m, 0.30);
  EXPECT_NEAR(sigma / kPsi, 6417.0, 6.0);
}

TEST(ShigleyExample14_4, CompleteRatingWithTheMethodAgma) {
  gg::GearPairInput in;
  in.z1 = 17;
  in.z2 = 52;
  in.module = kInch / 10.0;
  in.face_width = 1.5 * kInch;
  const auto geometry = gg::compute_gear_pair(in);
  gg::RatingInput load;
  load.method = gg::RatingMethod::agma;
  load.T_1 = 164.8 * kLbf * 0.5 * 1.7 * kInch / 1000.0;  // W_t d_P / 2
  load.n_1 = 1800.0;
  load.life_h = 1e8 / (1800.0 * 60.0);
  load.Q_v = 6;
  load.reliability = 0.90;
  load.material = {through_hardened(240), through_hardened(200)};
  load.factors.set(gg::Factor::J1, 0.30);
  load.factors.set(gg::Factor::J2, 0.40);
  load.factors.set(gg::Factor::Z_E, 2300.0 * std::sqrt(kPsi));  // C_p of Table 14-8, as the example takes it
  const auto p = gg::rate_gear_pair(in, geometry, load);
  EXPECT_NEAR(p.v * 196.8504, 801.1, 0.1);
  EXPECT_NEAR(p.F_t / kLbf, 164.8, 0.01);
  EXPECT_NEAR(p.K_v, 1.377, 0.0005);
  EXPECT_NEAR(p.K_Hbeta, 1.22, 0.0005);
  EXPECT_NEAR(p.gear[0].sigma_F / kPsi, 6417.0, 10.0);
  EXPECT_NEAR(p.gear[1].sigma_F / kPsi, 4854.0, 10.0);
  EXPECT_NEAR(p.gear[0].S_F, 5.62, 0.01);
  EXPECT_NEAR(p.gear[1].S_F, 6.82, 0.01);
  EXPECT_NEAR(p.Z_E / std::sqrt(kPsi), 2300.0, 5.0);
  EXPECT_NEAR(p.gear[0].sigma_H / kPsi, 70360.0, 100.0);
  EXPECT_NEAR(p.gear[1].sigma_H / kPsi, 70660.0, 100.0);
  EXPECT_NEAR(p.gear[0].S_H, 1.69, 0.01);
  EXPECT_NEAR(p.gear[1].S_H, 1.52, 0.01);
}

TEST(Agma, ReliabilityAndGeometryFactors) {
  EXPECT_NEAR(agma::reliability_factor(0.95), 0.658 - 0.0759 * std::log(0.05), 1e-12);
  EXPECT_NEAR(agma::reliability_factor(0.995), 0.50 - 0.109 * std::log(0.005), 1e-12);
  EXPECT_DOUBLE_EQ(agma::hardness_ratio_factor(200, 200, 3.0), 1.0);
  // I of an internal pair uses m_G - 1.
  EXPECT_NEAR(agma::surface_geometry_factor(20.0 * kDeg, 3.0, 1.0, true) / agma::surface_geometry_factor(20.0 * kDeg, 3.0, 1.0, false),
              4.0 / 2.0, 1e-12);
  EXPECT_NEAR(agma::dynamic_factor(6, 801.1 * 0.00508), agma::dynamic_factor_ft_min(6, 801.1), 1e-12);
}
