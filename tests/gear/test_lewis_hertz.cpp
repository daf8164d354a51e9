// Tests for gearkit/gear/lewis_hertz.hpp against Shigley's "Mechanical Engineering Design"
// (9th ed.), Examples 14-1 and 14-3 (transcription: holooly.com, "The pinion of Examples 14-1 and
// 14-2 is to be mated with a 50-tooth gear ... ASTM No. 50 cast iron").
#include <gearkit/gear/lewis_hertz.hpp>

#include <gearkit/gear/iso6336_pitting.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gg = gearkit::gear;
namespace lewis = gearkit::gear::lewis;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}

TEST(ShigleyExample14_1, LewisRatingOfAStockGear) {
  // P = 8 teeth/in, F = 1.5 in, 16 teeth, 20 deg full depth, AISI 1020 as rolled, n_d = 3,
  // 1200 rev/min: Y = 0.296, V = 628.3 ft/min, K_v = 1.52 (cut teeth), sigma_all = 10 kpsi,
  // W_t = F Y sigma_all / (K_v P) = 365 lbf, H = 6.95 hp.
  EXPECT_DOUBLE_EQ(lewis::form_factor(16), 0.296);
  const double V = std::numbers::pi * 2.0 * 1200.0 / 12.0;
  EXPECT_NEAR(V, 628.3, 0.05);
  const double K_v = lewis::velocity_factor_ft_min(gg::LewisProfile::cut, V);
  EXPECT_NEAR(K_v, 1.52, 0.005);
  // sigma = K_v W_t P / (F Y): the module form with m = 1/P in.
  const double W_t = 1.5 * 0.296 * 10000.0 / (K_v * 8.0);
  EXPECT_NEAR(W_t, 365.0, 1.0);
  EXPECT_NEAR(lewis::bending_stress(W_t, K_v, 1.5, 1.0 / 8.0, 0.296), 10000.0, 1e-6);
  EXPECT_NEAR(W_t * V / 33000.0, 6.95, 0.02);
  // The metric Barth factor is the same law (V in m/s).
  EXPECT_NEAR(lewis::velocity_factor(gg::LewisProfile::cut, V * 0.00508), K_v, 0.001);
}

TEST(ShigleyExample14_3, HertzContactWithACastIronGear) {
  // E_P = 30 Mpsi, nu_P = 0.292; E_G = 14.5 Mpsi, nu_G = 0.211: C_p = 1817 psi^0.5;
  // r_1 = 0.342 in, r_2 = 1.069 in, K_v = 1.52, W_t = 380 lbf, F = 1.5 in: sigma_C = 72 400 psi;
  // S_C = 0.32 (262) = 83.8 kpsi, n = (S_C / sigma_C)^2 = 1.34.
  const double C_p = gg::iso6336::elasticity_factor(30e6, 0.292, 14.5e6, 0.211);
  EXPECT_NEAR(C_p, 1817.0, 0.5);
  const double r_1 = lewis::pitch_point_radius(2.0, 20.0 * kDeg);
  const double r_2 = lewis::pitch_point_radius(6.25, 20.0 * kDeg);
  EXPECT_NEAR(r_1, 0.342, 0.0005);
  EXPECT_NEAR(r_2, 1.069, 0.0005);
  const double sigma = lewis::contact_stress(C_p, 380.0, 1.52, 1.5, 20.0 * kDeg, r_1, r_2, false);
  EXPECT_NEAR(sigma, 72400.0, 0.003 * 72400.0);  // printed to three figures
  EXPECT_NEAR(std::pow(0.32 * 262.0 * 1000.0 / sigma, 2), 1.34, 0.01);
}

TEST(LewisHertz, TableAndInternalContact) {
  EXPECT_DOUBLE_EQ(lewis::form_factor(12), 0.245);
  EXPECT_NEAR(lewis::form_factor(23), 0.334, 1e-12);  // halfway 22..24
  EXPECT_NEAR(lewis::form_factor(1e9), 0.485, 1e-6);
  const double ext = lewis::contact_stress(1.0, 1.0, 1.0, 1.0, 0.0, 1.0, 3.0, false);
  const double in = lewis::contact_stress(1.0, 1.0, 1.0, 1.0, 0.0, 1.0, 3.0, true);
  EXPECT_NEAR(in / ext, std::sqrt((2.0 / 3.0) / (4.0 / 3.0)), 1e-12);
}
