// The per-analysis workspace (data.hpp): sizes, the drawn pose and driver values as the
// start, the fixed pattern of Phi_q and its assembly from the constraints' blocks.
#include <gearkit/kin/angle_relation.hpp>
#include <gearkit/kin/data.hpp>
#include <gearkit/kin/dof.hpp>
#include <gearkit/kin/kinetostatics.hpp>
#include <gearkit/kin/solve.hpp>
#include <gearkit/kin/sweep.hpp>

#include <gtest/gtest.h>

#include <memory>
#include <utility>
#include <vector>

#include "mechanisms.hpp"

namespace gearkit::kin {
namespace {

using testing::kDeg;

// Issue 12 item 3: a body added after the Data was made wrote out of bounds in
// Revolute::evaluate (AddressSanitizer: SEGV); every algorithm now checks the Data first.
TEST(Data, AChangedModelIsRefusedInsteadOfReadOutOfBounds) {
  Model m = testing::four_bar({0.040, 0.120, 0.080, 0.100}, 30 * kDeg);
  Data data(m);
  ASSERT_NO_THROW(check_data(m, data));
  ASSERT_TRUE(solve_position(m, data, 0.0).converged);
  const int extra = testing::add_link(m, "extra", 0.0, {{"P", {0.0, 0.0}}, {"Q", {0.05, 0.0}}});
  testing::pin(m, "P", extra, "P", kGround, "O2");
  EXPECT_THROW(solve_position(m, data, 0.0), DataMismatch);
  EXPECT_THROW(evaluate_constraints(m, data, 0.0), DataMismatch);
  EXPECT_THROW(solve_velocity(m, data), DataMismatch);
  EXPECT_THROW(dof(m, data), DataMismatch);
  EXPECT_THROW(solve_forces(m, data), DataMismatch);
  try {
    check_data(m, data);
    ADD_FAILURE() << "no DataMismatch";
  } catch (const DataMismatch& e) {
    EXPECT_NE(std::string(e.what()).find("3 bodies"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("make a new Data"), std::string::npos) << e.what();
  }
  Data fresh(m);  // a new Data fits the changed model
  EXPECT_NO_THROW(check_data(m, fresh));
}

TEST(Data, ADataOfAnotherModelIsRefused) {
  const Model four_bar = testing::four_bar({0.040, 0.120, 0.080, 0.100}, 30 * kDeg);
  const Model chain = testing::four_bar_chain({0.040, 0.120, 0.080, 0.100}, 3);
  Data data(four_bar);
  EXPECT_THROW(solve_position(chain, data, 0.0), DataMismatch);
  SweepOptions o;
  o.step = 0.1;
  o.end = 1.0;
  EXPECT_THROW(sweep(chain, data, o), DataMismatch);
}

TEST(Data, StartsFromTheDrawingWithThePatternOfEveryBlock) {
  const Model m = testing::four_bar({0.040, 0.120, 0.080, 0.100}, 30 * kDeg);
  const Data data(m);
  ASSERT_EQ(data.q.size(), 9);
  for (std::size_t i = 0; i < m.bodies().size(); ++i) {
    EXPECT_EQ(data.q.segment<2>(3 * static_cast<int>(i)), m.bodies()[i].position_guess);
    EXPECT_EQ(data.q(3 * static_cast<int>(i) + 2), m.bodies()[i].angle_guess);
  }
  EXPECT_EQ(data.inputs.size(), 1);
  EXPECT_EQ(data.inputs(0), 30 * kDeg);
  // Blocks on moving bodies: revolutes to ground 2 x 3, between links 2 x 6, driver 1 x 3.
  EXPECT_EQ(data.phi_q.rows(), 9);
  EXPECT_EQ(data.phi_q.cols(), 9);
  EXPECT_EQ(data.phi_q.nonZeros(), 6 + 12 + 12 + 6 + 3);
  EXPECT_FALSE(data.sum_jacobian_entries);
  EXPECT_FALSE(data.sparse);
  EXPECT_FALSE(data.factored);
  const Data large(testing::four_bar_chain({0.040, 0.120, 0.080, 0.100}, 11));
  EXPECT_TRUE(large.sparse);  // 69 coordinates: rank tests by sparse QR
}

// The assembled Phi_q against central differences of the assembled Phi, on a model whose
// angle relation lists one body twice (its two block entries must add up in Phi_q).
TEST(EvaluateConstraints, JacobianMatchesFiniteDifferencesWithABodyListedTwice) {
  Model m;
  m.ground().points = {{"O", {0, 0}}};
  Body a, b;
  a.name = "a";
  a.points = {{"O", {0, 0}}, {"P", {0.05, 0.0}}};
  b.name = "b";
  b.points = {{"P", {0, 0}}};
  const int ia = m.add_body(a), ib = m.add_body(b);
  m.add_constraint("O", std::make_shared<Revolute>(BodyPoint{ia, {0, 0}}, BodyPoint{kGround, {0, 0}}));
  m.add_constraint("P", std::make_shared<Revolute>(BodyPoint{ia, {0.05, 0}}, BodyPoint{ib, {0, 0}}));
  m.add_constraint("twice", std::make_shared<AngleRelation>(std::vector<std::pair<int, double>>{{ia, 1.0}, {ib, -2.0}, {ia, 0.5}},
                                                            0.2, "test"));
  const int drv = m.add_constraint("input", std::make_shared<AngleDriver>(ia, kGround, Motion{1.0, 0.0}));
  m.set_driver(drv, DriverQuantity::angle, 0.3);
  Data data(m);
  ASSERT_TRUE(data.sum_jacobian_entries);
  data.q << 0.01, -0.02, 0.4, 0.06, 0.03, -0.7;
  evaluate_constraints(m, data, 0.0);
  const Eigen::MatrixXd J = data.jacobian();
  EXPECT_DOUBLE_EQ(J(4, 2), 1.5);  // 1 + 0.5 on theta_a
  const double e = 1e-6;
  for (int c = 0; c < m.coordinates(); ++c) {
    const Eigen::VectorXd q0 = data.q;
    data.q(c) = q0(c) + e;
    evaluate_constraints(m, data, 0.0);
    const Eigen::VectorXd plus = data.phi;
    data.q(c) = q0(c) - e;
    evaluate_constraints(m, data, 0.0);
    const Eigen::VectorXd column = (plus - data.phi) / (2 * e);
    data.q = q0;
    for (int r = 0; r < m.equations(); ++r) EXPECT_NEAR(J(r, c), column(r), 1e-8) << r << ", " << c;
  }
  // Solved, the relation holds: theta_a + 0.5 theta_a - 2 theta_b = 0.2 with theta_a = 0.3.
  ASSERT_TRUE(solve_position(m, data, 0.0).converged);
  EXPECT_NEAR(data.q(5), (1.5 * 0.3 - 0.2) / 2.0, 1e-12);
}

}  // namespace
}  // namespace gearkit::kin
