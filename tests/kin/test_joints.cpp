// Every built-in constraint's Jacobian and gamma checked by finite differences of Phi along a
// trajectory q(t) = q0 + qd t + qdd t^2/2:  d2/dt2 Phi(q(t), t) = Phi_q qdd - gamma, and
// d/dt Phi = Phi_q qd + Phi_t.
#include <gearkit/kin/angle_relation.hpp>
#include <gearkit/kin/joints.hpp>

#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <vector>

namespace gearkit::kin {
namespace {

struct Trajectory {
  std::vector<BodyState> at(double t) const {
    std::vector<BodyState> s(q0.size());
    for (std::size_t i = 0; i < q0.size(); ++i) {
      const Eigen::Vector3d q = q0[i] + qd[i] * t + 0.5 * qdd[i] * t * t;
      const Eigen::Vector3d v = qd[i] + qdd[i] * t;
      s[i].r = q.head<2>();
      s[i].set_theta(q(2));
      s[i].r_dot = v.head<2>();
      s[i].omega = v(2);
    }
    return s;
  }
  std::vector<Eigen::Vector3d> q0, qd, qdd;
};

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

void check(const Constraint& c, double input = 0.3) {
  const std::size_t n = c.bodies().size();
  Trajectory tr;
  for (std::size_t i = 0; i < n; ++i) {
    const double k = static_cast<double>(i) + 1.0;
    tr.q0.emplace_back(0.05 * k, -0.02 * k, 0.4 * k);
    tr.qd.emplace_back(0.3 - 0.1 * k, 0.2 * k, 1.5 - k);
    tr.qdd.emplace_back(2.0 * k, -1.0, 3.0 - 2 * k);
  }
  const double t = 0.1, h = 1e-4;
  const Rows r = evaluate(c, tr.at(t), t, input);
  const Rows rp = evaluate(c, tr.at(t + h), t + h, input), rm = evaluate(c, tr.at(t - h), t - h, input);
  Eigen::VectorXd qd(3 * n), qdd(3 * n);
  const auto s = tr.at(t);
  for (std::size_t i = 0; i < n; ++i) {
    qd.segment<3>(3 * static_cast<int>(i)) = tr.qd[i] + tr.qdd[i] * t;
    qdd.segment<3>(3 * static_cast<int>(i)) = tr.qdd[i];
  }
  const Eigen::VectorXd d1 = (rp.phi - rm.phi) / (2 * h);
  const Eigen::VectorXd d2 = (rp.phi - 2 * r.phi + rm.phi) / (h * h);
  const Eigen::VectorXd v = r.phi_q * qd + r.phi_t;
  const Eigen::VectorXd a = r.phi_q * qdd - r.gamma;
  for (int k = 0; k < c.equations(); ++k) {
    EXPECT_NEAR(d1(k), v(k), 1e-7) << c.kind() << " row " << k;
    EXPECT_NEAR(d2(k), a(k), 1e-5) << c.kind() << " row " << k;
  }
  // Jacobian column by column against central differences of Phi in q.
  for (std::size_t b = 0; b < n; ++b)
    for (int j = 0; j < 3; ++j) {
      auto plus = s, minus = s;
      const double e = 1e-6;
      if (j < 2) {
        plus[b].r(j) += e;
        minus[b].r(j) -= e;
      } else {
        plus[b].set_theta(plus[b].theta + e);
        minus[b].set_theta(minus[b].theta - e);
      }
      const Eigen::VectorXd col = (evaluate(c, plus, t, input).phi - evaluate(c, minus, t, input).phi) / (2 * e);
      for (int k = 0; k < c.equations(); ++k)
        EXPECT_NEAR(r.phi_q(k, 3 * static_cast<int>(b) + j), col(k), 1e-8) << c.kind() << " body " << b << " coord " << j;
    }
}

TEST(Joints, RevoluteDerivatives) { check(Revolute({0, {0.03, -0.01}}, {1, {-0.02, 0.04}})); }

TEST(Joints, PrismaticDerivatives) {
  check(Prismatic({0, {0.01, 0.02}}, {1, {-0.03, 0.01}}, Eigen::Vector2d(0.6, 0.8), 0.2));
}

TEST(Joints, PinInSlotDerivatives) { check(PinInSlot({0, {0.02, 0.0}}, {1, {0.0, -0.05}}, Eigen::Vector2d(1, 2))); }

TEST(Joints, DriversDerivatives) {
  check(AngleDriver(0, 1, Motion{2.0, -3.0}));
  check(DisplacementDriver({0, {0.01, 0.0}}, {1, {0.0, 0.02}}, Eigen::Vector2d(0, 1), Motion{0.5, 4.0}));
}

TEST(Joints, AngleRelationDerivatives) {
  check(AngleRelation({{0, 1.0}, {1, -0.5}, {2, -0.5}}, 0.1, "gear_mesh"));
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
