// Tests of gearkit/cam/motion_program.hpp: the OTM 2015 problem 2 table, derivatives, tables,
// continuity warnings and the validation of programs.
#include <gearkit/cam/motion_program.hpp>

#include "cam_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using namespace gearkit::cam;
using gearkit::cam::testing::dwell;
using gearkit::cam::testing::move;
using gearkit::cam::testing::rad;

constexpr double pi = std::numbers::pi;

TEST(MotionProgram, Otm2015Problem2TableOfFollowerAngles) {
  // Seed 000_bc94d104a9983772.txt, OTM 2015 problem 2, part b: psi [deg] against theta [deg],
  // printed to two decimals.
  const MotionProgram p = gearkit::cam::testing::otm2015_program();
  const double theta[] = {0, 120, 130, 140, 150, 160, 170, 180, 240, 260, 280, 300, 320, 340, 360};
  const double psi[] = {0, 0, 1.65, 11.20, 28.65, 46.09, 55.64, 57.30, 57.30, 55.64, 46.09, 28.65, 11.20, 1.65, 0};
  for (std::size_t i = 0; i < std::size(theta); ++i) {
    EXPECT_NEAR(p.at(rad(theta[i])).s * 180 / pi, psi[i], 0.005 + 1e-9) << "theta = " << theta[i];
  }
}

TEST(MotionProgram, Otm2015Problem2AnalyticExpressionsAndTrueDerivatives) {
  // Part a of the seed's solution: rise Psi = 3/pi (theta - 2pi/3) - 1/(2pi) sin(6 (theta - 2pi/3)),
  // Psi' = 3/pi [1 - cos(6 (theta - 2pi/3))]; return Psi = 1 - 3/(2pi)(theta - 4pi/3)
  // + 1/(2pi) sin(3 (theta - 4pi/3)). The solution prints the return's derivative as
  // -3/(2pi) [1 - 3/(2pi) cos(...)], a typo: differentiating its own Psi gives
  // Psi' = -3/(2pi) [1 - cos(3 (theta - 4pi/3))], which is what the follower does.
  const MotionProgram p = gearkit::cam::testing::otm2015_program();
  for (double deg = 121; deg < 180; deg += 7) {
    const double t = rad(deg) - 2 * pi / 3;
    EXPECT_NEAR(p.at(rad(deg)).s, 3 / pi * t - std::sin(6 * t) / (2 * pi), 1e-12);
    EXPECT_NEAR(p.at(rad(deg)).ds, 3 / pi * (1 - std::cos(6 * t)), 1e-12);
  }
  bool typo_differs = false;
  for (double deg = 241; deg < 360; deg += 7) {
    const double t = rad(deg) - 4 * pi / 3;
    EXPECT_NEAR(p.at(rad(deg)).s, 1 - 3 / (2 * pi) * t + std::sin(3 * t) / (2 * pi), 1e-12);
    const double true_derivative = -3 / (2 * pi) * (1 - std::cos(3 * t));
    const double printed = -3 / (2 * pi) * (1 - 3 / (2 * pi) * std::cos(3 * t));
    EXPECT_NEAR(p.at(rad(deg)).ds, true_derivative, 1e-12);
    typo_differs = typo_differs || std::abs(printed - true_derivative) > 1e-3;
  }
  EXPECT_TRUE(typo_differs);
}

TEST(MotionProgram, DerivativesMatchFiniteDifferencesAcrossTheTurn) {
  const MotionProgram p({move(SegmentKind::rise, 10, 100, Law::modified_sine, 12), dwell(100, 150),
                         move(SegmentKind::fall, 150, 250, Law::polynomial_4567, 7),
                         move(SegmentKind::fall, 250, 300, Law::cycloidal, 5), dwell(300, 370)});
  const double h = 1e-6;
  for (double deg = 15; deg < 370; deg += 9.7) {
    const double t = rad(deg);
    const Motion a = p.at(t - h), b = p.at(t + h), c = p.at(t);
    EXPECT_NEAR((b.s - a.s) / (2 * h), c.ds, 1e-5) << deg;
    EXPECT_NEAR((b.ds - a.ds) / (2 * h), c.d2s, 1e-4) << deg;
    EXPECT_NEAR((b.d2s - a.d2s) / (2 * h), c.d3s, 1e-2) << deg;
  }
  // Angles outside [start, start + 360 deg) wrap.
  EXPECT_DOUBLE_EQ(p.at(rad(50)).s, p.at(rad(50 + 360)).s);
  EXPECT_DOUBLE_EQ(p.at(rad(5)).s, p.at(rad(365)).s);
}

TEST(MotionProgram, PerSecondScalesByPowersOfTheSpeed) {
  const Motion m{2, 3, 5, 7};
  const MotionPerSecond s = per_second(m, 10);
  EXPECT_DOUBLE_EQ(s.s, 2);
  EXPECT_DOUBLE_EQ(s.v, 30);
  EXPECT_DOUBLE_EQ(s.a, 500);
  EXPECT_DOUBLE_EQ(s.j, 7000);
}

TEST(MotionProgram, TableIsInterpolatedByACubicSplineThroughItsPoints) {
  Segment t;
  t.kind = SegmentKind::table;
  t.start = 0, t.end = rad(150);
  for (auto [deg, s] : {std::pair{0.0, 0.0}, {30.0, 1.5}, {60.0, 6.0}, {90.0, 11.0}, {120.0, 14.5}, {150.0, 16.0}})
    t.table.push_back({rad(deg), s});
  const MotionProgram p({t, dwell(150, 210), move(SegmentKind::fall, 210, 360, Law::cycloidal, 16)});
  for (const TablePoint& q : t.table) EXPECT_NEAR(p.at(q.theta).s, q.s, 1e-12);
  // Zero-slope ends, and C2 inside: velocity and acceleration continuous at the inner knots.
  EXPECT_NEAR(p.at(0).ds, 0, 1e-12);
  EXPECT_NEAR(p.left_limit(0).ds, 0, 1e-12);
  const double h = 1e-9;
  for (double deg : {30.0, 60.0, 90.0, 120.0}) {
    EXPECT_NEAR(p.at(rad(deg) - h).ds, p.at(rad(deg) + h).ds, 1e-6);
    EXPECT_NEAR(p.at(rad(deg) - h).d2s, p.at(rad(deg) + h).d2s, 1e-6);
  }
  // A straight-line table stays straight with natural ends (the spline reproduces linear data).
  Segment line = t;
  line.table_ends = TableEnds::natural;
  for (TablePoint& q : line.table) q.s = 10 * q.theta;
  const MotionProgram straight({line, move(SegmentKind::fall, 150, 360, Law::cycloidal, 10 * rad(150))});
  EXPECT_NEAR(straight.at(rad(45)).s, 10 * rad(45), 1e-12);
  EXPECT_NEAR(straight.at(rad(45)).d2s, 0, 1e-9);
}

TEST(MotionProgram, PeriodicTableIsSmoothAcrossTheWrap) {
  Segment t;
  t.kind = SegmentKind::table;
  t.table_ends = TableEnds::periodic;
  t.start = 0, t.end = 2 * pi;
  for (int k = 0; k <= 12; ++k) t.table.push_back({2 * pi * k / 12, 5 + 5 * std::sin(2 * pi * k / 12)});
  t.table.back().s = t.table.front().s;
  const MotionProgram p({t});
  const Motion before = p.left_limit(0), after = p.at(0);
  EXPECT_NEAR(before.s, after.s, 1e-12);
  EXPECT_NEAR(before.ds, after.ds, 1e-9);
  EXPECT_NEAR(before.d2s, after.d2s, 1e-9);
  // Sampled sine: the spline follows 5 + 5 sin(theta) closely between the knots.
  EXPECT_NEAR(p.at(rad(45)).s, 5 + 5 * std::sin(rad(45)), 0.01);
  EXPECT_TRUE(continuity_check(p).empty());
}

TEST(MotionProgram, ContinuityCheckFlagsAccelerationJumpsOfHarmonicAndNotOfCycloidal) {
  EXPECT_TRUE(continuity_check(gearkit::cam::testing::rise_dwell_return(20, Law::cycloidal)).empty());
  const auto jumps = continuity_check(gearkit::cam::testing::rise_dwell_return(20, Law::simple_harmonic));
  // Simple harmonic starts and ends with acceleration +-pi^2/2 L/beta^2: four jumps at 0, 120, 180, 300 deg.
  ASSERT_EQ(jumps.size(), 4u);
  for (const JoinJump& j : jumps) EXPECT_EQ(j.quantity, "acceleration");
  const double beta = rad(120);
  EXPECT_NEAR(std::abs(jumps[0].before - jumps[0].after), pi * pi / 2 * 20 / (beta * beta), 1e-9);
  const auto uv = continuity_check(gearkit::cam::testing::rise_dwell_return(20, Law::uniform_velocity));
  bool velocity = false;
  for (const JoinJump& j : uv) velocity = velocity || j.quantity == "velocity";
  EXPECT_TRUE(velocity);
}

int error_segment(std::vector<Segment> segments) {
  try {
    MotionProgram p(std::move(segments));
  } catch (const ProgramError& e) {
    return e.segment();
  }
  return -100;
}

TEST(MotionProgram, RejectsBadPrograms) {
  // Gap, overlap, short of 360 deg, zero duration, no lift, return below the base, no return.
  EXPECT_EQ(error_segment({move(SegmentKind::rise, 0, 100, Law::cycloidal, 10), dwell(110, 200),
                           move(SegmentKind::fall, 200, 360, Law::cycloidal, 10)}),
            1);
  EXPECT_EQ(error_segment({move(SegmentKind::rise, 0, 100, Law::cycloidal, 10), dwell(90, 200),
                           move(SegmentKind::fall, 200, 360, Law::cycloidal, 10)}),
            1);
  EXPECT_EQ(error_segment({move(SegmentKind::rise, 0, 100, Law::cycloidal, 10),
                           move(SegmentKind::fall, 100, 350, Law::cycloidal, 10)}),
            -1);
  EXPECT_EQ(error_segment({dwell(0, 0), move(SegmentKind::rise, 0, 180, Law::cycloidal, 10),
                           move(SegmentKind::fall, 180, 360, Law::cycloidal, 10)}),
            0);
  EXPECT_EQ(error_segment({dwell(0, 100), move(SegmentKind::rise, 100, 100, Law::cycloidal, 10),
                           move(SegmentKind::fall, 100, 360, Law::cycloidal, 10)}),
            1);
  EXPECT_EQ(error_segment({move(SegmentKind::rise, 0, 180, Law::cycloidal, -5),
                           move(SegmentKind::fall, 180, 360, Law::cycloidal, -5)}),
            0);
  EXPECT_EQ(error_segment({move(SegmentKind::rise, 0, 180, Law::cycloidal, 5),
                           move(SegmentKind::fall, 180, 360, Law::cycloidal, 6)}),
            1);
  EXPECT_EQ(error_segment({move(SegmentKind::rise, 0, 180, Law::cycloidal, 5), dwell(180, 360)}), -1);
  EXPECT_EQ(error_segment({}), -1);
  EXPECT_EQ(error_segment({dwell(0, 360)}), -100);  // a plain circle is a valid (if dull) cam
}

}  // namespace
