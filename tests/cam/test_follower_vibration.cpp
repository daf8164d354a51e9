// Tests of gearkit/cam/follower_vibration.hpp: residual vibration against the closed form of an
// undamped oscillator after a cycloidal rise, the program's periodic response against the
// single-rise response, the stiff limit against the rigid kinetostatics, cycloidal against
// simple harmonic.
#include <gearkit/cam/follower_vibration.hpp>

#include "cam_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

namespace {

using namespace gearkit::cam;
using gearkit::cam::testing::dwell;
using gearkit::cam::testing::move;
using gearkit::cam::testing::rad;
using gearkit::cam::testing::translating;

constexpr double pi = std::numbers::pi;

/// Residual amplitude after a cycloidal rise L over time T of an undamped oscillator at rest:
/// e'' + w_n^2 e = -L y''(t), y'' = (2 pi / T^2) sin(2 pi t / T), so the amplitude is
/// |integral L y'' e^{-i w_n t} dt| / w_n = L (2 pi / T^2) W 2 |sin(w_n T / 2)| / (|W^2 - w_n^2| w_n),
/// W = 2 pi / T (hand derivation; cf. Norton, Design of Machinery, sec. 15.5, and Koster,
/// "Vibrations of cam mechanisms", for the same residual-vibration spectra).
double cycloidal_residual(double L, double T, double wn) {
  const double W = 2 * pi / T;
  return L * (2 * pi / (T * T)) * W * 2 * std::abs(std::sin(wn * T / 2)) / (std::abs(W * W - wn * wn) * wn);
}

TEST(FollowerVibration, UndampedCycloidalResidualIsTheClosedForm) {
  const double L = 0.02, beta = rad(90), omega = 30;
  const double T = beta / omega;
  for (double ratio : {2.3, 3.5, 7.25, 12.6}) {
    const double wn = ratio * 2 * pi / T;
    EXPECT_NEAR(residual_vibration_of_law(Law::cycloidal, L, beta, omega, wn, 0, 1), cycloidal_residual(L, T, wn),
                1e-7 * L)
        << ratio;
  }
  // The cycloidal law leaves no vibration when w_n T is a whole number (> 1) of turns.
  EXPECT_NEAR(residual_vibration_of_law(Law::cycloidal, L, beta, omega, 4 * 2 * pi / T, 0, 1), 0, 1e-8 * L);
}

TEST(FollowerVibration, CycloidalBeatsSimpleHarmonicAtSpeed) {
  // The harmonic law's acceleration steps at both ends excite the train with every frequency
  // (its residual falls as 1/(w_n T)^2); the cycloidal one starts and stops with zero
  // acceleration (1/(w_n T)^3). Both spectra have zeros, so compare their envelopes: the largest
  // residual over a band of natural frequencies, w_n T from 20 to 21 turns. The 4-5-6-7 law (zero
  // jerk at the ends too) is below the 3-4-5 there.
  const double L = 0.02, beta = rad(90), omega = 30, T = beta / omega;
  auto envelope = [&](Law law) {
    double worst = 0;
    for (int i = 0; i <= 50; ++i)
      worst = std::max(worst, residual_vibration_of_law(law, L, beta, omega, (20 + i / 50.0) * 2 * pi / T, 0.0, 1));
    return worst;
  };
  EXPECT_GT(envelope(Law::simple_harmonic), 10 * envelope(Law::cycloidal));
  EXPECT_LT(envelope(Law::polynomial_4567), envelope(Law::polynomial_345));
}

TEST(FollowerVibration, ProgramResponseAfterALongDwellIsTheSingleRiseResponse) {
  // A rise after a long dwell starts from rest (earlier vibration has died away at zeta = 0.05),
  // so the residual vibration in the periodic response equals that of the rise alone, and the
  // whole response scales with the static ratio k_f / (k + k_f).
  const MotionProgram p({dwell(0, 180), move(SegmentKind::rise, 180, 240, Law::cycloidal, 12), dwell(240, 300),
                         move(SegmentKind::fall, 300, 360, Law::cycloidal, 12)});
  const CamDesign d{p, translating(Contact::roller, 10), 40, Rotation::ccw};
  FollowerTrain t;
  t.mass = 0.4, t.spring_rate = 2000, t.preload = 30, t.stiffness = 2e6;
  const double K = t.spring_rate + t.stiffness, zeta = 0.15;  // the dwell damps earlier vibration by e^-10
  t.damping = 2 * zeta * std::sqrt(K * t.mass);
  const double omega = 100;  // wn / omega = 22.4: about 3.7 free periods during the rise
  const FlexibleResponse r = flexible_response(d, t, omega, 3600);
  EXPECT_TRUE(r.periodic);
  EXPECT_NEAR(r.natural_frequency, std::sqrt(K / t.mass), 1e-9);
  EXPECT_NEAR(r.damping_ratio, zeta, 1e-12);
  const auto residuals = residual_vibrations(d, t, r);
  ASSERT_EQ(residuals.size(), 2u);
  EXPECT_EQ(residuals[0].segment, 1u);
  const double expected =
      residual_vibration_of_law(Law::cycloidal, 0.012, rad(60), omega, r.natural_frequency, zeta, r.static_ratio);
  EXPECT_NEAR(residuals[0].amplitude, expected, 1e-3 * expected);
  EXPECT_GT(expected, 1e-7);
  // At rest on the base circle just before the rise: the static position -F_pl / (k + k_f).
  const auto before = std::lower_bound(r.theta.begin(), r.theta.end(), rad(180)) - r.theta.begin();
  EXPECT_NEAR(r.x[before], -t.preload / K, 1e-3 * t.preload / K);
}

TEST(FollowerVibration, StiffFollowerTrainTendsToTheRigidKinetostatics) {
  // k_f -> infinity: the follower moves with the cam and k_f (q - x) -> Q (Norton, eq. 15.8).
  // A 4-5-6-7 program (jerk continuous: hardly any vibration is excited).
  const CamDesign d{gearkit::cam::testing::rise_dwell_return(20, Law::polynomial_4567), translating(Contact::roller, 10),
                    40, Rotation::ccw};
  FollowerTrain t;
  t.mass = 0.5, t.spring_rate = 5000, t.preload = 50, t.damping = 2 * 0.05 * std::sqrt(1e10 * 0.5), t.stiffness = 1e10;
  const double omega = 60;
  const FlexibleResponse r = flexible_response(d, t, omega, 3600);
  double scale = 0;  // the largest force of the turn
  for (double th : r.theta) scale = std::max(scale, std::abs(dynamic_state(d, t, omega, th, nullptr).force));
  for (std::size_t i = 0; i < r.theta.size(); i += 37) {
    const DynamicState s = dynamic_state(d, t, omega, r.theta[i], nullptr);
    EXPECT_NEAR(r.force[i], s.force, 1e-3 * scale) << r.theta[i];
  }
}

}  // namespace
