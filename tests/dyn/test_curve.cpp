// Tests of gearkit/dyn/curve.hpp: exact integrals of piecewise-linear torque diagrams.
#include <gearkit/dyn/curve.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

using gearkit::dyn::PiecewiseLinear;
constexpr double pi = std::numbers::pi;

TEST(Curve, TriangleValuesAndArea) {
  // The seed's triangular resisting torque (000_bc94d104a9983772.txt, OTM 2015 problem 4):
  // zero up to 90 deg, peak at 180 deg, back to zero at 360 deg; area = peak * (3 pi / 2) / 2.
  const PiecewiseLinear t({0, pi / 2, pi, 2 * pi}, {0, 0, 1, 0}, true);
  EXPECT_DOUBLE_EQ(t(0.75 * pi), 0.5);
  EXPECT_DOUBLE_EQ(t(1.5 * pi), 0.5);
  EXPECT_NEAR(t.integral(0, 2 * pi), 0.75 * pi, 1e-14);
  EXPECT_NEAR(t.mean(), 0.375, 1e-15);
  // Periodic: any interval, several periods, reversed limits.
  EXPECT_NEAR(t.integral(-2 * pi, 4 * pi), 3 * 0.75 * pi, 1e-13);
  EXPECT_NEAR(t.integral(pi, 0), -(0.5 * pi / 2), 1e-14);
  EXPECT_NEAR(t(2 * pi + 0.75 * pi), 0.5, 1e-14);
  EXPECT_NEAR(t(-1.25 * pi), 0.5, 1e-14);  // same as 0.75 pi
}

TEST(Curve, StepTakesRightValueAndLeftLimit) {
  // A sawtooth: rises from 0 to 10 over [0, 1], drops back at x = 1, zero until 2.
  const PiecewiseLinear s({0, 1, 1, 2}, {0, 10, 0, 0}, true);
  EXPECT_DOUBLE_EQ(s(1), 0);
  EXPECT_DOUBLE_EQ(s.left_value(1), 10);
  EXPECT_DOUBLE_EQ(s(0.5), 5);
  EXPECT_DOUBLE_EQ(s.integral(0, 2), 5);
  EXPECT_DOUBLE_EQ(s.integral(0.5, 1.5), 3.75);
}

TEST(Curve, NonPeriodicHoldsEndValues) {
  const PiecewiseLinear f({1, 3}, {2, 4}, false);
  EXPECT_DOUBLE_EQ(f(0), 2);
  EXPECT_DOUBLE_EQ(f(5), 4);
  EXPECT_DOUBLE_EQ(f.integral(0, 1), 2);
  EXPECT_DOUBLE_EQ(f.integral(3, 5), 8);
  EXPECT_DOUBLE_EQ(f.integral(1, 3), 6);
}

TEST(Curve, ScaledAndStretched) {
  const PiecewiseLinear t({0, 1, 2}, {0, 1, 0}, true);
  EXPECT_DOUBLE_EQ(t.scaled(3)(1), 3);
  const PiecewiseLinear w = t.stretched(2);
  EXPECT_DOUBLE_EQ(w(2), 1);
  EXPECT_DOUBLE_EQ(w.integral(0, 4), 2);
  EXPECT_THROW(t.stretched(0), std::invalid_argument);
}

TEST(Curve, DifferenceKeepsStepsAndCrossings) {
  const PiecewiseLinear d = gearkit::dyn::difference(PiecewiseLinear::constant(2, 0, 2),
                                                     PiecewiseLinear({0, 1, 1, 2}, {0, 4, 0, 0}, true));
  EXPECT_DOUBLE_EQ(d(0.5), 0);
  EXPECT_DOUBLE_EQ(d.left_value(1), -2);
  EXPECT_DOUBLE_EQ(d(1), 2);
  EXPECT_DOUBLE_EQ(d.integral(0, 2), 4 - 2);
}

TEST(Curve, DifferenceOfCurvesWithAStepAtTheStart) {
  const PiecewiseLinear f({0, 0, 1, 2}, {0, 5, 5, 0}, true);
  const PiecewiseLinear d = gearkit::dyn::difference(f, PiecewiseLinear::constant(1, 0, 2));
  EXPECT_DOUBLE_EQ(d(0), 4);
  EXPECT_DOUBLE_EQ(d.integral(0, 2), f.integral(0, 2) - 2);
}

TEST(Curve, SampleIsExactAtNodes) {
  const auto s = gearkit::dyn::sample([](double x) { return std::sin(x); }, 0, 2 * pi, 360, true);
  EXPECT_NEAR(s(pi / 2), 1, 1e-15);
  // Trapezoid error bound for sin: (b - a) h^2 / 12 * max|f''|.
  EXPECT_NEAR(s.integral(0, pi), 2, pi * std::pow(2 * pi / 360, 2) / 12);
}

TEST(Curve, BadTablesAreRejected) {
  using V = std::vector<double>;
  EXPECT_THROW(PiecewiseLinear(V{0}, V{1}, false), std::invalid_argument);
  EXPECT_THROW(PiecewiseLinear(V{0, 1}, V{1}, false), std::invalid_argument);
  EXPECT_THROW(PiecewiseLinear(V{0, 2, 1}, V{0, 0, 0}, false), std::invalid_argument);
  EXPECT_THROW(PiecewiseLinear(V{0, 1, 1, 1}, V{0, 0, 0, 0}, false), std::invalid_argument);
  EXPECT_THROW(PiecewiseLinear(V{1, 1}, V{0, 0}, false), std::invalid_argument);
  EXPECT_THROW(PiecewiseLinear(V{0, NAN}, V{0, 0}, false), std::invalid_argument);
  try {
    PiecewiseLinear(V{0, 1, 2}, V{0, 5, 3}, true);
    FAIL() << "a torque table whose ends differ is not periodic";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not periodic"), std::string::npos) << e.what();
  }
  EXPECT_THROW(gearkit::dyn::difference(PiecewiseLinear::constant(1, 0, 1), PiecewiseLinear::constant(1, 0, 2)),
               std::invalid_argument);
  EXPECT_THROW(gearkit::dyn::sample([](double) { return NAN; }, 0, 1, 4, false), std::invalid_argument);
}
