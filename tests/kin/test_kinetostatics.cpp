// Kinetostatics: seed answers, virtual power against Lagrange multipliers, energy balances.
#include <gearkit/kin/kinetostatics.hpp>
#include <gearkit/kin/solve.hpp>

#include <gtest/gtest.h>

#include "mechanisms.hpp"

namespace gearkit::kin {
namespace {

using testing::kDeg;

const TwoForceMember* member(const ForceAnalysis& f, const std::string& name) {
  for (const auto& m : f.two_force_members)
    if (m.name == name) return &m;
  return nullptr;
}

// Seed 004, exam 2021 exercise 2 (lifting platform): at q = {30, 42.6, 69.5} deg the torque on
// the lever is T_m = 113.4 N m and the rod PQ carries F_PQ = 445.1 N in tension. The torque
// does not depend on where the load sits on the platform (the platform translates).
TEST(Kinetostatics, LiftingPlatformSeedAnswers) {
  for (const Eigen::Vector2d& offset : {Eigen::Vector2d(0.3, 0.1), Eigen::Vector2d(-0.2, 0.4)}) {
    Model m = testing::lifting_platform(69.5 * kDeg, offset);
    Data data(m);
    ASSERT_TRUE(solve_position(m, data, 0.0).converged);
    EXPECT_NEAR(data.q(2) / kDeg, 30.0, 1e-6);          // phi1
    EXPECT_NEAR(180.0 - data.q(11) / kDeg, 42.6, 1e-6); // phi2 (rod drawn from P to Q)
    // Seed answer b): phi1'/phi3' = l3 sin(phi2 + phi3) / (l1 sin(phi2 + phi1)).
    const Eigen::VectorXd dq = input_sensitivity(m, data, 0);
    const double ratio = 0.275 * std::sin((42.6 + 69.5) * kDeg) / (0.400 * std::sin((42.6 + 30) * kDeg));
    EXPECT_NEAR(dq(2) / dq(14), ratio, 1e-9);
    ASSERT_TRUE(solve_velocity(m, data));
    ASSERT_TRUE(solve_acceleration(m, data));
    const ForceAnalysis f = solve_forces(m, data);
    ASSERT_EQ(f.effort_lagrange.size(), 1u);
    EXPECT_NEAR(f.effort_virtual_power[0], 113.4, 0.05);
    EXPECT_NEAR(f.effort_lagrange[0], f.effort_virtual_power[0], 1e-9);
    const TwoForceMember* rod = member(f, "rod");
    ASSERT_NE(rod, nullptr);
    EXPECT_TRUE(rod->tension());
    EXPECT_NEAR(rod->axial_force, 445.1, 0.1);
  }
}

// Seed 004, 2020-21 second paper, exercise 2 (spring compressor): with T = 20 N m on the bar
// RP at phi = (43.76, 46.24, 0) deg the spring force is F_m = 441.8 N and the rod PQ carries
// F_PQ = 1.112 kN in tension. Our half model carries half the torque for the same F_m.
TEST(Kinetostatics, SpringCompressorSeedAnswers) {
  Model m = testing::spring_compressor((90 - 43.76) * kDeg);
  const int lever = 2;
  m.add_force({{lever, *m.bodies()[2].point("V")}, {0.0, 441.8}, "spring on V2"});
  Data data(m);
  ASSERT_TRUE(solve_position(m, data, 0.0).converged);
  ASSERT_TRUE(solve_velocity(m, data));
  // Seed answer b): phi3' = -l1 cos(phi2 - phi1) / (l3 sin(phi2 - phi3)) phi1'; both angles
  // are measured clockwise in the seed, so the ratio is that of our counter-clockwise angles.
  const double expected = -0.009 * std::cos(2.48 * kDeg) / (0.055 * std::sin(46.24 * kDeg));
  EXPECT_NEAR(data.qd(8) / data.qd(2), expected, 1e-9);
  ASSERT_TRUE(solve_acceleration(m, data));
  const ForceAnalysis f = solve_forces(m, data);
  EXPECT_NEAR(2.0 * f.effort_virtual_power[0], -20.0, 0.02);  // clockwise, i.e. increasing phi1
  EXPECT_NEAR(f.effort_lagrange[0], f.effort_virtual_power[0], 1e-9);
  const TwoForceMember* rod = member(f, "rod");
  ASSERT_NE(rod, nullptr);
  EXPECT_TRUE(rod->tension());
  EXPECT_NEAR(rod->axial_force, 1112.0, 1.0);
}

// Inverse kinetostatics, seed 004 B2 d): the torque T = 20 N m given (10 N m clockwise on the
// half model), the spring force F_m is the unknown. The seed's value with its formula corrected
// (docs/seeds.md): F_m = T l3 sin(phi2 - phi3) / (2 l1 (l3 + l4) cos(phi3) cos(phi2 - phi1)) =
// 441.8 N with l1 = 9, l3 = 55, l3 + l4 = 100 mm.
TEST(Kinetostatics, SpringForceFromTheGivenTorque) {
  Model m = testing::spring_compressor((90 - 43.76) * kDeg);
  m.add_force({{2, *m.bodies()[2].point("V")}, {0.0, 1.0}, "F_m", true});
  m.set_driver_effort(0, -10.0);
  Data data(m);
  ASSERT_TRUE(solve_position(m, data, 0.0).converged);
  ASSERT_TRUE(solve_velocity(m, data));
  ASSERT_TRUE(solve_acceleration(m, data));
  const ForceAnalysis f = solve_forces(m, data);
  ASSERT_EQ(f.unknown_loads.size(), 1u);
  const double formula = 20.0 * 0.055 * std::sin(46.24 * kDeg) / (2 * 0.009 * 0.100 * std::cos(0.0) * std::cos(2.48 * kDeg));
  EXPECT_NEAR(f.unknown_loads[0].value, formula, 1e-9);
  EXPECT_NEAR(f.unknown_loads[0].value, 441.8, 0.05);
  EXPECT_NEAR(f.unknown_loads[0].force.y(), formula, 1e-9);
  EXPECT_NEAR(f.effort_virtual_power[0], -10.0, 1e-12);  // the given effort, reproduced
  EXPECT_NEAR(f.effort_lagrange[0], -10.0, 1e-9);
  // Two unknowns need two given efforts.
  m.add_torque({1, 1.0, "extra", true});
  Data d2(m);
  ASSERT_TRUE(solve_position(m, d2, 0.0).converged);
  EXPECT_THROW(solve_forces(m, d2), std::invalid_argument);
}

// Inverse kinetostatics with friction: a block pushed up an incline (theta, mu) by a given force
// E along it, held back by an unknown horizontal force P (which also lifts it off the incline by
// P sin(theta)): E = m g sin(theta) + P cos(theta) + mu (m g cos(theta) - P sin(theta)), so
// P = (E - m g (sin + mu cos)) / (cos - mu sin).
TEST(Kinetostatics, UnknownLoadWithFriction) {
  const double theta = 25 * kDeg, mass = 3.0, g = 9.81, mu = 0.25, E = 60.0;
  Model m;
  m.ground().points = {{"O", {0, 0}}};
  const int block = testing::add_link(m, "block", theta, {{"P", {0, 0}}}, mass, "P");
  const BodyPoint p = testing::at(m, block, "P"), o{kGround, {0, 0}};
  const Eigen::Vector2d axis(std::cos(theta), std::sin(theta));
  const int guide = m.add_constraint("guide", std::make_shared<Prismatic>(p, o, axis, theta));
  const int drv = m.add_constraint("push", std::make_shared<DisplacementDriver>(p, o, axis, Motion{0.0, 0.0}));
  m.set_driver(drv, DriverQuantity::displacement, 0.0);
  m.set_driver_effort(0, E);
  m.set_gravity({0, -g});
  m.add_friction({guide, mu, 0.0, 0.0});
  m.add_force({p, {-1.0, 0.0}, "P", true});
  Data data(m);
  ASSERT_TRUE(solve_position(m, data, 0.0).converged);
  ASSERT_TRUE(solve_velocity(m, data));
  ASSERT_TRUE(solve_acceleration(m, data));
  const ForceAnalysis f = solve_forces(m, data);
  const double P = (E - mass * g * (std::sin(theta) + mu * std::cos(theta))) / (std::cos(theta) - mu * std::sin(theta));
  ASSERT_EQ(f.unknown_loads.size(), 1u);
  EXPECT_NEAR(f.unknown_loads[0].value, P, 1e-8);
  EXPECT_NEAR(f.effort_virtual_power[0], E, 1e-8);
}

// Free-body diagrams: every moving body's forces (reactions, driver, weights, inertia, loads)
// balance, forces and moments, on a four-bar with masses, accelerations, friction in every pin
// and a load, and on the lifting platform (a load on the platform, two-force rod).
TEST(Kinetostatics, FreeBodiesBalance) {
  std::vector<Model> models;
  Model m = testing::four_bar({0.04, 0.12, 0.08, 0.1}, 50 * kDeg, Motion{12.0, 30.0});
  Model loaded;
  loaded.ground() = m.ground();
  for (Body b : m.bodies()) {
    b.mass = 0.3;
    b.inertia = 2e-4;
    b.centre_of_mass = 0.5 * b.points.back().second;
    loaded.add_body(b);
  }
  for (const ModelConstraint& c : m.constraints()) loaded.add_constraint(c.name, c.constraint);
  loaded.set_driver(m.drivers()[0].constraint, DriverQuantity::angle, m.drivers()[0].value);
  loaded.set_gravity({0, -9.81});
  loaded.add_force({testing::at(loaded, 1, "B"), {5.0, -2.0}, "pull"});
  for (const char* pin : {"O2", "A", "B", "O4"}) loaded.add_friction({*loaded.constraint_index(pin), 0.2, 0.006, 0.0});
  models.push_back(loaded);
  models.push_back(testing::lifting_platform(69.5 * kDeg));
  for (const Model& model : models) {
    Data data(model);
    ASSERT_TRUE(solve_position(model, data, 0.0).converged);
    ASSERT_TRUE(solve_velocity(model, data));
    ASSERT_TRUE(solve_acceleration(model, data));
    const ForceAnalysis f = solve_forces(model, data);
    const std::vector<FreeBody> fb = free_bodies(model, data, f);
    ASSERT_EQ(fb.size(), model.bodies().size());
    for (const FreeBody& b : fb) {
      Eigen::Vector2d sum = Eigen::Vector2d::Zero();
      double moment = 0.0, scale = 1.0;
      for (const BodyForce& x : b.forces) {
        sum += x.force;
        moment += x.moment + cross(x.at, x.force);  // about the ground origin
        scale = std::max(scale, x.force.norm());
      }
      EXPECT_LT(sum.norm(), 1e-9 * scale) << b.name;
      EXPECT_LT(std::abs(moment), 1e-9 * scale) << b.name;
    }
  }
}

// A revolute's reaction balances the forces on a free body: on the massless crank, the force
// from the ground plus the force from the coupler plus the driving torque's zero resultant.
TEST(Kinetostatics, ReactionsBalanceEveryBody) {
  Model m = testing::lifting_platform(69.5 * kDeg);
  Data data(m);
  ASSERT_TRUE(solve_position(m, data, 0.0).converged);
  solve_velocity(m, data);
  solve_acceleration(m, data);
  const ForceAnalysis f = solve_forces(m, data);
  // Sum of forces on the platform (P, R joints + weight) must vanish.
  Eigen::Vector2d sum(0, -50.0 * 9.81);
  for (const ConstraintReaction& r : f.reactions) {
    if (r.name == "P_platform" || r.name == "R") sum -= r.force;  // platform is their second body
  }
  EXPECT_NEAR(sum.norm(), 0.0, 1e-9);
}

// Energy balance: with gravity and a spring (conservative) the work of the driving torque over
// a full crank turn is zero, and over part of it equals the change of potential energy.
// Quasi-static and at constant crank speed with inertia both hold.
TEST(Kinetostatics, DrivingTorqueWorkEqualsEnergyChange) {
  const testing::FourBarDims dims{0.040, 0.120, 0.080, 0.100};
  Model m = testing::four_bar(dims, 0.0, Motion{10.0, 0.0});
  Model loaded;
  loaded.ground() = m.ground();
  for (std::size_t i = 0; i < m.bodies().size(); ++i) {
    Body b = m.bodies()[i];
    b.mass = 0.5 + static_cast<double>(i);
    b.centre_of_mass = b.points.back().second * 0.5;
    b.inertia = 1e-3 * (1.0 + static_cast<double>(i));
    loaded.add_body(b);
  }
  for (const ModelConstraint& c : m.constraints()) loaded.add_constraint(c.name, c.constraint);
  loaded.set_driver(4, DriverQuantity::angle, 0.0);
  loaded.set_gravity({0, -9.81});
  loaded.add_spring({{2, *loaded.bodies()[2].point("B")}, {kGround, {0.02, 0.15}}, 500.0, 0.05, 3.0, "k"});
  Data data(loaded);
  const int n = 3600;
  const double step = 2 * M_PI / n;
  double work = 0.0, previous_torque = 0.0;
  double energy0 = 0.0;
  for (int k = 0; k <= n; ++k) {
    data.inputs(0) = k * step;
    ASSERT_TRUE(solve_position(loaded, data, 0.0).converged) << k;
    ASSERT_TRUE(solve_velocity(loaded, data));
    ASSERT_TRUE(solve_acceleration(loaded, data));
    const double torque = solve_forces(loaded, data).effort_virtual_power[0];
    const double energy = potential_energy(loaded, data) + kinetic_energy(loaded, data);
    if (k == 0) energy0 = energy;
    if (k > 0) work += 0.5 * (torque + previous_torque) * step;  // trapezoid on theta
    previous_torque = torque;
    if (k == n / 3) {
      EXPECT_NEAR(work, energy - energy0, 1e-5 * (1.0 + std::abs(energy - energy0)));
    }
  }
  EXPECT_NEAR(work, 0.0, 1e-5);
}

TEST(Kinetostatics, RefusesASingularConfiguration) {
  // Pantograph driven by the slider exactly at its dead point s_max = 346.41 mm.
  Model m = testing::pantograph(-60 * kDeg, true, std::sqrt(0.4 * 0.4 - 0.2 * 0.2));
  Data data(m);
  solve_position(m, data, 0.0);
  m.add_torque({0, 1.0, "t"});
  EXPECT_THROW(solve_forces(m, data), std::runtime_error);
}

}  // namespace
}  // namespace gearkit::kin
