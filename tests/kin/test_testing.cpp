// kin::testing::check_derivatives, the derivative checker every element type is held to
// (tests/kin/test_joints.cpp: the built-in joints; tests/elements: the elements plugins
// register). A checker that cannot fail proves nothing: here it
// must find each kind of error planted in an otherwise correct constraint, and pass the
// correct one. The reference is the hand derivation of a point fixed to a body,
// Phi = r + A(theta) s' - c(t) with c(t) = (v t, 0):
//   Phi_q = [I, perp(A s')],  Phi_t = (-v, 0),  gamma = omega^2 A s',
// by hand: d/dt A s' = omega perp(A s'), d2/dt2 A s' = theta_dd perp(A s') - omega^2 A s', and
// gamma = Phi_q qdd - d2 Phi/dt2 leaves omega^2 A s'.
#include <gearkit/kin/joints.hpp>
#include <gearkit/kin/testing.hpp>

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace gearkit::kin {
namespace {

enum class Plant { none, jacobian_sign, no_phi_t, no_centripetal, unwritten_gamma };

// The point s' of body 0 follows c(t) = (speed t, 0). `plant` breaks one derivative.
class MovingPoint final : public Constraint {
 public:
  explicit MovingPoint(Plant plant, int body = 0) : plant_(plant), body_(body) {}
  std::string kind() const override { return "moving_point"; }
  int equations() const override { return 2; }
  std::vector<int> bodies() const override { return {body_}; }
  void evaluate(const ConstraintInput& in, ConstraintOutput& out) const override {
    const BodyState& b = in.bodies[0];
    const Eigen::Vector2d s = b.rotated(local_);
    out.phi = b.r + s - Eigen::Vector2d(speed_ * in.t, 0.0);
    out.phi_q.setIdentity();
    out.phi_q.col(2) = (plant_ == Plant::jacobian_sign ? -1.0 : 1.0) * perp(s);
    out.phi_t = plant_ == Plant::no_phi_t ? Eigen::Vector2d::Zero() : Eigen::Vector2d(-speed_, 0.0);
    out.gamma = plant_ == Plant::no_centripetal ? Eigen::Vector2d::Zero() : Eigen::Vector2d(b.omega * b.omega * s);
    if (plant_ == Plant::unwritten_gamma) out.gamma(1) = std::numeric_limits<double>::quiet_NaN();
  }

 private:
  Plant plant_;
  int body_;
  Eigen::Vector2d local_{0.07, -0.03};
  double speed_ = 0.4;
};

bool found(const testing::DerivativeReport& r, const std::string& quantity) {
  for (const auto& m : r.mismatches)
    if (m.quantity == quantity) return true;
  return false;
}

TEST(DerivativeCheck, PassesTheHandDerivedConstraint) {
  const testing::DerivativeReport r = testing::check_derivatives(MovingPoint(Plant::none));
  EXPECT_TRUE(r.ok()) << r.describe("moving_point");
  // 16 configurations x (2 rows x 3 columns + 2 Phi_t + 2 gamma).
  EXPECT_EQ(r.entries_checked, 16 * (6 + 2 + 2));
  EXPECT_EQ(r.describe("moving_point"), "");
}

TEST(DerivativeCheck, FindsAWrongJacobianColumn) {
  const testing::DerivativeReport r = testing::check_derivatives(MovingPoint(Plant::jacobian_sign));
  ASSERT_TRUE(found(r, "Phi_q"));
  EXPECT_FALSE(found(r, "Phi_t"));
  for (const auto& m : r.mismatches) {
    if (m.quantity == "Phi_q") {
      EXPECT_EQ(m.column, 2);  // the theta column, the one planted
    }
  }
  // (gamma is found wrong too: it is checked through Phi_q qdd, with the analytic Phi_q.)
  EXPECT_NE(r.describe("moving_point").find("moving_point: Phi_q row"), std::string::npos);
}

TEST(DerivativeCheck, FindsAMissingPhiT) {
  const testing::DerivativeReport r = testing::check_derivatives(MovingPoint(Plant::no_phi_t));
  EXPECT_TRUE(found(r, "Phi_t")) << r.describe("moving_point");
  // The planted error is -speed in row 0 only: row 1's Phi_t (0) is right.
  for (const auto& m : r.mismatches)
    if (m.quantity == "Phi_t") {
      EXPECT_EQ(m.row, 0);
      EXPECT_NEAR(m.numeric, -0.4, 1e-6);
    }
}

TEST(DerivativeCheck, FindsAMissingCentripetalTerm) {
  const testing::DerivativeReport r = testing::check_derivatives(MovingPoint(Plant::no_centripetal));
  EXPECT_TRUE(found(r, "gamma")) << r.describe("moving_point");
  EXPECT_FALSE(found(r, "Phi_q"));
  EXPECT_FALSE(found(r, "Phi_t"));
}

TEST(DerivativeCheck, FindsAnEntryLeftUnwritten) {
  const testing::DerivativeReport r = testing::check_derivatives(MovingPoint(Plant::unwritten_gamma));
  ASSERT_TRUE(found(r, "not finite"));
  EXPECT_EQ(r.mismatches.front().row, 1);
}

TEST(DerivativeCheck, GroundSlotsStayFixedAndRepeatedBodiesAreSummed) {
  // A revolute between two points of one body: its columns for the two slots sum (in x and y
  // they cancel), as the solver assembles them. A revolute to the ground: only the moving
  // body's columns are checked.
  EXPECT_TRUE(testing::check_derivatives(Revolute({0, {0.05, 0.0}}, {0, {0.0, 0.02}})).ok());
  EXPECT_TRUE(testing::check_derivatives(Revolute({kGround, {0.05, 0.0}}, {2, {0.0, 0.02}})).ok());
  EXPECT_TRUE(testing::check_derivatives(MovingPoint(Plant::none, 7)).ok());
}

TEST(DerivativeCheck, RefusesMeaninglessOptions) {
  testing::DerivativeCheckOptions o;
  o.configurations = 0;
  EXPECT_THROW(testing::check_derivatives(MovingPoint(Plant::none), o), std::invalid_argument);
  o = {};
  o.h_t = 0.0;
  EXPECT_THROW(testing::check_derivatives(MovingPoint(Plant::none), o), std::invalid_argument);
}

}  // namespace
}  // namespace gearkit::kin
