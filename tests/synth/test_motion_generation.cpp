// libsynth motion_generation.hpp: Norton's two- and three-position motion synthesis (perpendicular
// bisectors, circumcentres, the inversion for chosen fixed pivots, the analytical dyad equations
// with free choices). The truth is the reference four-bar analysed by libkin: given poses of its
// coupler, each method must give back its pivots; every result is then written as a mechanism
// file and driven by the solver through the poses.
#include "synth_test_support.hpp"

#include <gearkit/synth/mechanism_writer.hpp>
#include <gearkit/synth/motion_generation.hpp>

#include <gtest/gtest.h>

using namespace gearkit::synth;
using namespace gearkit::synth::testing;

namespace {

// The reference linkage's joints in pose 1 (crank at 30 deg): A and B by the closed form.
struct Truth {
  std::vector<Pose> poses;
  Vec2 A1, B1;
};

Truth truth(const std::vector<double>& theta2) {
  Truth t{reference_poses(theta2), {}, {}};
  const auto pose = pose_at(reference_four_bar(), theta2[0]);
  t.A1 = pose->A;
  t.B1 = pose->B;
  return t;
}

// Drives the written mechanism through the poses and returns the largest miss of P [m].
double solver_miss(const MotionCandidate& c, const std::vector<Pose>& poses) {
  Driven d = Driven::from_text(to_mechanism_yaml(four_bar_sketch(c.linkage, c.theta2[0], c.defects.travel, c.defects.direction, "m")));
  double worst = 0;
  for (std::size_t j = 0; j < poses.size(); ++j) {
    const double t = c.theta2[0] + c.defects.direction * wrap_two_pi(c.defects.direction * (c.theta2[j] - c.theta2[0]));
    if (!d.drive_to(t)) return 1;
    worst = std::max(worst, std::hypot(d.output("Px") - poses[j].point.x(), d.output("Py") - poses[j].point.y()));
    const double coupler = d.output("theta3") - pose_at(c.linkage, c.theta2[0])->theta3;
    worst = std::max(worst, std::abs(std::remainder(coupler - (poses[j].angle - poses[0].angle), 2 * pi)));
  }
  return worst;
}

}  // namespace

TEST(MotionGeneration, PoseFromTwoPointsAndCarry) {
  const Pose p = pose_from_points({1, 1}, {1, 3});
  EXPECT_NEAR(p.angle, pi / 2, 1e-15);
  const Pose q{{5, 0}, pi};
  const Vec2 c = carry(p, q, {2, 1});  // one unit "right" of C in pose p -> one unit down of (5, 0) turned
  EXPECT_NEAR(c.x(), 5, 1e-15);
  EXPECT_NEAR(c.y(), 1, 1e-15);
  EXPECT_THROW(pose_from_points({1, 1}, {1, 1}), std::invalid_argument);
}

TEST(MotionGeneration, ThreePositionsWithTheMovingPivotsGiveBackTheGroundPivots) {
  // Norton's three-position synthesis with specified moving pivots: O2 and O4 are the centres of
  // the circles through A1 A2 A3 and B1 B2 B3.
  const Truth t = truth({30 * deg, 75 * deg, 120 * deg});
  const Dyad in = dyad_from_moving_pivot(t.poses, t.A1), out = dyad_from_moving_pivot(t.poses, t.B1);
  EXPECT_NEAR((in.ground_pivot - Vec2(0, 0)).norm(), 0, 1e-9);
  EXPECT_NEAR((out.ground_pivot - Vec2(0.1, 0)).norm(), 0, 1e-9);
  const MotionCandidate c = four_bar_from_dyads(t.poses, in, out, true);
  EXPECT_TRUE(c.defects.ok());
  EXPECT_NEAR(c.linkage.crank, 0.04, 1e-9);
  EXPECT_NEAR(c.linkage.coupler, 0.12, 1e-9);
  EXPECT_NEAR(c.linkage.rocker, 0.08, 1e-9);
  EXPECT_NEAR(c.theta2[1] - c.theta2[0], 45 * deg, 1e-9);
  EXPECT_LT(solver_miss(c, t.poses), 1e-8);
}

TEST(MotionGeneration, ThreePositionsWithTheFixedPivotsGiveBackTheMovingPivots) {
  // Norton's specified fixed pivots, by inversion.
  const Truth t = truth({30 * deg, 75 * deg, 120 * deg});
  const Dyad in = dyad_from_ground_pivot(t.poses, {0, 0}), out = dyad_from_ground_pivot(t.poses, {0.1, 0});
  EXPECT_NEAR((in.moving_pivot - t.A1).norm(), 0, 1e-9);
  EXPECT_NEAR((out.moving_pivot - t.B1).norm(), 0, 1e-9);
}

TEST(MotionGeneration, AnalyticalFreeChoicesAreTheDyadRotations) {
  // Norton sec. 5.6: with beta2, beta3 the crank's rotations (45, 90 deg) the dyad equations
  // give W = A1 - O2 and Z = P1 - A1; with the rocker's rotations, the right-hand dyad.
  const Truth t = truth({30 * deg, 75 * deg, 120 * deg});
  const Dyad in = dyad_from_rotations(t.poses, 45 * deg, 90 * deg);
  EXPECT_NEAR(in.ground_pivot.norm(), 0, 1e-9);
  EXPECT_NEAR((in.moving_pivot - t.A1).norm(), 0, 1e-9);
  const FourBar f = reference_four_bar();
  const double t4_1 = pose_at(f, 30 * deg)->theta4;
  const Dyad out = dyad_from_rotations(t.poses, pose_at(f, 75 * deg)->theta4 - t4_1, pose_at(f, 120 * deg)->theta4 - t4_1);
  EXPECT_NEAR((out.ground_pivot - Vec2(0.1, 0)).norm(), 0, 1e-9);
  EXPECT_NEAR((out.moving_pivot - t.B1).norm(), 0, 1e-9);
  // beta = alpha makes the equations singular.
  EXPECT_THROW(dyad_from_rotations(t.poses, t.poses[1].angle - t.poses[0].angle, t.poses[2].angle - t.poses[0].angle), NoSolution);
}

TEST(MotionGeneration, TwoPositionsGroundPivotsOnTheBisectors) {
  // Norton Ex. 3-3: C1 D1 -> C2 D2 with C and D the moving pivots; every choice along the
  // bisectors guides the coupler through both positions.
  const std::vector<Pose> poses{pose_from_points({0, 0}, {0.08, 0}), pose_from_points({0.06, 0.04}, {0.11, 0.102})};
  for (double s : {-0.05, 0.0, 0.07}) {
    const Dyad d = dyad_two_positions(poses[0], poses[1], {0, 0}, s);
    EXPECT_NEAR((d.ground_pivot - Vec2(0, 0)).norm(), (d.ground_pivot - Vec2(0.06, 0.04)).norm(), 1e-12);
  }
  const MotionCandidate best = best_two_position(poses, {0, 0}, {0.08, 0}, 41, 10, false);
  EXPECT_TRUE(best.defects.ok());
  EXPECT_LE(best.link_ratio, 10);
  EXPECT_LT(solver_miss(best, poses), 1e-8);
}

TEST(MotionGeneration, ThreePositionSearchFindsADefectFreeLinkage) {
  const Truth t = truth({30 * deg, 75 * deg, 120 * deg});
  const MotionCandidate c = best_three_position(t.poses, 16, 10, false);
  EXPECT_TRUE(c.defects.ok());
  EXPECT_GE(c.transmission.min, 30 * deg);
  EXPECT_LT(solver_miss(c, t.poses), 1e-8);
}

TEST(MotionGeneration, BranchDefectIsReported) {
  // A real branch defect: poses 1 and 3 of the reference crank-rocker on its open branch (crank
  // at 30 and 120 deg) and pose 2 on its crossed branch (crank at 75 deg, the other assembly of
  // the same links). With pose 1's joints as moving pivots the circles through A_j and B_j are
  // the crank and rocker circles, so the synthesis gives back the reference's own pivots and
  // lengths; but a Grashof crank-rocker cannot pass from one assembly to the other without being
  // taken apart (Norton, Design of Machinery, sec. 5.10, branch defect).
  const FourBar f = reference_four_bar();
  FourBar crossed = f;
  crossed.branch = -f.branch;
  const auto p1 = pose_at(f, 30 * deg), p2 = pose_at(crossed, 75 * deg), p3 = pose_at(f, 120 * deg);
  ASSERT_TRUE(p1 && p2 && p3);
  const std::vector<Pose> poses{{p1->P, p1->theta3}, {p2->P, p2->theta3}, {p3->P, p3->theta3}};
  // By hand: B lies on opposite sides of the line A O4 in poses 1 and 2.
  auto side = [&](const FourBarPose& p) { return (f.O4 - p.A).x() * (p.B - p.A).y() - (f.O4 - p.A).y() * (p.B - p.A).x(); };
  ASSERT_LT(side(*p1) * side(*p2), 0);
  const Dyad in = dyad_from_moving_pivot(poses, p1->A), out = dyad_from_moving_pivot(poses, p1->B);
  EXPECT_NEAR(in.ground_pivot.norm(), 0, 1e-9);
  EXPECT_NEAR((out.ground_pivot - Vec2(0.1, 0)).norm(), 0, 1e-9);
  const MotionCandidate bad = four_bar_from_dyads(poses, in, out, false);
  EXPECT_NEAR(bad.linkage.crank, 0.04, 1e-9);
  EXPECT_NEAR(bad.linkage.coupler, 0.12, 1e-9);
  EXPECT_NEAR(bad.linkage.rocker, 0.08, 1e-9);
  EXPECT_TRUE(bad.defects.branch_defect);
  EXPECT_FALSE(bad.defects.ok());
  ASSERT_FALSE(bad.defects.notes.empty());
  EXPECT_NE(bad.defects.notes.front().find("branch"), std::string::npos) << bad.defects.notes.front();
  // The search over the free choices finds a defect-free linkage for the same poses, and the
  // ranking puts it first.
  const MotionCandidate good = best_three_position(poses, 16, 10, false);
  EXPECT_TRUE(good.defects.ok());
  EXPECT_TRUE(better_candidate(good, bad, 10));
  EXPECT_FALSE(better_candidate(bad, good, 10));
}
