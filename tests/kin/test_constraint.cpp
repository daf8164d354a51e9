// The helpers every constraint shares (constraint.hpp): body states with cached trigonometry,
// rotation, perpendicular and planar cross product, against hand values and differences.
#include <gearkit/kin/constraint.hpp>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

namespace gearkit::kin {
namespace {

TEST(BodyState, SetThetaKeepsItsCosineAndSine) {
  BodyState s;
  EXPECT_EQ(s.cos_theta, 1.0);  // theta = 0 by default
  EXPECT_EQ(s.sin_theta, 0.0);
  for (const double theta : {-3.0, -0.5, 0.0, 1.0, 2.5, 7.0}) {
    s.set_theta(theta);
    EXPECT_EQ(s.theta, theta);
    EXPECT_DOUBLE_EQ(s.cos_theta, std::cos(theta));
    EXPECT_DOUBLE_EQ(s.sin_theta, std::sin(theta));
  }
}

TEST(BodyState, RotatedEqualsTheRotationMatrix) {
  BodyState s;
  s.set_theta(M_PI / 2);
  const Eigen::Vector2d v = s.rotated({2.0, 1.0});  // a quarter turn: (x, y) -> (-y, x)
  EXPECT_NEAR(v.x(), -1.0, 1e-15);
  EXPECT_NEAR(v.y(), 2.0, 1e-15);
  s.set_theta(0.7);
  const Eigen::Vector2d w(0.03, -0.05);
  EXPECT_LE((s.rotated(w) - Eigen::Rotation2Dd(0.7).toRotationMatrix() * w).norm(), 1e-16);
  EXPECT_LE((s.rotated(w) - rotate(0.7, w)).norm(), 1e-17);
}

// d/dtheta (A(theta) s) = perp(A(theta) s): the identity every joint's Jacobian uses.
TEST(ConstraintHelpers, PerpIsTheDerivativeOfTheRotation) {
  const Eigen::Vector2d s(0.04, 0.01);
  const double theta = 1.1, h = 1e-6;
  const Eigen::Vector2d fd = (rotate(theta + h, s) - rotate(theta - h, s)) / (2 * h);
  EXPECT_LE((fd - perp(rotate(theta, s))).norm(), 1e-11);
}

TEST(ConstraintHelpers, CrossIsTheZComponent) {
  EXPECT_EQ(cross({1, 0}, {0, 1}), 1.0);
  EXPECT_EQ(cross({0, 1}, {1, 0}), -1.0);
  EXPECT_EQ(cross({2, 3}, {4, 6}), 0.0);  // parallel
  // |a||b| sin(angle from a to b)
  EXPECT_NEAR(cross({3, 0}, 2.0 * Eigen::Vector2d(std::cos(0.3), std::sin(0.3))), 6.0 * std::sin(0.3), 1e-15);
}

}  // namespace
}  // namespace gearkit::kin
