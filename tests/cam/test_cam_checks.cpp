// Tests of gearkit/cam/cam_checks.hpp: extremes and where they occur, undercut, smallest base
// circle (closed form cross-checked by evaluating the design it returns).
#include <gearkit/cam/cam_checks.hpp>

#include "cam_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace gearkit::cam;
using gearkit::cam::testing::oscillating;
using gearkit::cam::testing::rad;
using gearkit::cam::testing::translating;

double max_abs_pressure_angle(const CamDesign& d, int n = 7200) {
  double worst = 0;
  for (int i = 0; i < n; ++i) worst = std::max(worst, std::abs(contact_at(d, 2 * M_PI * i / n).pressure_angle));
  return worst;
}

TEST(CamChecks, RadialRollerCycloidalPressureAngleAndCurvature) {
  const CamDesign d{gearkit::cam::testing::rise_dwell_return(20), translating(Contact::roller, 10), 40, Rotation::ccw};
  validate(d);
  const CamChecks c = check_design(d, {3600, rad(30)});
  // Independent brute force of tan(phi) = s' / (Rp + s) (radial follower, Norton eq. 8.31).
  double worst = 0, at = 0;
  for (int i = 0; i < 36000; ++i) {
    const double t = 2 * M_PI * i / 36000;
    const Motion m = d.program.at(t);
    const double phi = std::atan(m.ds / (50 + m.s));
    if (std::abs(phi) > worst) worst = std::abs(phi), at = t;
  }
  EXPECT_NEAR(std::abs(c.pressure_angle_max.value), worst, 1e-5);
  EXPECT_NEAR(std::remainder(c.pressure_angle_max.theta - at, 2 * M_PI), 0, rad(0.2));
  EXPECT_FALSE(c.pressure_angle_exceeded);
  EXPECT_FALSE(c.undercut);
  // The base dwell (radius 50 pitch, 40 profile) is convex; the rise is flatter than the base here.
  EXPECT_LE(c.rho_pitch_min.value, 50 + 1e-9);
  EXPECT_NEAR(c.rho_profile_min.value, c.rho_pitch_min.value - 10, 1e-9);
  EXPECT_EQ(c.samples.size(), 3600u);
}

TEST(CamChecks, UndercutWhenTheRollerExceedsThePitchCurvesRadius) {
  // A steep rise on a small cam: find the pitch curve's smallest convex radius with a small
  // roller, then ask for a roller larger than it.
  const auto program = MotionProgram({gearkit::cam::testing::move(SegmentKind::rise, 0, 45, Law::cycloidal, 30),
                                      gearkit::cam::testing::move(SegmentKind::fall, 45, 90, Law::cycloidal, 30),
                                      gearkit::cam::testing::dwell(90, 360)});
  const CamDesign small{program, translating(Contact::roller, 2), 30, Rotation::ccw};
  validate(small);
  const CamChecks ok = check_design(small, {3600, rad(30)});
  ASSERT_TRUE(std::isfinite(ok.rho_pitch_min.value));
  EXPECT_FALSE(ok.undercut);
  // Growing the roller by dr and shrinking the base circle by dr keeps the pitch curve.
  const double big_roller = ok.rho_pitch_min.value + 1;
  const CamDesign big{program, translating(Contact::roller, big_roller), 32 - big_roller, Rotation::ccw};
  ASSERT_GE(big.base_radius, big_roller);
  validate(big);
  const CamChecks bad = check_design(big, {3600, rad(30)});
  EXPECT_NEAR(bad.rho_pitch_min.value, ok.rho_pitch_min.value, 1e-9);
  EXPECT_TRUE(bad.undercut);
  EXPECT_NEAR(bad.rho_profile_min.value, -1, 1e-9);
  EXPECT_FALSE(bad.undercut_ranges.empty());
}

TEST(CamChecks, SmallestBaseRadiusMeetsThePressureAngleLimitExactly) {
  for (double offset : {0.0, 8.0}) {
    const CamDesign d{gearkit::cam::testing::rise_dwell_return(25), translating(Contact::roller, 10, offset), 40,
                      Rotation::cw};
    validate(d);
    const double rb = smallest_base_radius(d, rad(25), 7200);
    CamDesign at_limit = d;
    at_limit.base_radius = rb;
    validate(at_limit);
    EXPECT_NEAR(max_abs_pressure_angle(at_limit), rad(25), rad(0.01)) << offset;
    at_limit.base_radius = rb * 0.97;
    EXPECT_GT(max_abs_pressure_angle(at_limit), rad(25)) << offset;
  }
}

TEST(CamChecks, SmallestBaseRadiusForAnOscillatingFollowerByBisection) {
  const CamDesign d{MotionProgram({gearkit::cam::testing::move(SegmentKind::rise, 0, 120, Law::cycloidal, rad(20)),
                                   gearkit::cam::testing::dwell(120, 180),
                                   gearkit::cam::testing::move(SegmentKind::fall, 180, 300, Law::cycloidal, rad(20)),
                                   gearkit::cam::testing::dwell(300, 360)}),
                    oscillating(Contact::roller, 150, 110, 10), 40, Rotation::ccw};
  validate(d);
  const double rb = smallest_base_radius(d, rad(30), 1440);
  CamDesign at_limit = d;
  at_limit.base_radius = rb;
  EXPECT_LE(max_abs_pressure_angle(at_limit), rad(30) + rad(0.05));
  at_limit.base_radius = rb * 0.95;
  EXPECT_GT(max_abs_pressure_angle(at_limit), rad(30));
}

TEST(CamChecks, FlatFaceWidthAndConvexity) {
  const CamDesign d{gearkit::cam::testing::rise_dwell_return(15, Law::polynomial_345), translating(Contact::flat_face),
                    30, Rotation::ccw};
  validate(d);
  const CamChecks c = check_design(d, {3600, rad(30)});
  // The contact runs over +-max|s'|: 3-4-5 peak velocity 1.875 L / beta.
  const double vmax = 1.875 * 15 / rad(120);
  EXPECT_NEAR(c.face_max, vmax, 1e-3);
  EXPECT_NEAR(c.face_min, -vmax, 1e-3);
  // Convex iff Rb > max(-(s + s'')): the base radius found is that bound.
  double need = 0;
  for (int i = 0; i < 36000; ++i) {
    const Motion m = d.program.at(2 * M_PI * i / 36000);
    need = std::max(need, -(m.s + m.d2s));
  }
  EXPECT_NEAR(c.base_radius_min, need, 1e-3);
  EXPECT_EQ(c.undercut, 30 < need);
}

}  // namespace

namespace {

using namespace gearkit::cam;
using gearkit::cam::testing::rad;
using gearkit::cam::testing::translating;

TEST(CamChecks, FlatFaceSmallestBaseRadiusIsTheSupremumNotASample) {
  // Issue 18: sampled at 0.25 deg the bound came out 4e-4 mm short, so a base "at the limit" was
  // still cusped. The bound sup(-(s + s'')) (Norton, Design of Machinery, eq. 8.31: rho = Rb + s
  // + s'' > 0) must be at least every densely sampled value and a base just above it convex.
  for (Law law : {Law::polynomial_345, Law::cycloidal, Law::modified_sine}) {
    SCOPED_TRACE(std::string(name_of(law)));
    const MotionProgram program({gearkit::cam::testing::move(SegmentKind::rise, 0, 50, law, 15), gearkit::cam::testing::dwell(50, 180),
                                 gearkit::cam::testing::move(SegmentKind::fall, 180, 230, law, 15), gearkit::cam::testing::dwell(230, 360)});
    const CamDesign d{program, translating(Contact::flat_face), 30, Rotation::ccw};
    const double bound = smallest_base_radius(d, rad(30), 720);
    double sampled = 0;
    for (int i = 0; i < 2000000; ++i) {
      const Motion m = program.at(2 * M_PI * i / 2000000);
      sampled = std::max(sampled, -(m.s + m.d2s));
    }
    EXPECT_GE(bound, sampled - 1e-12);
    EXPECT_LT(bound - sampled, 1e-7);
    CamDesign above = d, below = d;
    above.base_radius = bound * (1 + 1e-9);
    below.base_radius = bound * (1 - 1e-6);
    EXPECT_FALSE(check_design(above, {3600, rad(30)}).undercut);
    EXPECT_GT(check_design(above, {3600, rad(30)}).rho_profile_min.value, 0);
    // Just below, the radius of curvature is negative at the critical angle (found, not sampled).
    EXPECT_LT(check_design(below, {3600, rad(30)}).rho_profile_min.value, 0);
  }
}

TEST(CamChecks, FlatFaceCuspNarrowerThanTheSamplesIsAnUndercut) {
  // Issue 18: 4e-7 mm below the exact smallest base circle rho_min was found negative but
  // `undercut` was false and no range was given: the fold lay between the samples. Independent
  // bound: the 3-4-5 rise P(u) = 10u^3 - 15u^4 + 6u^5, P'' = 60u - 180u^2 + 120u^3 (Norton, Design
  // of Machinery, eq. 8.23) gives rho = Rb + L (P + P'' / beta^2) (eq. 8.31) on the rise and, by
  // the symmetry P(1 - u) = 1 - P(u), the same minimum on the return at the mirrored angle.
  const double L = 15, beta = M_PI / 2;
  auto f = [&](double u) { return L * (10 * u * u * u - 15 * std::pow(u, 4) + 6 * std::pow(u, 5)) +
                                  L / (beta * beta) * (60 * u - 180 * u * u + 120 * u * u * u); };
  double u_min = 0, f_min = INFINITY;
  for (int i = 0; i <= 1000000; ++i)
    if (const double u = i / 1e6; f(u) < f_min) f_min = f(u), u_min = u;
  for (double a = u_min - 1e-6, b = u_min + 1e-6; b - a > 1e-15;) {  // golden-section refinement
    const double x1 = b - 0.618034 * (b - a), x2 = a + 0.618034 * (b - a);
    (f(x1) < f(x2) ? b : a) = f(x1) < f(x2) ? x2 : x1;
    u_min = 0.5 * (a + b);
  }
  const double bound = -f(u_min);  // Rb > -(s + s'')
  const MotionProgram program({gearkit::cam::testing::move(SegmentKind::rise, 0, 90, Law::polynomial_345, L),
                               gearkit::cam::testing::dwell(90, 180),
                               gearkit::cam::testing::move(SegmentKind::fall, 180, 270, Law::polynomial_345, L),
                               gearkit::cam::testing::dwell(270, 360)});
  CamDesign d{program, translating(Contact::flat_face), bound - 4e-7, Rotation::cw};
  const CamChecks below = check_design(d, {3600, rad(30)});
  EXPECT_LT(below.rho_profile_min.value, 0);
  EXPECT_TRUE(below.undercut);
  ASSERT_EQ(below.undercut_ranges.size(), 2u);
  const double at[2] = {u_min * 90, 180 + (1 - u_min) * 90};
  for (int k = 0; k < 2; ++k) {
    const ValueAt& r = below.undercut_ranges[k];
    EXPECT_LE(r.theta, rad(at[k]) + 1e-9) << at[k];
    EXPECT_GE(r.value, rad(at[k]) - 1e-9) << at[k];
    EXPECT_LT(r.value - r.theta, rad(0.1));  // narrower than the 0.1 deg sampling
  }
  d.base_radius = bound + 1e-7;
  EXPECT_FALSE(check_design(d, {3600, rad(30)}).undercut);
}

TEST(CamChecks, TranslatingRollerSmallestBaseRadiusIsTheSupremum) {
  // tan(phi) = (s' - e) / (s0 + s) (Norton, eq. 8.29b): with the base radius found, the largest
  // pressure angle found equals the limit to 1e-9 and no dense sample exceeds it.
  const MotionProgram program({gearkit::cam::testing::move(SegmentKind::rise, 0, 70, Law::modified_trapezoid, 25),
                               gearkit::cam::testing::dwell(70, 180), gearkit::cam::testing::move(SegmentKind::fall, 180, 300, Law::cycloidal, 25),
                               gearkit::cam::testing::dwell(300, 360)});
  CamDesign d{program, translating(Contact::roller, 8, 6), 40, Rotation::cw};
  d.base_radius = smallest_base_radius(d, rad(28), 720);
  validate(d);
  const CamChecks c = check_design(d, {3600, rad(28)});
  EXPECT_NEAR(std::abs(c.pressure_angle_max.value), rad(28), 1e-9);
  double sampled = 0;
  for (int i = 0; i < 400000; ++i) sampled = std::max(sampled, std::abs(contact_at(d, 2 * M_PI * i / 400000).pressure_angle));
  EXPECT_LE(sampled, rad(28) + 1e-12);
}

TEST(CamChecks, LargestRadiusOfTheCam) {
  // A radial roller cam: the profile's farthest point is Rb + lift along the top dwell.
  const CamDesign d{gearkit::cam::testing::rise_dwell_return(20), translating(Contact::roller, 10), 40, Rotation::ccw};
  const ValueAt r = largest_radius(d);
  EXPECT_NEAR(r.value, 40 + 20, 1e-9);
  EXPECT_GE(r.theta, rad(120) - 1e-9);
  EXPECT_LE(r.theta, rad(180) + 1e-9);
}

}  // namespace
