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
  t.interpolation = TableInterpolation::cubic;
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
  t.interpolation = TableInterpolation::cubic;
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
  // A cubic spline is C2: only the jerk jumps, at its knots.
  for (const JoinJump& j : continuity_check(p)) EXPECT_EQ(j.quantity, "jerk");
}

std::vector<JoinJump> only(const std::vector<JoinJump>& jumps, const std::string& quantity) {
  std::vector<JoinJump> out;
  for (const JoinJump& j : jumps)
    if (j.quantity == quantity) out.push_back(j);
  return out;
}

TEST(MotionProgram, ContinuityCheckFlagsAccelerationJumpsOfHarmonicAndNotOfCycloidal) {
  const double beta = rad(120);
  // Cycloidal: s, v, a continuous; the jerk jumps by 4 pi^2 L / beta^3 where it meets a dwell
  // (y''' = 4 pi^2 cos(2 pi u), Norton, Design of Machinery, eq. 8.14).
  const auto cycloidal = continuity_check(gearkit::cam::testing::rise_dwell_return(20, Law::cycloidal));
  ASSERT_EQ(cycloidal.size(), 4u);
  for (const JoinJump& j : cycloidal) {
    EXPECT_EQ(j.quantity, "jerk");
    EXPECT_NEAR(std::abs(j.before - j.after), 4 * pi * pi * 20 / (beta * beta * beta), 1e-9);
  }
  const auto jumps = only(continuity_check(gearkit::cam::testing::rise_dwell_return(20, Law::simple_harmonic)),
                          "acceleration");
  // Simple harmonic starts and ends with acceleration +-pi^2/2 L/beta^2: four jumps at 0, 120, 180, 300 deg.
  ASSERT_EQ(jumps.size(), 4u);
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

namespace {

Segment table(std::vector<std::pair<double, double>> deg_s, TableInterpolation how,
              TableEnds ends = TableEnds::zero_slope) {
  Segment t;
  t.kind = SegmentKind::table;
  t.interpolation = how;
  t.table_ends = ends;
  t.start = rad(deg_s.front().first), t.end = rad(deg_s.back().first);
  for (auto [d, s] : deg_s) t.table.push_back({rad(d), s});
  return t;
}

std::string program_error(std::vector<Segment> segments) {
  try {
    MotionProgram p(std::move(segments), {"mm", 1});
  } catch (const ProgramError& e) {
    return e.what();
  }
  return "";
}

// The table of issue 18: a cubic spline through [[0,0],[20,0],[40,0],[50,20],[120,20]] mm dips to
// about -4.7 mm near 32.5 deg (the cam would cut into its own base circle).
const std::vector<std::pair<double, double>> kIssueTable{{0, 0}, {20, 0}, {40, 0}, {50, 20}, {120, 20}};

TEST(MotionProgram, CubicTableThatDipsBelowTheBaseCircleIsRefusedWithTheValue) {
  const std::string msg = program_error({table(kIssueTable, TableInterpolation::cubic),
                                         move(SegmentKind::fall, 120, 360, Law::cycloidal, 20)});
  EXPECT_NE(msg.find("below the base circle"), std::string::npos) << msg;
  EXPECT_NE(msg.find("dips to s = -4.6"), std::string::npos) << msg;
  EXPECT_NE(msg.find(" mm at cam angle 3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("pchip"), std::string::npos) << msg;
}

TEST(MotionProgram, PchipTableStaysBetweenItsPointsAndIsMonotoneWhereTheyAre) {
  const MotionProgram p({table(kIssueTable, TableInterpolation::pchip),
                         move(SegmentKind::fall, 120, 360, Law::cycloidal, 20)});
  double prev = 0;
  for (int i = 0; i <= 12000; ++i) {
    const double theta = rad(120.0 * i / 12000);
    const Motion m = p.at(theta);
    EXPECT_GE(m.s, 0);
    EXPECT_LE(m.s, 20);
    EXPECT_GE(m.s, prev - 1e-12);  // non-decreasing data, non-decreasing curve
    prev = m.s;
  }
  for (auto [d, s] : kIssueTable) EXPECT_NEAR(p.at(rad(d)).s, s, 1e-12);
  EXPECT_TRUE(table_overshoots(p).empty());
}

TEST(MotionProgram, PchipSlopesAreFritschButlandHarmonicMeans) {
  // Points (0, 0), (1, 1), (2, 3) in rad: secants 1 and 2, equal widths, so the inner slope is
  // (w1 + w2) / (w1/1 + w2/2) with w1 = w2 = 3: 4/3 (Fritsch & Butland 1984, eq. 3.4).
  Segment t;
  t.kind = SegmentKind::table;
  t.start = 0, t.end = 2;
  t.table = {{0, 0}, {1, 1}, {2, 3}};
  const MotionProgram p({t, move(SegmentKind::fall, 2 * 180 / pi, 360, Law::cycloidal, 3)});
  EXPECT_NEAR(p.at(1).ds, 4.0 / 3.0, 1e-12);
  EXPECT_NEAR(p.at(0).ds, 0, 1e-12);  // zero_slope ends
  // Hermite cubic on [0, 1] with slopes 0 and 4/3: s(0.5) = 1/2 + (0 - 4/3)/8 = 1/3.
  EXPECT_NEAR(p.at(0.5).s, 0.5 - (4.0 / 3.0) / 8, 1e-12);
}

TEST(MotionProgram, CubicTableOvershootIsReported) {
  // Still rising at 60 deg, the C2 spline overshoots the top value between 60 and 120 deg.
  const MotionProgram p({table({{0, 0}, {30, 10}, {60, 20}, {120, 20}}, TableInterpolation::cubic),
                         move(SegmentKind::fall, 120, 360, Law::cycloidal, 20)});
  const auto over = table_overshoots(p);
  ASSERT_FALSE(over.empty());
  EXPECT_GT(over.front().s, 20);
  EXPECT_EQ(over.front().limit, 20);
  EXPECT_NEAR(p.at(over.front().theta).s, over.front().s, 1e-12);
}

TEST(MotionProgram, PolynomialFromSixConditionsIsThe345Law) {
  // s, v, a given at both ends (0 and lift, v = a = 0): the unique quintic is the 3-4-5
  // polynomial (Norton, Design of Machinery, sec. 8.6), and with j = 0 too the 4-5-6-7.
  for (bool with_jerk : {false, true}) {
    Segment poly;
    poly.kind = SegmentKind::polynomial;
    poly.start = 0, poly.end = rad(90);
    poly.at_start = {std::nullopt, 0.0, 0.0, with_jerk ? std::optional<double>(0.0) : std::nullopt};
    poly.at_end = {15.0, 0.0, 0.0, with_jerk ? std::optional<double>(0.0) : std::nullopt};
    const MotionProgram p({poly, dwell(90, 180), move(SegmentKind::fall, 180, 360, Law::cycloidal, 15)});
    const Law law = with_jerk ? Law::polynomial_4567 : Law::polynomial_345;
    const MotionProgram reference({move(SegmentKind::rise, 0, 90, law, 15), dwell(90, 180),
                                   move(SegmentKind::fall, 180, 360, Law::cycloidal, 15)});
    for (int i = 0; i <= 90; ++i) {
      const Motion a = p.at(rad(i)), b = reference.at(rad(i));
      EXPECT_NEAR(a.s, b.s, 1e-11);
      EXPECT_NEAR(a.ds, b.ds, 1e-10);
      EXPECT_NEAR(a.d2s, b.d2s, 1e-9);
      EXPECT_NEAR(a.d3s, b.d3s, 1e-8);
    }
  }
}

TEST(MotionProgram, PolynomialWithAGapInItsConditionsOrDippingBelowTheBaseIsRefused) {
  Segment poly;
  poly.kind = SegmentKind::polynomial;
  poly.start = 0, poly.end = rad(90);
  poly.at_start = {0.0, std::nullopt, 0.0, std::nullopt};  // a without v
  poly.at_end = {15.0, 0.0, std::nullopt, std::nullopt};
  const auto rest = move(SegmentKind::fall, 90, 360, Law::cycloidal, 15);
  EXPECT_NE(program_error({poly, rest}).find("skip an order"), std::string::npos);
  poly.at_start = {0.0, -20.0, std::nullopt, std::nullopt};  // starts downwards
  const std::string msg = program_error({poly, rest});
  EXPECT_NE(msg.find("below the base circle"), std::string::npos) << msg;
  poly.at_start = {2.0, 0.0, std::nullopt, std::nullopt};  // not where the follower is
  EXPECT_NE(program_error({poly, rest}).find("starts at s = 2 mm"), std::string::npos);
  poly.at_start = {0.0, 0.0, std::nullopt, std::nullopt};
  poly.at_end = {std::nullopt, 0.0, std::nullopt, std::nullopt};
  EXPECT_NE(program_error({poly, rest}).find("end value"), std::string::npos);
}

TEST(MotionProgram, BsplineTableIsSmoothStaysInRangeAndLeavesTheDwellsGently) {
  const MotionProgram p({table(kIssueTable, TableInterpolation::bspline),
                         move(SegmentKind::fall, 120, 360, Law::cycloidal, 20)});
  // C4 inside: no jump of s, v, a or jerk anywhere in the table, nor where it meets the
  // dwell-like ends (zero_slope: v = a = j = 0 at both ends); only the cycloidal return's
  // jerk jumps.
  for (const JoinJump& j : continuity_check(p)) EXPECT_EQ(j.quantity, "jerk");
  for (const JoinJump& j : continuity_check(p)) EXPECT_TRUE(j.join || j.segment != 0) << j.theta;
  EXPECT_NEAR(p.at(0).ds, 0, 1e-12);
  EXPECT_NEAR(p.at(0).d2s, 0, 1e-9);
  EXPECT_NEAR(p.left_limit(0).ds, 0, 1e-12);
  EXPECT_NEAR(p.left_limit(0).d2s, 0, 1e-9);
  // Variation diminishing: within the points' range and monotone like them.
  double prev = 0;
  for (int i = 0; i <= 6000; ++i) {
    const double s = p.at(rad(120.0 * i / 6000)).s;
    EXPECT_GE(s, -1e-12);
    EXPECT_LE(s, 20 + 1e-12);
    EXPECT_GE(s, prev - 1e-12);
    prev = s;
  }
  // It approximates, it does not interpolate: the report states how far it passes from the points.
  EXPECT_GT(table_fit_residual(p, 0), 0.1);
  // Derivatives agree with central differences of s.
  for (double d : {25.0, 45.0, 47.5, 60.0, 90.0}) {
    const double h = 1e-5, t = rad(d);
    const Motion m = p.at(t), a = p.at(t - h), b = p.at(t + h);
    EXPECT_NEAR(m.ds, (b.s - a.s) / (2 * h), 1e-6 * std::max(1.0, std::abs(m.ds)));
    EXPECT_NEAR(m.d2s, (b.ds - a.ds) / (2 * h), 1e-5 * std::max(1.0, std::abs(m.d2s)));
    EXPECT_NEAR(m.d3s, (b.d2s - a.d2s) / (2 * h), 1e-4 * std::max(1.0, std::abs(m.d3s)));
  }
}

TEST(MotionProgram, ParabolicAccelerationJumpAtHalfRiseIsFound) {
  // Constant acceleration +4 L/beta^2 then -4 L/beta^2 (Norton, eq. 8.3): a jump of 8 L/beta^2
  // in the middle of the rise, not only where the rise meets the dwells.
  const auto jumps = only(continuity_check(gearkit::cam::testing::rise_dwell_return(20, Law::parabolic)),
                          "acceleration");
  const double beta = rad(120);
  bool inside = false;
  for (const JoinJump& j : jumps) {
    if (j.join) continue;
    inside = true;
    EXPECT_NEAR(j.theta, rad(60), 1e-12);
    EXPECT_NEAR(j.before - j.after, 8 * 20 / (beta * beta), 1e-9);
    break;
  }
  EXPECT_TRUE(inside);
}

TEST(MotionProgram, MessagesCarryTheFollowerUnit) {
  const std::string msg = program_error({move(SegmentKind::rise, 0, 180, Law::cycloidal, 5),
                                         move(SegmentKind::fall, 180, 360, Law::cycloidal, 10)});
  EXPECT_NE(msg.find("goes 5 mm below"), std::string::npos) << msg;
}

}  // namespace
