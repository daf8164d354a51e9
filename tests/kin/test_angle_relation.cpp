// Linear relations between link angles (angle_relation.hpp), the form of gear meshes and
// epicyclic trains inside the solver, against the ratios they stand for.
#include <gearkit/kin/angle_relation.hpp>
#include <gearkit/kin/solve.hpp>

#include <gtest/gtest.h>

#include <memory>

namespace gearkit::kin {
namespace {

// Two gears on ground pivots, z1 = 20 driving z2 = 50 (external mesh): theta2 = -(20/50)
// theta1 + phase, i.e. theta2 + 0.4 theta1 = phase; a ground term changes nothing.
TEST(AngleRelation, ExternalMeshRatio) {
  Model m;
  Body g1, g2;
  g1.name = "pinion";
  g2.name = "wheel";
  g2.position_guess = {0.070, 0.0};
  const int p = m.add_body(g1), w = m.add_body(g2);
  m.add_constraint("O1", std::make_shared<Revolute>(BodyPoint{p, {0, 0}}, BodyPoint{kGround, {0, 0}}));
  m.add_constraint("O2", std::make_shared<Revolute>(BodyPoint{w, {0, 0}}, BodyPoint{kGround, {0.070, 0}}));
  const auto relation = std::make_shared<AngleRelation>(std::vector<std::pair<int, double>>{{w, 1.0}, {p, 0.4}, {kGround, 3.0}},
                                                        0.1, "gear_mesh");
  EXPECT_EQ(relation->kind(), "gear_mesh");
  EXPECT_EQ(relation->equations(), 1);
  EXPECT_EQ(relation->bodies(), (std::vector<int>{w, p, kGround}));
  m.add_constraint("mesh", relation);
  const int drv = m.add_constraint("input", std::make_shared<AngleDriver>(p, kGround, Motion{10.0, 0.0}));
  m.set_driver(drv, DriverQuantity::angle, 0.5);
  Data data(m);
  ASSERT_TRUE(solve_position(m, data, 0.0).converged);
  ASSERT_TRUE(solve_velocity(m, data));
  ASSERT_TRUE(solve_acceleration(m, data));
  EXPECT_NEAR(data.q(5), 0.1 - 0.4 * 0.5, 1e-12);
  EXPECT_NEAR(data.qd(5) / data.qd(2), -20.0 / 50.0, 1e-12);  // omega2 / omega1 = -z1/z2
  EXPECT_NEAR(data.qdd(5), 0.0, 1e-12);                       // constant speed, linear relation
}

}  // namespace
}  // namespace gearkit::kin
