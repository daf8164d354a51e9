// Tests of gearkit/cam/motion_law.hpp: boundary conditions, derivatives against finite
// differences, and peak factors against hand derivations and Norton's table.
#include <gearkit/cam/motion_law.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using gearkit::cam::evaluate;
using gearkit::cam::Law;
using gearkit::cam::LawValue;

constexpr double pi = std::numbers::pi;

const Law kAll[] = {Law::uniform_velocity,   Law::parabolic,          Law::simple_harmonic,
                    Law::cycloidal,          Law::polynomial_345,     Law::polynomial_4567,
                    Law::modified_trapezoid, Law::modified_sine};

TEST(MotionLaw, EveryLawRisesFromZeroToOne) {
  for (Law law : kAll) {
    SCOPED_TRACE(std::string(gearkit::cam::name_of(law)));
    EXPECT_NEAR(evaluate(law, 0).y, 0, 1e-14);
    EXPECT_NEAR(evaluate(law, 1).y, 1, 1e-12);
    EXPECT_NEAR(evaluate(law, 0.5).y, 0.5, 1e-12);  // every law here is point-symmetric about the middle
  }
}

TEST(MotionLaw, DwellCompatibleLawsStartAndEndAtRest) {
  for (Law law : kAll) {
    if (law == Law::uniform_velocity) continue;
    SCOPED_TRACE(std::string(gearkit::cam::name_of(law)));
    EXPECT_NEAR(evaluate(law, 0).dy, 0, 1e-12);
    EXPECT_NEAR(evaluate(law, 1).dy, 0, 1e-12);
  }
  // Zero acceleration at the ends: the laws without acceleration jumps at a dwell.
  for (Law law : {Law::cycloidal, Law::polynomial_345, Law::polynomial_4567, Law::modified_trapezoid,
                  Law::modified_sine}) {
    SCOPED_TRACE(std::string(gearkit::cam::name_of(law)));
    EXPECT_NEAR(evaluate(law, 0).d2y, 0, 1e-12);
    EXPECT_NEAR(evaluate(law, 1).d2y, 0, 1e-9);
  }
  // 4-5-6-7 also has zero jerk at both ends.
  EXPECT_NEAR(evaluate(Law::polynomial_4567, 0).d3y, 0, 1e-12);
  EXPECT_NEAR(evaluate(Law::polynomial_4567, 1).d3y, 0, 1e-9);
}

TEST(MotionLaw, DerivativesMatchFiniteDifferences) {
  const double h = 1e-5;
  for (Law law : kAll) {
    SCOPED_TRACE(std::string(gearkit::cam::name_of(law)));
    // Points away from the piece boundaries (1/8, 3/8, 1/2, 5/8, 7/8) of the piecewise laws.
    for (double u : {0.05, 0.2, 0.3, 0.45, 0.55, 0.7, 0.8, 0.95}) {
      const LawValue a = evaluate(law, u - h), b = evaluate(law, u + h), c = evaluate(law, u);
      EXPECT_NEAR((b.y - a.y) / (2 * h), c.dy, 1e-7) << "u = " << u;
      EXPECT_NEAR((b.dy - a.dy) / (2 * h), c.d2y, 1e-6) << "u = " << u;
      EXPECT_NEAR((b.d2y - a.d2y) / (2 * h), c.d3y, 1e-4) << "u = " << u;
    }
  }
}

TEST(MotionLaw, PiecewiseLawsAreContinuousInAcceleration) {
  const double h = 1e-10;
  for (Law law : {Law::modified_trapezoid, Law::modified_sine}) {
    for (double u : {0.125, 0.375, 0.625, 0.875}) {
      const LawValue a = evaluate(law, u - h), b = evaluate(law, u + h);
      EXPECT_NEAR(a.y, b.y, 1e-9);
      EXPECT_NEAR(a.dy, b.dy, 1e-8);
      EXPECT_NEAR(a.d2y, b.d2y, 1e-7);
    }
  }
}

double peak(Law law, double LawValue::*member) {
  double best = 0;
  for (int i = 0; i <= 200000; ++i) best = std::max(best, std::abs(evaluate(law, i / 200000.0).*member));
  return best;
}

TEST(MotionLaw, PeakFactorsMatchTheTextbook) {
  // Hand derivations:
  //  cycloidal: y' = 1 - cos(2 pi u) -> 2; y'' = 2 pi sin -> 2 pi; y''' = 4 pi^2 cos -> 4 pi^2.
  //  simple harmonic: pi/2, pi^2/2, pi^3/2.
  //  3-4-5: y' peak at u = 1/2: 30/16 = 1.875; y'' peak where y''' = 0, u = (3 - sqrt 3)/6:
  //    60 u (1-u)(1-2u) = 10/sqrt(3) = 5.7735; y''' peak at the ends: 60.
  //  4-5-6-7: y' at 1/2: 140/64 * ... = 35/16 = 2.1875; y'' = 420 u^2 (1-u)^2 (1-2u), peak at
  //    u = (5 - sqrt 5)/10: 7.5132; y''' peak at u = 1/2: 840 * 0.5 * 0.0625 = 52.5 (in magnitude).
  // Norton, Design of Machinery (5th ed.), table 8-3: modified trapezoid Cv = 2.0000,
  // Ca = 4.8881, Cj = 61.426; modified sine Cv = 1.7596, Ca = 5.5280, Cj = 69.466.
  EXPECT_NEAR(peak(Law::cycloidal, &LawValue::dy), 2, 1e-9);
  EXPECT_NEAR(peak(Law::cycloidal, &LawValue::d2y), 2 * pi, 1e-6);
  EXPECT_NEAR(peak(Law::cycloidal, &LawValue::d3y), 4 * pi * pi, 1e-9);
  EXPECT_NEAR(peak(Law::simple_harmonic, &LawValue::dy), pi / 2, 1e-9);
  EXPECT_NEAR(peak(Law::simple_harmonic, &LawValue::d2y), pi * pi / 2, 1e-9);
  EXPECT_NEAR(peak(Law::polynomial_345, &LawValue::dy), 1.875, 1e-9);
  EXPECT_NEAR(peak(Law::polynomial_345, &LawValue::d2y), 10 / std::sqrt(3.0), 1e-6);
  EXPECT_NEAR(peak(Law::polynomial_345, &LawValue::d3y), 60, 1e-9);
  EXPECT_NEAR(peak(Law::polynomial_4567, &LawValue::dy), 2.1875, 1e-9);
  const double u = (5 - std::sqrt(5.0)) / 10;
  EXPECT_NEAR(peak(Law::polynomial_4567, &LawValue::d2y), 420 * u * u * (1 - u) * (1 - u) * (1 - 2 * u), 1e-6);
  EXPECT_NEAR(peak(Law::polynomial_4567, &LawValue::d3y), 52.5, 1e-6);
  EXPECT_NEAR(peak(Law::parabolic, &LawValue::dy), 2, 1e-9);
  EXPECT_NEAR(peak(Law::parabolic, &LawValue::d2y), 4, 1e-12);
  EXPECT_NEAR(peak(Law::modified_trapezoid, &LawValue::dy), 2.0000, 1e-4);
  EXPECT_NEAR(peak(Law::modified_trapezoid, &LawValue::d2y), 4.8881, 1e-4);
  EXPECT_NEAR(peak(Law::modified_trapezoid, &LawValue::d3y), 61.426, 1e-3);
  EXPECT_NEAR(peak(Law::modified_sine, &LawValue::dy), 1.7596, 1e-4);
  EXPECT_NEAR(peak(Law::modified_sine, &LawValue::d2y), 5.5280, 1e-4);
  EXPECT_NEAR(peak(Law::modified_sine, &LawValue::d3y), 69.466, 1e-3);
}

TEST(MotionLaw, NamesRoundTrip) {
  for (Law law : kAll) EXPECT_EQ(gearkit::cam::law_from_name(gearkit::cam::name_of(law)), law);
  EXPECT_FALSE(gearkit::cam::law_from_name("cycloid").has_value());
  EXPECT_EQ(gearkit::cam::law_names().size(), 8u);
}

}  // namespace
