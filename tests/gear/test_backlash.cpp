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
