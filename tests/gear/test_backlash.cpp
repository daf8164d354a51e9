// Tests for gearkit/gear/backlash.hpp.
#include <gearkit/gear/backlash.hpp>
#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/gear_pair.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gg = gearkit::gear;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Nominal (zero-backlash) data of a pair at its working centre distance.
gg::BacklashInput nominal(int z1, int z2, double m_n, double beta, double x1, double x2) {
  const double a_n = 20.0 * kDeg;
  const double a_t = gg::transverse_pressure_angle(a_n, beta);
  const double m_t = gg::transverse_module(m_n, beta);
  gg::BacklashInput in;
  in.z1 = z1;
  in.z2 = z2;
  in.d1 = gg::reference_diameter(z1, m_n, beta);
  in.d2 = gg::reference_diameter(z2, m_n, beta);
  in.d_b1 = gg::base_diameter(in.d1, a_t);
  in.d_b2 = gg::base_diameter(in.d2, a_t);
  in.alpha_t = a_t;
  in.beta_b = gg::base_helix_angle(beta, a_n);
  in.s_t1 = gg::reference_tooth_thickness(m_t, x1, a_n);
  in.s_t2 = gg::reference_tooth_thickness(m_t, x2, a_n);
  const double a_wt = gg::working_pressure_angle(a_t, a_n, z1, z2, x1 + x2);
  in.a = gg::centre_distance(gg::reference_centre_distance(z1, z2, m_t), a_t, a_wt);
  return in;
}

}  // namespace

TEST(Backlash, ZeroAtTheShiftDerivedCentreDistance) {
  // Two methods must agree: the centre distance from inv a_wt = inv a_t + 2 tan a_n sum_x / sum_z
  // is the one where the nominal teeth mesh without backlash (ISO 21771 clause 5).
  EXPECT_NEAR(gg::circumferential_backlash(nominal(12, 24, 3.0, 0.0, 0.6, 0.36)), 0.0, 1e-12);
  EXPECT_NEAR(gg::circumferential_backlash(nominal(31, 30, 3.5, 21.0 * kDeg, 0.291, 0.36)), 0.0, 1e-12);
  EXPECT_NEAR(gg::circumferential_backlash(nominal(17, -96, 14.0, 0.0, 0.2, -0.5)), 0.0, 1e-11);  // internal
}

TEST(Backlash, CentreDistanceDeviationMatchesTheLinearRule) {
  // DIN 3967 / textbook: a small centre distance increase da gives j_t = 2 da tan(a_wt)
  // on the working circle (finite-difference check of the exact formula).
  gg::BacklashInput in = nominal(12, 24, 3.0, 0.0, 0.6, 0.36);
  const double a_wt = gg::working_pressure_angle_at(in);
  const double da = 1e-5;
  in.a += da;
  EXPECT_NEAR(gg::circumferential_backlash(in) / da, 2.0 * std::tan(a_wt), 1e-4);
}

TEST(Backlash, AllowancesAreExactlyLinear) {
  // j_bn = -(A_sn1 + A_sn2) cos(alpha_n) at the nominal centre distance (ISO 21771 clause 7).
  for (double beta : {0.0, 18.0 * kDeg}) {
    gg::BacklashInput in = nominal(19, 53, 2.0, beta, 0.1, -0.1);
    const double A1 = -0.05, A2 = -0.08;
    in.s_t1 += A1 / std::cos(beta);
    in.s_t2 += A2 / std::cos(beta);
    const double j_wt = gg::circumferential_backlash(in);
    const double j_bn = gg::normal_backlash(j_wt, gg::working_pressure_angle_at(in), in.beta_b);
    EXPECT_NEAR(j_bn, 0.13 * std::cos(20.0 * kDeg), 1e-12);
  }
}

TEST(Backlash, AllowanceForATargetRoundTrips) {
  gg::BacklashInput in = nominal(12, 24, 3.0, 0.0, 0.6, 0.36);
  in.a += 0.02;  // with a centre distance deviation too
  const double A = gg::allowance_for_backlash(in, 20.0 * kDeg, 0.1);
  EXPECT_LT(A, 0.0);
  in.s_t1 += A;
  in.s_t2 += A;
  EXPECT_NEAR(gg::normal_backlash(gg::circumferential_backlash(in), gg::working_pressure_angle_at(in), in.beta_b), 0.1, 1e-12);
}

TEST(Backlash, BaseCirclesOutOfReach) {
  gg::BacklashInput in = nominal(12, 24, 3.0, 0.0, 0.0, 0.0);
  in.a = 40.0;
  EXPECT_THROW(gg::circumferential_backlash(in), std::domain_error);
}

TEST(BacklashRange, ExternalPairMatchesTheLinearRules) {
  // Two methods: the exact states of backlash_range against the linear rules of DIN 3967 /
  // ISO 21771-2, j_n = -(A_sn1 + A_sn2) cos(alpha_n) + 2 A_a sin(alpha_wt) cos(beta_b).
  for (double beta : {0.0, 15.0 * kDeg}) {
    const gg::BacklashInput in = nominal(19, 53, 2.0, beta, 0.1, -0.1);
    const gg::PairLimits l{-0.04, -0.09, -0.05, -0.11, 0.02, -0.02};
    const auto r = gg::backlash_range(in, beta, l);
    const double a_wt = gg::working_pressure_angle_at(in);
    const double k_a = 2.0 * std::sin(a_wt) * std::cos(in.beta_b);
    EXPECT_NEAR(r.min.j_n, 0.09 * std::cos(20 * kDeg) - 0.02 * k_a, 2e-5);
    EXPECT_NEAR(r.max.j_n, 0.20 * std::cos(20 * kDeg) + 0.02 * k_a, 2e-5);
    EXPECT_NEAR(r.min.j_t, r.min.j_n / (std::cos(a_wt) * std::cos(in.beta_b)), 1e-4);
  }
}

TEST(BacklashRange, InternalPairIsTightestAtTheLargestDistance) {
  // Moving the pinion away from the ring centre pushes its teeth into the ring's: for an internal
  // pair the least backlash is at the largest centre distance.
  const gg::BacklashInput in = nominal(17, -96, 4.0, 0.0, 0.2, -0.5);
  const gg::PairLimits l{-0.05, -0.1, -0.05, -0.1, 0.03, -0.03};
  const auto r = gg::backlash_range(in, 0.0, l);
  gg::BacklashInput far = in;
  far.s_t1 -= 0.05;
  far.s_t2 -= 0.05;
  far.a -= 0.03;  // a < 0 for internal pairs: |a| + 0.03
  EXPECT_NEAR(r.min.j_n, gg::backlash_at(far).j_n, 1e-12);
  EXPECT_LT(r.min.j_n, 0.1 * std::cos(20 * kDeg));
  EXPECT_GT(r.max.j_n, 0.2 * std::cos(20 * kDeg));
}

TEST(BacklashRange, ThermalExpansion) {
  const gg::BacklashInput in = nominal(20, 40, 3.0, 0.0, 0.0, 0.0);
  // Everything at one temperature: a similar pair, still without backlash.
  EXPECT_NEAR(gg::backlash_at(gg::at_temperature(in, 6e-4, 6e-4, 6e-4)).j_n, 0.0, 1e-12);
  // Aluminium housing (23e-6 /K) and steel gears (11.5e-6 /K) 50 K warmer: the bores move apart by
  // a (e_h - e_g) and, linearly, j_n = 2 a (e_h - e_g) sin(alpha_wt) cos(beta_b).
  const double e_g = 11.5e-6 * 50, e_h = 23e-6 * 50;
  const auto warm = gg::backlash_at(gg::at_temperature(in, e_g, e_g, e_h));
  EXPECT_NEAR(warm.j_n, 2.0 * 90.0 * (e_h - e_g) * std::sin(20 * kDeg), 1e-4);  // 0.2 % second order
}
