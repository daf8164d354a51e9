// Position, velocity and acceleration analysis against closed-form textbook solutions and
// finite differences.
#include <gearkit/kin/solve.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "mechanisms.hpp"

namespace gearkit::kin {
namespace {

using testing::FourBarDims;
using testing::kDeg;

// Norton, Design of Machinery (5th ed.), four-bar closed forms: positions eq. 4.10 (via
// four_bar_closed_form), velocities eq. 6.18, accelerations eq. 7.12. Dimensions in the style of
// his Examples 4-1/6-1/7-1: a = 40, b = 120, c = 80, d = 100 mm, theta2 = 40 deg,
// omega2 = 25 rad/s, alpha2 = -40 rad/s^2. The solver works on absolute coordinates with
// Newton-Raphson, so the closed form is an independent method.
TEST(SolvePosition, FourBarMatchesNortonClosedForms) {
  const FourBarDims f{0.040, 0.120, 0.080, 0.100};
  const double theta2 = 40 * kDeg, omega2 = 25.0, alpha2 = -40.0;
  // Start from a deliberately rough drawing (5 deg off) so Newton has work to do.
  Model m = testing::four_bar(f, theta2 + 5 * kDeg, Motion{omega2, alpha2});
  Data data(m);
  data.inputs(0) = theta2;
  const PositionReport r = solve_position(m, data, 0.0);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_GT(r.iterations, 0);
  EXPECT_LE(r.residual, 1e-10);
  ASSERT_TRUE(solve_velocity(m, data));
  ASSERT_TRUE(solve_acceleration(m, data));

  const auto [theta3, theta4] = testing::four_bar_closed_form(f, theta2);
  EXPECT_NEAR(data.q(5), theta3, 1e-9);
  EXPECT_NEAR(data.q(8), theta4, 1e-9);

  const double w3 = f.a * omega2 * std::sin(theta4 - theta2) / (f.b * std::sin(theta3 - theta4));
  const double w4 = f.a * omega2 * std::sin(theta2 - theta3) / (f.c * std::sin(theta4 - theta3));
  EXPECT_NEAR(data.qd(2), omega2, 1e-9);
  EXPECT_NEAR(data.qd(5), w3, 1e-8);
  EXPECT_NEAR(data.qd(8), w4, 1e-8);

  const double A = f.c * std::sin(theta4), B = f.b * std::sin(theta3);
  const double C = f.a * alpha2 * std::sin(theta2) + f.a * omega2 * omega2 * std::cos(theta2) +
                   f.b * w3 * w3 * std::cos(theta3) - f.c * w4 * w4 * std::cos(theta4);
  const double D = f.c * std::cos(theta4), E = f.b * std::cos(theta3);
  const double F = f.a * alpha2 * std::cos(theta2) - f.a * omega2 * omega2 * std::sin(theta2) -
                   f.b * w3 * w3 * std::sin(theta3) + f.c * w4 * w4 * std::sin(theta4);
  const double a3 = (C * D - A * F) / (A * E - B * D);
  const double a4 = (C * E - B * F) / (A * E - B * D);
  EXPECT_NEAR(data.qdd(2), alpha2, 1e-8);
  EXPECT_NEAR(data.qdd(5), a3, 1e-6);
  EXPECT_NEAR(data.qdd(8), a4, 1e-6);
}

// Offset-free slider-crank, crank a = 50 mm, rod b = 200 mm, omega = 100 rad/s constant: the
// textbook piston position x = a cos(t) + sqrt(b^2 - a^2 sin^2(t)) and its derivatives.
TEST(SolvePosition, SliderCrankMatchesPistonFormula) {
  const double a = 0.050, b = 0.200, omega = 100.0;
  for (double deg : {0.0, 30.0, 75.0, 140.0, 225.0, 300.0}) {
    const double th = deg * kDeg;
    Model m;
    m.ground().points = {{"O", {0, 0}}};
    const Eigen::Vector2d A = testing::polar(a, th);
    const double S = std::sqrt(b * b - a * a * std::sin(th) * std::sin(th));
    const Eigen::Vector2d Bp(a * std::cos(th) + S, 0.0);
    const int crank = testing::add_link(m, "crank", th, {{"O", {0, 0}}, {"A", A}});
    const int rod = testing::add_link(m, "rod", std::atan2((Bp - A).y(), (Bp - A).x()), {{"A", A}, {"B", Bp}});
    const int piston = testing::add_link(m, "piston", 0.0, {{"B", Bp}});
    testing::pin(m, "O", crank, "O", kGround, "O");
    testing::pin(m, "A", crank, "A", rod, "A");
    testing::pin(m, "B", rod, "B", piston, "B");
    m.add_constraint("guide", std::make_shared<Prismatic>(BodyPoint{piston, {0, 0}}, BodyPoint{kGround, {0, 0}},
                                                          Eigen::Vector2d(1, 0), 0.0));
    const int drv = m.add_constraint("input", std::make_shared<AngleDriver>(crank, kGround, Motion{omega, 0.0}));
    m.set_driver(drv, DriverQuantity::angle, th);
    Data data(m);
    data.q(6) += 0.01;  // start the piston 10 mm off
    ASSERT_TRUE(solve_position(m, data, 0.0).converged);
    ASSERT_TRUE(solve_velocity(m, data));
    ASSERT_TRUE(solve_acceleration(m, data));
    const double s = std::sin(th), c = std::cos(th);
    const double x = a * c + S;
    const double dx = -a * s - a * a * s * c / S;
    const double ddx = -a * c - a * a * std::cos(2 * th) / S - std::pow(a, 4) * s * s * c * c / std::pow(S, 3);
    EXPECT_NEAR(data.q(6), x, 1e-12) << deg;
    EXPECT_NEAR(data.qd(6), dx * omega, 1e-9) << deg;
    EXPECT_NEAR(data.qdd(6), ddx * omega * omega, 1e-6) << deg;
  }
}

// Velocities and accelerations are the time derivatives of positions: central differences of
// solve_position at t +- h with a driver f(t) = f0 + w t + a t^2/2.
TEST(SolveVelocity, MatchesFiniteDifferencesOfPositions) {
  const FourBarDims f{0.040, 0.120, 0.080, 0.100};
  Model m = testing::four_bar(f, 70 * kDeg, Motion{3.0, 2.0});
  Data data(m);
  const double t = 0.2, h = 1e-4;
  auto q_at = [&](double time) {
    const PositionReport r = solve_position(m, data, time, {1e-13, 50, 0.5});
    EXPECT_TRUE(r.converged);
    return Eigen::VectorXd(data.q);
  };
  const Eigen::VectorXd qm = q_at(t - h), qp = q_at(t + h), q0 = q_at(t);
  ASSERT_TRUE(solve_velocity(m, data));
  ASSERT_TRUE(solve_acceleration(m, data));
  const Eigen::VectorXd v_fd = (qp - qm) / (2 * h);
  const Eigen::VectorXd a_fd = (qp - 2 * q0 + qm) / (h * h);
  for (int i = 0; i < m.coordinates(); ++i) {
    EXPECT_NEAR(data.qd(i), v_fd(i), 1e-6) << i;
    EXPECT_NEAR(data.qdd(i), a_fd(i), 1e-3) << i;
  }
}

TEST(SolvePosition, ReportsWhenTheLinkageCannotClose) {
  // Crank 40, coupler 120, rocker 80, ground 100 mm: fine. Ground 300 mm cannot close at all.
  const FourBarDims f{0.040, 0.120, 0.080, 0.100};
  Model good = testing::four_bar(f, 40 * kDeg);
  Model m;
  m.ground().points = {{"O2", {0, 0}}, {"O4", {0.300, 0}}};
  for (const Body& b : good.bodies()) m.add_body(b);
  testing::pin(m, "O2", 0, "O2", kGround, "O2");
  testing::pin(m, "A", 0, "A", 1, "A");
  testing::pin(m, "B", 1, "B", 2, "B");
  testing::pin(m, "O4", 2, "O4", kGround, "O4");
  const int drv = m.add_constraint("input", std::make_shared<AngleDriver>(0, kGround, Motion{1.0, 0.0}));
  m.set_driver(drv, DriverQuantity::angle, 40 * kDeg);
  Data data(m);
  const Eigen::VectorXd guess = data.q;
  const PositionReport r = solve_position(m, data, 0.0);
  EXPECT_FALSE(r.converged);
  EXPECT_FALSE(r.message.empty());
  EXPECT_LE(r.iterations, SolverOptions{}.max_iterations);
  EXPECT_EQ(data.q, guess);  // no garbage left behind
}

// Norton's four-bar drawn lazily: every link along the x axis (crank at O2, coupler from
// A = (40, 0), rocker at O4, all angles 0) with the input at 0 (issue 13 item 3). Newton stalls
// on the flat drawing's singular Jacobian; assemble() restarts from perturbed angles and keeps the
// assembly nearest the drawing, which is one of the two closed-form branches at theta2 = 0 (the
// crossed one is the open one mirrored in the ground line there). It returns the drawing's own
// failure for a loop that cannot close.
TEST(Assemble, ALazyDrawingFindsTheNearestBranch) {
  const FourBarDims f{0.040, 0.120, 0.080, 0.100};
  Model m = testing::four_bar(f, 0.0);
  Data data(m);
  data.q << 0, 0, 0, f.a, 0, 0, f.d, 0, 0;  // crank, coupler, rocker: (x, y, angle), all flat
  Data plain(m);
  plain.q = data.q;
  const PositionReport newton = solve_position(m, plain, 0.0);
  EXPECT_TRUE(!newton.converged || newton.singular);
  const PositionReport r = assemble(m, data, 0.0);
  ASSERT_TRUE(r.converged && !r.singular) << r.message;
  const auto [theta3, theta4] = testing::four_bar_closed_form(f, 0.0);
  EXPECT_NEAR(std::abs(data.q(5)), std::abs(theta3), 1e-9);
  EXPECT_NEAR(std::abs(data.q(8)), std::abs(theta4), 1e-9);
  EXPECT_GT(data.q(5) * data.q(8) * theta3 * theta4, 0.0);  // both from one branch
  EXPECT_NEAR(data.q(2), 0.0, 1e-12);  // the crank where the driver holds it
}

TEST(SolvePosition, UnderDrivenModelIsRefused) {
  Model m = testing::four_bar({0.04, 0.12, 0.08, 0.1}, 40 * kDeg);
  Model free;
  free.ground() = m.ground();
  for (const Body& b : m.bodies()) free.add_body(b);
  testing::pin(free, "O2", 0, "O2", kGround, "O2");
  testing::pin(free, "A", 0, "A", 1, "A");
  testing::pin(free, "B", 1, "B", 2, "B");
  testing::pin(free, "O4", 2, "O4", kGround, "O4");
  Data data(free);
  const PositionReport r = solve_position(free, data, 0.0);
  EXPECT_FALSE(r.converged);
  EXPECT_NE(r.message.find("under-driven"), std::string::npos) << r.message;
}

// The sparse LU (KLU) against Eigen's dense LU, an independent factorisation: the sign of
// det(Phi_q) drives the branch check of sweeps, and it is assembled from KLU's pivots and the
// parities of its row and column permutations (block triangular form included). A chain of
// ten four-bars (63 coordinates, eleven diagonal blocks) at 200 poses off the constraint
// manifold, one after another, exercises both refactorisation with the old pivots and fresh
// pivoting when they decay.
TEST(Factorisation, DeterminantSignAgreesWithDenseLU) {
  const Model m = testing::four_bar_chain({0.040, 0.120, 0.080, 0.100}, 10, 30 * kDeg);
  Data data(m);
  const Eigen::VectorXd drawn = data.q;
  std::srand(7);
  int positive = 0, negative = 0;
  for (int trial = 0; trial < 200; ++trial) {
    data.q = drawn + (trial < 100 ? 0.05 : 1.5) * Eigen::VectorXd::Random(drawn.size());
    evaluate_constraints(m, data, 0.0);
    ASSERT_TRUE(factorize(m, data)) << trial;
    const Eigen::PartialPivLU<Eigen::MatrixXd> dense(data.jacobian());
    const double det = dense.determinant();
    ASSERT_NE(det, 0.0);
    EXPECT_EQ(data.determinant_sign, det > 0 ? 1 : -1) << trial;
    (det > 0 ? positive : negative) += 1;
    // The LU solves like the dense one.
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(m.equations(), -1.0, 2.0);
    const Eigen::VectorXd x = solve_with_jacobian(data, b), x_dense = dense.solve(b);
    EXPECT_LE((x - x_dense).norm(), 1e-9 * (1.0 + x_dense.norm())) << trial;
    const Eigen::VectorXd y = solve_with_jacobian_transpose(data, b), y_dense = dense.transpose().solve(b);
    EXPECT_LE((y - y_dense).norm(), 1e-9 * (1.0 + y_dense.norm())) << trial;
  }
  EXPECT_GT(positive, 10);  // both signs were met, so the test can tell them apart
  EXPECT_GT(negative, 10);
}

// At a toggle the Jacobian is singular; nearby its condition estimate collapses, far away it
// does not. Triple rocker 80/90/100/120 mm: coupler and rocker align when |A O4| = b + c.
TEST(Factorisation, ConditionEstimateCollapsesAtAToggle) {
  const FourBarDims f{0.080, 0.090, 0.100, 0.120};
  const double toggle = std::acos((f.a * f.a + f.d * f.d - (f.b + f.c) * (f.b + f.c)) / (2 * f.a * f.d));
  Model m = testing::four_bar(f, 60 * kDeg);
  Data data(m);
  ASSERT_TRUE(solve_position(m, data, 0.0).converged);
  EXPECT_GT(data.rcond, 1e-4);
  const double far = data.rcond;
  // Walk up to the toggle along the branch, halving the distance (the smallest singular value
  // falls like its square root).
  for (double gap = 10 * kDeg; gap > 1e-11; gap *= 0.5) {
    data.inputs(0) = toggle - gap;
    ASSERT_TRUE(solve_position(m, data, 0.0).converged) << gap;
  }
  EXPECT_LT(data.rcond, 1e-4 * far);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(data.jacobian());
  const double sigma_ratio = svd.singularValues().tail<1>()(0) / svd.singularValues()(0);
  EXPECT_LT(sigma_ratio, 1e-4);  // the independent check that this is near-singular
}

// A chord first step with the factorisation of a nearby solution, or even of a far-away pose
// (then the step is undone), reaches the same solution as plain Newton-Raphson.
TEST(SolvePosition, ReusedFactorisationGivesTheSameSolution) {
  const FourBarDims f{0.040, 0.120, 0.080, 0.100};
  Model m = testing::four_bar(f, 30 * kDeg);
  SolverOptions reuse;
  reuse.reuse_factorization = true;
  reuse.tolerance = 1e-12;
  SolverOptions plain = reuse;
  plain.reuse_factorization = false;
  for (const double from : {29.0, 10.0, 200.0}) {
    Data a(m), b(m);
    a.inputs(0) = from * kDeg;
    ASSERT_TRUE(solve_position(m, a, 0.0).converged);  // factorised at `from`
    a.q = b.q;                                          // the drawn pose at 30 deg as the guess
    a.inputs(0) = b.inputs(0) = 31 * kDeg;
    const PositionReport ra = solve_position(m, a, 0.0, reuse), rb = solve_position(m, b, 0.0, plain);
    ASSERT_TRUE(ra.converged && rb.converged) << from;
    EXPECT_LE((a.q - b.q).cwiseAbs().maxCoeff(), 1e-11) << from;
    const auto [theta3, theta4] = testing::four_bar_closed_form(f, 31 * kDeg);
    EXPECT_NEAR(a.q(5), theta3, 1e-10);
    EXPECT_NEAR(a.q(8), theta4, 1e-10);
    // The factorisation now belongs to the solution: velocities are exact.
    ASSERT_TRUE(solve_velocity(m, a));
    ASSERT_TRUE(solve_velocity(m, b));
    EXPECT_LE((a.qd - b.qd).cwiseAbs().maxCoeff(), 1e-9) << from;
  }
}

// With one moving driver Phi_t has a single non-zero row, so qd = omega dq/d(input).
TEST(SolveVelocity, AlongTheInputSensitivityEqualsTheFullSolve) {
  Model m = testing::four_bar({0.040, 0.120, 0.080, 0.100}, 50 * kDeg, Motion{2.5, -4.0});
  Data data(m);
  ASSERT_TRUE(solve_position(m, data, 0.3).converged);
  ASSERT_TRUE(solve_velocity(m, data));
  const Eigen::VectorXd qd = data.qd, gamma = data.gamma;
  const Eigen::VectorXd dq = input_sensitivity(m, data, 0);
  const double omega = 2.5 - 4.0 * 0.3;
  ASSERT_TRUE(solve_velocity_along(m, data, dq, omega));
  EXPECT_LE((data.qd - qd).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LE((data.gamma - gamma).cwiseAbs().maxCoeff(), 1e-9);
}

}  // namespace
}  // namespace gearkit::kin
