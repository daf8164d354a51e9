// libsynth linkage.hpp: closed-form four-bar and slider-crank positions, the crank's range,
// transmission angles and the defect checks, against libkin's solver, Norton's closed form and
// the law of cosines.
#include "synth_test_support.hpp"

#include <gearkit/kin/fourbar.hpp>
#include <gearkit/synth/linkage.hpp>

#include <gtest/gtest.h>

using namespace gearkit::synth;
using namespace gearkit::synth::testing;

namespace {

// Norton, Design of Machinery, eq. 4.10: the two rocker angles of a four-bar with O2 O4 on x.
std::pair<double, double> norton_theta4(double a, double b, double c, double d, double t2) {
  const double K1 = d / a, K2 = d / c, K3 = (a * a - b * b + c * c + d * d) / (2 * a * c);
  const double A = std::cos(t2) - K1 - K2 * std::cos(t2) + K3, B = -2 * std::sin(t2);
  const double C = K1 - (K2 + 1) * std::cos(t2) + K3;
  const double root = std::sqrt(B * B - 4 * A * C);
  return {2 * std::atan2(-B - root, 2 * A), 2 * std::atan2(-B + root, 2 * A)};
}

double angle_diff(double a, double b) { return std::abs(std::remainder(a - b, 2 * pi)); }

}  // namespace

TEST(Linkage, PoseMatchesTheSolverOfTheReferenceFourBar) {
  const FourBar f = reference_four_bar();
  Driven d = Driven::from_file(std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/four_bar.yaml");
  for (double t : {0.0, 40.0, 135.0, 250.0, 359.0}) {
    ASSERT_TRUE(d.drive_to(t * deg));
    const auto pose = pose_at(f, t * deg);
    ASSERT_TRUE(pose);
    EXPECT_NEAR(pose->P.x(), d.output("Cx"), 1e-9) << t;  // the solver's tolerance is 1e-10 on |Phi|
    EXPECT_NEAR(pose->P.y(), d.output("Cy"), 1e-9) << t;
    EXPECT_NEAR(angle_diff(pose->theta4, d.output("theta4")), 0, 1e-8) << t;
  }
}

TEST(Linkage, BothBranchesAreNortonsTwoRoots) {
  FourBar f = reference_four_bar();
  for (double t : {10.0, 75.0, 200.0}) {
    const auto [open, crossed] = norton_theta4(0.04, 0.12, 0.08, 0.1, t * deg);
    f.branch = 1;
    const double up = pose_at(f, t * deg)->theta4;
    f.branch = -1;
    const double down = pose_at(f, t * deg)->theta4;
    EXPECT_NEAR(std::min(angle_diff(up, open), angle_diff(up, crossed)), 0, 1e-12);
    EXPECT_NEAR(std::min(angle_diff(down, open), angle_diff(down, crossed)), 0, 1e-12);
    EXPECT_GT(angle_diff(up, down), 1e-3);
  }
}

TEST(Linkage, BranchOfIsTheSideOfTheLineAToO4) {
  EXPECT_EQ(branch_of({0, 0}, {1, 1}, {2, 0}), 1);
  EXPECT_EQ(branch_of({0, 0}, {1, -1}, {2, 0}), -1);
  EXPECT_EQ(branch_of({0, 0}, {1, 0}, {2, 0}), 0);
  const FourBar f = reference_four_bar();
  const auto pose = pose_at(f, 1.0);
  EXPECT_EQ(branch_of(pose->A, pose->B, f.O4), f.branch);
}

TEST(Linkage, TransmissionAngleFollowsTheLawOfCosines) {
  const FourBar f = reference_four_bar();
  for (double t : {0.0, 90.0, 180.0, 300.0}) {
    const auto pose = pose_at(f, t * deg);
    const double L2 = (f.O4 - pose->A).squaredNorm(), b = f.coupler, c = f.rocker;
    const double mu = std::acos((b * b + c * c - L2) / (2 * b * c));
    EXPECT_NEAR(transmission_angle(*pose, f), std::min(mu, pi - mu), 1e-12) << t;
  }
  // Extremes at theta2 = 0 and 180 deg: acos((b^2 + c^2 - (d -+ a)^2)/(2bc)).
  const TransmissionRange r = transmission_range(f, 0, 2 * pi, 1);
  EXPECT_NEAR(r.min, std::acos((0.0144 + 0.0064 - 0.06 * 0.06) / (2 * 0.12 * 0.08)), 1e-9);  // 26.4 deg
  EXPECT_NEAR(r.max, std::acos((0.0144 + 0.0064 - 0.14 * 0.14) / (2 * 0.12 * 0.08)), 1e-9);  // 86.4 deg
}

TEST(Linkage, CrankRangeOfAGrashofCrankIsTheFullTurn) {
  const FourBar f = reference_four_bar();
  EXPECT_TRUE(crank_turns_fully(f));
  EXPECT_EQ(gearkit::kin::grashof(0.1, 0.04, 0.12, 0.08).kind, gearkit::kin::GrashofClass::crank_rocker);
}

TEST(Linkage, CrankRangeOfATripleRockerEndsAtItsToggles) {
  FourBar f;  // a = 80, b = 40, c = 50, d = 60 mm: s + l = 120 > p + q = 110
  f.O4 = Vec2(0.06, 0);
  f.crank = 0.08;
  f.coupler = 0.04;
  f.rocker = 0.05;
  EXPECT_FALSE(crank_turns_fully(f));
  const auto ranges = crank_range(f);
  ASSERT_EQ(ranges.size(), 1u);
  for (double end : {ranges[0].start, ranges[0].start + ranges[0].length}) {
    const Vec2 A = f.crank * Vec2(std::cos(end), std::sin(end));
    EXPECT_NEAR((A - f.O4).norm(), f.coupler + f.rocker, 1e-12);  // coupler and rocker in line
  }
  EXPECT_TRUE(pose_at(f, ranges[0].start + 1e-6));
  EXPECT_FALSE(pose_at(f, ranges[0].start - 1e-3));
  EXPECT_FALSE(pose_at(f, ranges[0].start + ranges[0].length + 1e-3));
}

TEST(Linkage, DefectsOrderBranchAndToggle) {
  const FourBar f = reference_four_bar();
  const std::vector<double> ordered{0, 30 * deg, 60 * deg}, shuffled{0, 90 * deg, 45 * deg, 135 * deg};
  EXPECT_TRUE(check_defects(f, ordered, std::vector<int>{1, 1, 1}, true).ok());
  EXPECT_EQ(check_defects(f, ordered, std::vector<int>{1, 1, 1}, true).direction, 1);
  EXPECT_NEAR(check_defects(f, ordered, std::vector<int>{1, 1, 1}, true).travel, 60 * deg, 1e-12);
  EXPECT_TRUE(check_defects(f, shuffled, std::vector<int>{1, 1, 1, 1}, false).order_defect);
  EXPECT_TRUE(check_defects(f, ordered, std::vector<int>{1, -1, 1}, false).branch_defect);
  // Turning clockwise reaches 0, -30, -60 deg in order.
  EXPECT_EQ(check_defects(f, std::vector<double>{0, -30 * deg, -60 * deg}, std::vector<int>{1, 1, 1}, false).direction, -1);
  FourBar rocker;  // triple rocker of the previous test: 0 -> 180 deg crosses its toggle
  rocker.O4 = Vec2(0.06, 0);
  rocker.crank = 0.08;
  rocker.coupler = 0.04;
  rocker.rocker = 0.05;
  const auto r = check_defects(rocker, std::vector<double>{10 * deg, 60 * deg}, std::vector<int>{1, 1}, true);
  EXPECT_TRUE(r.grashof_defect);
  EXPECT_FALSE(r.notes.empty());
}

TEST(Linkage, SliderPositionKeepsTheRodLength) {
  SliderCrank k;
  k.crank = 0.05;
  k.rod = 0.2;
  k.offset = 0.02;
  for (double t : {0.0, 70.0, 180.0, 290.0}) {
    const double s = *slider_position(k, t * deg);
    const Vec2 A = k.crank * Vec2(std::cos(t * deg), std::sin(t * deg)), B(s, k.offset);
    EXPECT_NEAR((B - A).norm(), k.rod, 1e-12) << t;
    EXPECT_GT(s, A.x());
  }
  k.rod = 0.01;  // cannot reach the guide at theta2 = -90 deg
  EXPECT_FALSE(slider_position(k, -pi / 2));
  EXPECT_NEAR(wrap_two_pi(-0.5), 2 * pi - 0.5, 1e-15);
}
