// The helpers every constraint shares (constraint.hpp): body states with cached trigonometry,
// rotation, perpendicular and planar cross product, against hand values and differences.
#include <gearkit/kin/constraint.hpp>
#include <gearkit/kin/joints.hpp>

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

// The default reaction is the generalised force -Phi_q^T lambda on the first body: for a
// revolute seen through the default (a copy that does not override it) the force is
// F = -lambda and the moment about the frame origin is (A s_a) x F.
class PlainRevolute final : public Constraint {
 public:
  PlainRevolute(BodyPoint a, BodyPoint b) : joint_(a, b) {}
  std::string kind() const override { return "plain"; }
  int equations() const override { return 2; }
  std::vector<int> bodies() const override { return joint_.bodies(); }
  void evaluate(const ConstraintInput& in, ConstraintOutput& out) const override { joint_.evaluate(in, out); }

 private:
  Revolute joint_;
};

TEST(ConstraintReaction, DefaultIsTheGeneralisedForceOnTheFirstBody) {
  const BodyPoint a{0, {0.3, 0.1}}, b{1, {0.0, 0.0}};
  std::vector<BodyState> states(2);
  states[0].r = {1.0, 2.0};
  states[0].set_theta(0.7);
  states[1].r = states[0].r + states[0].rotated(a.local);
  const ConstraintInput in{states, 0.0, 0.0};
  const std::vector<double> lambda{3.0, -4.0};
  const Reaction plain = PlainRevolute(a, b).reaction(in, lambda);
  const Eigen::Vector2d F(-3.0, 4.0);
  EXPECT_NEAR((plain.force - F).norm(), 0.0, 1e-14);
  EXPECT_NEAR(plain.moment, cross(states[0].rotated(a.local), F), 1e-14);
  EXPECT_FALSE(plain.at.has_value());
  EXPECT_TRUE(plain.values.empty());
  // The revolute's own reaction: the same force, at the joint point, a pin (no moment).
  const Reaction pin = Revolute(a, b).reaction(in, lambda);
  EXPECT_NEAR((pin.force - F).norm(), 0.0, 1e-14);
  ASSERT_TRUE(pin.at.has_value());
  EXPECT_NEAR((*pin.at - states[1].r).norm(), 0.0, 1e-14);
  EXPECT_TRUE(pin.pin);
  EXPECT_EQ(pin.moment, 0.0);
}

// A prismatic joint: the force is normal to the guide, the moment is about the slider point
// (the moment about the frame origin of the default minus (A s) x F).
TEST(ConstraintReaction, PrismaticMomentIsAboutTheSliderPoint) {
  const BodyPoint slider{0, {0.2, -0.1}}, guide{1, {0.0, 0.0}};
  const Prismatic joint(slider, guide, Eigen::Vector2d(1, 0), 0.0);
  std::vector<BodyState> states(2);
  states[0].set_theta(0.4);
  states[1].set_theta(0.4);
  states[0].r = {0.5, 0.0};
  const ConstraintInput in{states, 0.0, 0.0};
  const std::vector<double> lambda{2.0, 5.0};
  const Reaction r = joint.reaction(in, lambda);
  const Eigen::Vector2d n = states[1].rotated({0, 1});
  EXPECT_NEAR((r.force + 5.0 * n).norm(), 0.0, 1e-14);
  EXPECT_NEAR(r.moment, -2.0, 1e-14);
  const Reaction general = joint.Constraint::reaction(in, lambda);
  EXPECT_NEAR(general.moment - cross(states[0].rotated(slider.local), general.force), r.moment, 1e-13);
  EXPECT_FALSE(r.pin);
}

}  // namespace
}  // namespace gearkit::kin
