// Every built-in constraint's Jacobian, Phi_t and gamma checked by finite differences of its
// own Phi at random configurations (kin::testing::check_derivatives, the one checker every
// element type is held to; tests/kin/test_testing.cpp shows it catches each kind of error).
#include <gearkit/kin/angle_relation.hpp>
#include <gearkit/kin/joints.hpp>
#include <gearkit/kin/testing.hpp>

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace gearkit::kin {
namespace {

void check(const Constraint& c) {
  const testing::DerivativeReport r = testing::check_derivatives(c);
  EXPECT_TRUE(r.ok()) << r.describe(c.kind());
  // 16 configurations, each a Jacobian column per coordinate of every moving body and a Phi_t
  // and a gamma per row: the check compared something.
  EXPECT_GE(r.entries_checked, 16 * c.equations() * 5);
}

TEST(Joints, RevoluteDerivatives) {
  check(Revolute({0, {0.03, -0.01}}, {1, {-0.02, 0.04}}));
  check(Revolute({kGround, {0.1, 0.2}}, {1, {-0.02, 0.04}}));  // to the ground
}

TEST(Joints, PrismaticDerivatives) {
  check(Prismatic({0, {0.01, 0.02}}, {1, {-0.03, 0.01}}, Eigen::Vector2d(0.6, 0.8), 0.2));
  check(Prismatic({0, {0.01, 0.02}}, {kGround, {-0.03, 0.01}}, Eigen::Vector2d(1.0, 0.0), 0.0));
}

TEST(Joints, PinInSlotDerivatives) {
  check(PinInSlot({0, {0.02, 0.0}}, {1, {0.0, -0.05}}, Eigen::Vector2d(1, 2)));
  check(PinInSlot({kGround, {0.02, 0.0}}, {1, {0.0, -0.05}}, Eigen::Vector2d(1, 2)));
}

TEST(Joints, ContactDerivatives) {
  check(Contact({0, {0.01, 0.03}}, 0.015, {1, {-0.02, 0.0}}, Eigen::Vector2d(1, 1), 1));
  check(Contact({0, {0.01, 0.03}}, 0.0, {1, {-0.02, 0.0}}, Eigen::Vector2d(0, 1), -1));  // an edge
  check(Contact({0, {0.0, 0.0}}, 0.02, {kGround, {0.0, 0.0}}, Eigen::Vector2d(1, 0), 1));  // on a ground line
}

TEST(Joints, DriversDerivatives) {
  check(AngleDriver(0, 1, Motion{2.0, -3.0}));
  check(AngleDriver(0, kGround, Motion{1.0, 0.0}));
  check(DisplacementDriver({0, {0.01, 0.0}}, {1, {0.0, 0.02}}, Eigen::Vector2d(0, 1), Motion{0.5, 4.0}));
}

TEST(Joints, AngleRelationDerivatives) {
  check(AngleRelation({{0, 1.0}, {1, -0.5}, {2, -0.5}}, 0.1, "gear_mesh"));
  check(AngleRelation({{0, 1.0}, {kGround, 2.0}, {1, -3.0}}, -0.2, "epicyclic_train"));
}

struct Rows {
  Eigen::VectorXd phi, phi_t, gamma;
  Eigen::MatrixXd phi_q;
};

Rows evaluate(const Constraint& c, const std::vector<BodyState>& s, double t, double input) {
  Rows r{Eigen::VectorXd(c.equations()), Eigen::VectorXd(c.equations()), Eigen::VectorXd(c.equations()),
         Eigen::MatrixXd(c.equations(), 3 * static_cast<int>(s.size()))};
  ConstraintOutput out{r.phi, r.phi_q, r.phi_t, r.gamma};
  c.evaluate(ConstraintInput{s, t, input}, out);
  return r;
}

TEST(Joints, AxesAreNormalised) {
  // A non-unit axis must not scale the equation: the slider displacement is a length.
  const DisplacementDriver d({0, {0, 0}}, {1, {0, 0}}, Eigen::Vector2d(0, 5), Motion{});
  std::vector<BodyState> s(2);
  s[0].r = {0.0, 0.3};
  const Rows r = evaluate(d, s, 0.0, 0.1);
  EXPECT_NEAR(r.phi(0), 0.3 - 0.1, 1e-15);
}

}  // namespace
}  // namespace gearkit::kin
