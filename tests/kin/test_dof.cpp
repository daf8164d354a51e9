// Degrees of freedom: Gruebler-Kutzbach count and Jacobian rank.
#include <gearkit/kin/dof.hpp>
#include <gearkit/kin/solve.hpp>

#include <gtest/gtest.h>

#include "mechanisms.hpp"

namespace gearkit::kin {
namespace {

using testing::kDeg;

// Seed 004, exam 2020-21 exercise 1: 5 moving bodies x 3 - 6 revolutes x 2 - 1 prismatic x 2 = 1,
// and no redundancy since the mobility is also 1.
TEST(Dof, PantographGrueblerAndRank) {
  Model m = testing::pantograph(-50 * kDeg);
  Data data(m);
  ASSERT_TRUE(solve_position(m, data, 0.0).converged);
  const DofReport r = dof(m, data);
  EXPECT_EQ(r.moving_bodies, 5);
  EXPECT_EQ(r.gruebler, 1);
  EXPECT_EQ(r.dof, 1);
  EXPECT_EQ(r.redundant, 0);
  EXPECT_EQ(r.drivers, 1);
  EXPECT_NE(r.gruebler_count.find("3*5"), std::string::npos) << r.gruebler_count;
  EXPECT_NE(r.gruebler_count.find("= 1"), std::string::npos) << r.gruebler_count;
}

// Seed 004, exam 2021 exercise 2: 5 bodies, 7 revolutes: 15 - 14 = 1.
TEST(Dof, LiftingPlatform) {
  Model m = testing::lifting_platform(69.5 * kDeg);
  Data data(m);
  ASSERT_TRUE(solve_position(m, data, 0.0).converged);
  const DofReport r = dof(m, data);
  EXPECT_EQ(r.gruebler, 1);
  EXPECT_EQ(r.dof, 1);
  EXPECT_EQ(r.redundant, 0);
}

// A parallelogram with a third parallel link: Gruebler says 3*4 - 2*6 = 0, yet it moves with
// one freedom because one link's constraint repeats the others (a redundant constraint).
TEST(Dof, ParallelogramWithExtraLinkIsRedundant) {
  const double a = 0.05, d = 0.2, th = 60 * kDeg;
  Model m;
  m.ground().points = {{"O2", {0, 0}}, {"M", {d / 2, 0}}, {"O4", {d, 0}}};
  const Eigen::Vector2d A = testing::polar(a, th);
  const int crank = testing::add_link(m, "crank", th, {{"O2", {0, 0}}, {"A", A}});
  const int coupler = testing::add_link(m, "coupler", 0.0, {{"A", A}, {"C", A + Eigen::Vector2d(d / 2, 0)}, {"B", A + Eigen::Vector2d(d, 0)}});
  const int rocker = testing::add_link(m, "rocker", th, {{"O4", {d, 0}}, {"B", A + Eigen::Vector2d(d, 0)}});
  const int middle = testing::add_link(m, "middle", th, {{"M", {d / 2, 0}}, {"C", A + Eigen::Vector2d(d / 2, 0)}});
  testing::pin(m, "O2", crank, "O2", kGround, "O2");
  testing::pin(m, "A", crank, "A", coupler, "A");
  testing::pin(m, "B", coupler, "B", rocker, "B");
  testing::pin(m, "O4", rocker, "O4", kGround, "O4");
  testing::pin(m, "M", middle, "M", kGround, "M");
  testing::pin(m, "C", middle, "C", coupler, "C");
  const int drv = m.add_constraint("input", std::make_shared<AngleDriver>(crank, kGround, Motion{1.0, 0.0}));
  m.set_driver(drv, DriverQuantity::angle, 75 * kDeg);
  Data data(m);
  const PositionReport p = solve_position(m, data, 0.0);
  ASSERT_TRUE(p.converged) << p.message;
  EXPECT_NEAR(data.q(8), 75 * kDeg, 1e-9);  // rocker parallel to crank
  const DofReport r = dof(m, data);
  EXPECT_EQ(r.gruebler, 0);
  EXPECT_EQ(r.dof, 1);
  EXPECT_EQ(r.redundant, 1);
  EXPECT_EQ(r.redundant_rows.size(), 1u);
}

}  // namespace
}  // namespace gearkit::kin

namespace gearkit::kin {
namespace {

// A chain of 30 four-bars (each rocker drives the next crank) is large enough for the sparse
// path: 3*61 - 2*91 = 1, and the sparse rank agrees.
TEST(Dof, LargeChainUsesTheSparsePath) {
  Model m;
  m.ground().points = {{"O0", {0, 0}}};
  const testing::FourBarDims f{0.040, 0.120, 0.080, 0.100};
  int crank = testing::add_link(m, "crank", 0.0, {{"O", {0, 0}}, {"A", {f.a, 0}}});
  testing::pin(m, "O0", crank, "O", kGround, "O0");
  double input = 0.0;
  for (int k = 0; k < 30; ++k) {
    const Eigen::Vector2d o2(f.d * k, 0), o4(f.d * (k + 1), 0);
    m.ground().points.emplace_back("O" + std::to_string(k + 1), o4);
    const auto [theta3, theta4] = testing::four_bar_closed_form(f, input);
    const Eigen::Vector2d A = o2 + testing::polar(f.a, input), B = A + testing::polar(f.b, theta3);
    const int coupler = testing::add_link(m, "coupler" + std::to_string(k), theta3, {{"A", A}, {"B", B}});
    const int rocker = testing::add_link(m, "rocker" + std::to_string(k), theta4,
                                         {{"O", o4}, {"B", B}, {"A", o4 + testing::polar(f.a, theta4)}});
    testing::pin(m, "A" + std::to_string(k), crank, "A", coupler, "A");
    testing::pin(m, "B" + std::to_string(k), coupler, "B", rocker, "B");
    testing::pin(m, "O" + std::to_string(k + 1), rocker, "O", kGround, "O" + std::to_string(k + 1));
    crank = rocker;
    input = theta4;
  }
  const int drv = m.add_constraint("input", std::make_shared<AngleDriver>(0, kGround, Motion{1.0, 0.0}));
  m.set_driver(drv, DriverQuantity::angle, 0.0);
  Data data(m);
  ASSERT_TRUE(data.sparse);
  ASSERT_TRUE(solve_position(m, data, 0.0).converged);
  const DofReport r = dof(m, data);
  EXPECT_EQ(r.gruebler, 1);
  EXPECT_EQ(r.dof, 1);
  EXPECT_EQ(r.redundant, 0);
  // Every loop closes at its closed-form angle (the previous rocker angle is the next input).
  double theta = 0.0;
  for (int k = 0; k < 30; ++k) {
    const auto [theta3, theta4] = testing::four_bar_closed_form(f, theta);
    EXPECT_NEAR(data.q(3 * (2 * k + 2) + 2), theta4, 1e-9) << k;
    theta = theta4;
  }
}

}  // namespace
}  // namespace gearkit::kin

namespace gearkit::kin {
namespace {

// Chains of N four-bar loops (each rocker is the next crank), through both rank tests (dense
// up to 64 coordinates, SuiteSparseQR above): the Gruebler-Kutzbach count 3 (2N + 1) -
// 2 (3N + 1) = 1 is the mobility, and no row is redundant.
TEST(Dof, FourBarChainsAgreeWithGruebler) {
  for (const int loops : {1, 10, 11, 100, 1000}) {
    const Model m = testing::four_bar_chain({0.040, 0.120, 0.080, 0.100}, loops, 30 * kDeg);
    Data data(m);
    ASSERT_TRUE(solve_position(m, data, 0.0).converged) << loops;
    const DofReport r = dof(m, data);
    EXPECT_EQ(r.moving_bodies, 2 * loops + 1);
    EXPECT_EQ(r.constraint_equations, 2 * (3 * loops + 1));
    EXPECT_EQ(r.gruebler, 1) << loops;
    EXPECT_EQ(r.rank, 6 * loops + 2) << loops;
    EXPECT_EQ(r.dof, 1) << loops;
    EXPECT_EQ(r.redundant, 0) << loops;
    EXPECT_TRUE(r.redundant_rows.empty()) << loops;
  }
}

// Chains of N parallelograms with a third parallel link in each loop: Gruebler 1 - N, mobility
// 1, hence exactly N redundant rows (a parallelogram with a third equal parallel link is the
// textbook redundant constraint: Norton, Design of Machinery, sec. 2.8 "Paradoxes"). Each
// redundant row belongs to one of the loop's five revolutes; N = 1000 has 9003 coordinates.
TEST(Dof, ParallelogramChainsHaveOneRedundantRowPerLoop) {
  for (const int loops : {1, 5, 30, 300, 1000}) {
    const Model m = testing::parallelogram_chain(loops, 0.05, 0.2, 60 * kDeg);
    Data data(m);
    const DofReport r = dof(m, data);  // at the exactly assembled drawing
    EXPECT_EQ(r.gruebler, 1 - loops);
    EXPECT_EQ(r.dof, 1) << loops;
    EXPECT_EQ(r.redundant, loops) << loops;
    ASSERT_EQ(r.redundant_rows.size(), static_cast<std::size_t>(loops));
    for (const std::string& row : r.redundant_rows) EXPECT_NE(row.find("(revolute)"), std::string::npos) << row;
  }
}

// The sparse and the dense rank test agree on a model that both can take (a 70-coordinate
// parallelogram chain with one link's constraint repeated).
TEST(Dof, SparseAndDenseRankAgree) {
  const Model m = testing::parallelogram_chain(7, 0.05, 0.2, 50 * kDeg);
  Data sparse(m);
  ASSERT_TRUE(sparse.sparse);
  const DofReport a = dof(m, sparse);
  Data dense(m);
  dense.sparse = false;
  const DofReport b = dof(m, dense);
  EXPECT_EQ(a.rank, b.rank);
  EXPECT_EQ(a.redundant, 7);
  EXPECT_EQ(b.redundant, 7);
}

}  // namespace
}  // namespace gearkit::kin
