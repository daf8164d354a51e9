// libsynth burmester.hpp: four- and five-position synthesis. Poses of the reference four-bar
// (analysed by libkin) make a task whose solutions are known: its two dyads must lie on the
// four-position centre-point/circle-point curves and be among the five-position Burmester points.
#include "synth_test_support.hpp"

#include <gearkit/synth/burmester.hpp>
#include <gearkit/synth/mechanism_writer.hpp>

#include <gtest/gtest.h>

using namespace gearkit::synth;
using namespace gearkit::synth::testing;

namespace {

bool has_dyad(const std::vector<BurmesterDyad>& family, const Vec2& ground, const Vec2& moving, double tol) {
  for (const BurmesterDyad& b : family)
    if ((b.dyad.ground_pivot - ground).norm() < tol && (b.dyad.moving_pivot - moving).norm() < tol) return true;
  return false;
}

}  // namespace

TEST(Burmester, FourPositionFamilyHoldsTheReferenceDyads) {
  const std::vector<double> theta2{30 * deg, 60 * deg, 90 * deg, 120 * deg};
  const auto poses = reference_poses(theta2);
  const auto p1 = pose_at(reference_four_bar(), theta2[0]);
  // The crank's own rotation beta2 = 30 deg lies on the family: one closure gives O2, A1.
  bool found = false;
  for (int closure : {0, 1}) {
    try {
      const BurmesterDyad b = burmester_dyad(poses, 30 * deg, closure);
      found = found || ((b.dyad.ground_pivot - Vec2(0, 0)).norm() < 1e-9 && (b.dyad.moving_pivot - p1->A).norm() < 1e-9);
    } catch (const NoSolution&) {
    }
  }
  EXPECT_TRUE(found);
  // Every sampled member guides the coupler through all four poses.
  const auto family = burmester_curves(poses, 360);
  EXPECT_GT(family.size(), 100u);
  for (const BurmesterDyad& b : family) {
    const double size = (b.dyad.moving_pivot - b.dyad.ground_pivot).norm();
    EXPECT_LT(dyad_error(poses, b.dyad), 1e-9 * std::max(1.0, size)) << b.beta[0];
  }
}

TEST(Burmester, FivePositionBurmesterPointsIncludeTheReferencePivots) {
  const std::vector<double> theta2{30 * deg, 60 * deg, 90 * deg, 120 * deg, 150 * deg};
  const auto poses = reference_poses(theta2);
  const auto p1 = pose_at(reference_four_bar(), theta2[0]);
  const auto points = burmester_points(poses, 720);
  EXPECT_TRUE(points.size() == 2 || points.size() == 4) << points.size();
  EXPECT_TRUE(has_dyad(points, {0, 0}, p1->A, 1e-8));
  EXPECT_TRUE(has_dyad(points, {0.1, 0}, p1->B, 1e-8));
  for (const BurmesterDyad& b : points) EXPECT_LT(dyad_error(poses, b.dyad), 1e-9);
  // The linkage of the two reference dyads, written and driven by the solver, meets all five.
  std::vector<Dyad> dyads;
  for (const BurmesterDyad& b : points) dyads.push_back(b.dyad);
  const MotionCandidate c = best_pair_of_dyads(poses, dyads, 10, false);
  Driven d = Driven::from_text(to_mechanism_yaml(four_bar_sketch(c.linkage, c.theta2[0], c.defects.travel, c.defects.direction, "five")));
  for (std::size_t j = 0; j < poses.size(); ++j) {
    ASSERT_TRUE(d.drive_to(c.theta2[0] + c.defects.direction * wrap_two_pi(c.defects.direction * (c.theta2[j] - c.theta2[0]))));
    EXPECT_NEAR(std::hypot(d.output("Px") - poses[j].point.x(), d.output("Py") - poses[j].point.y()), 0, 1e-9);
  }
}

TEST(Burmester, BadCountsAreRejected) {
  const auto poses = reference_poses({30 * deg, 60 * deg, 90 * deg, 120 * deg});
  EXPECT_THROW(burmester_points(poses, 100), std::invalid_argument);
  EXPECT_THROW(burmester_curves(poses, kMaxBurmesterSamples + 1), std::invalid_argument);
}
