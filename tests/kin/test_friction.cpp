// Coulomb friction in the kinetostatics (friction.hpp): hand derivations (block on an incline,
// slider-crank with a sliding or a journal friction, a wedge, a lever wedged on a rod), the
// energy balance of the dissipated power, virtual power against the multipliers.
#include <gearkit/kin/friction.hpp>
#include <gearkit/kin/kinetostatics.hpp>
#include <gearkit/kin/solve.hpp>

#include <gtest/gtest.h>

#include "mechanisms.hpp"

namespace gearkit::kin {
namespace {

using testing::kDeg;

// A solved state: positions, velocities, accelerations.
void solve_all(const Model& m, Data& data) {
  ASSERT_TRUE(solve_position(m, data, 0.0).converged);
  ASSERT_TRUE(solve_velocity(m, data));
  ASSERT_TRUE(solve_acceleration(m, data));
}

// A block of mass m on a guide inclined at theta, driven along it (up is increasing input).
Model incline(double theta, double mass, double mu, double speed) {
  Model m;
  m.ground().points = {{"O", {0, 0}}};
  const int block = testing::add_link(m, "block", theta, {{"P", {0, 0}}}, mass, "P");
  const BodyPoint p = testing::at(m, block, "P"), o{kGround, {0, 0}};
  const Eigen::Vector2d axis(std::cos(theta), std::sin(theta));  // in the ground's frame
  const int guide = m.add_constraint("guide", std::make_shared<Prismatic>(p, o, axis, theta));
  const int drv = m.add_constraint("push", std::make_shared<DisplacementDriver>(p, o, axis, Motion{speed, 0.0}));
  m.set_driver(drv, DriverQuantity::displacement, 0.0);
  m.set_gravity({0, -9.81});
  m.add_friction({guide, mu, 0.0, 0.0});
  return m;
}

// Block on an incline (any statics text, e.g. Beer & Johnston, Vector Mechanics, ch. 8): pushing
// it up along the incline takes F = m g (sin theta + mu cos theta); holding it while it slides
// down takes m g (sin theta - mu cos theta); it cannot slide down by its weight (self-locking)
// once mu >= tan theta. Efficiencies: up tan(theta)/(tan(theta) + mu); down (the weight drives)
// 1 - mu / tan(theta).
TEST(Friction, BlockOnAnInclineByHand) {
  const double theta = 30 * kDeg, mass = 2.0, g = 9.81;
  for (const double mu : {0.3, 0.7}) {
    for (const double speed : {0.0, 0.5}) {  // quasi-static and moving: the same forces (no acceleration)
      const Model m = incline(theta, mass, mu, speed);
      Data data(m);
      solve_all(m, data);
      const ForceAnalysis f = solve_forces(m, data);
      ASSERT_TRUE(f.friction);
      const double up = mass * g * (std::sin(theta) + mu * std::cos(theta));
      const double down = mass * g * (std::sin(theta) - mu * std::cos(theta));
      EXPECT_NEAR(f.effort_virtual_power[0], up, 1e-9) << mu;
      EXPECT_NEAR(f.effort_lagrange[0], up, 1e-9);
      EXPECT_NEAR(f.friction->effort_ideal[0], mass * g * std::sin(theta), 1e-9);
      EXPECT_NEAR(f.friction->forward.effort[0], up, 1e-9);
      EXPECT_NEAR(f.friction->reverse.effort[0], down, 1e-9);
      EXPECT_NEAR(f.friction->forward.efficiency[0], std::tan(theta) / (std::tan(theta) + mu), 1e-12);
      EXPECT_NEAR(f.friction->reverse.efficiency[0], 1.0 - mu / std::tan(theta), 1e-12);
      EXPECT_FALSE(f.friction->forward.self_locking);
      EXPECT_FALSE(f.friction->reverse.wedged);  // the normal force does not grow with friction
      EXPECT_EQ(f.friction->reverse.self_locking, mu >= std::tan(theta));
      // Self-locking in reverse from mu = tan(theta), whatever mu is given.
      EXPECT_NEAR(f.friction->reverse.critical_factor * mu, std::tan(theta), 1e-12);
      EXPECT_TRUE(std::isinf(f.friction->forward.critical_factor));
      ASSERT_EQ(f.friction->joints.size(), 1u);
      EXPECT_NEAR(f.friction->joints[0].normal, mass * g * std::cos(theta), 1e-9);
      EXPECT_NEAR(f.friction->joints[0].friction, -mu * mass * g * std::cos(theta), 1e-9);  // on the block, down the slope
      EXPECT_NEAR(f.friction->dissipated_power, mu * mass * g * std::cos(theta) * speed, 1e-12);
    }
  }
}

// Slider-crank O A B, slider on the x axis, a load P along +x on the slider; at 60 deg the crank
// turning counter-clockwise moves the slider towards -x.
struct SliderCrank {
  double r = 0.05, l = 0.2, theta = 60 * kDeg, load = 1000.0;
};

Model slider_crank(const SliderCrank& s, double omega) {
  Model m;
  m.ground().points = {{"O", {0, 0}}};
  const Eigen::Vector2d A = testing::polar(s.r, s.theta);
  const Eigen::Vector2d B(A.x() + std::sqrt(s.l * s.l - A.y() * A.y()), 0.0);
  const int crank = testing::add_link(m, "crank", s.theta, {{"O", {0, 0}}, {"A", A}});
  const int rod = testing::add_link(m, "rod", std::atan2(B.y() - A.y(), B.x() - A.x()), {{"A", A}, {"B", B}});
  const int slider = testing::add_link(m, "slider", 0.0, {{"B", B}});
  testing::pin(m, "O", crank, "O", kGround, "O");
  testing::pin(m, "A", crank, "A", rod, "A");
  testing::pin(m, "B", rod, "B", slider, "B");
  m.add_constraint("guide", std::make_shared<Prismatic>(testing::at(m, slider, "B"), BodyPoint{kGround, {0, 0}},
                                                        Eigen::Vector2d(1, 0), 0.0));
  const int drv = m.add_constraint("crank", std::make_shared<AngleDriver>(crank, kGround, Motion{omega, 0.0}));
  m.set_driver(drv, DriverQuantity::angle, s.theta);
  m.add_force({testing::at(m, slider, "B"), {s.load, 0.0}, "P"});
  return m;
}

// Hand derivation: the rod is a two-force member with tension F along u = (A - B)/l; the slider's
// balance along x, F u_x + P + mu |F u_y| = 0 (the friction opposes its motion towards -x), gives
// F = P / (-u_x - mu u_y); the crank's torque T = F (A x u) (z component).
TEST(Friction, SliderCrankWithSlidingFrictionByHand) {
  const SliderCrank s;
  const double mu = 0.2;
  Model m = slider_crank(s, 0.0);
  m.add_friction({*m.constraint_index("guide"), mu, 0.0, 0.0});
  Data data(m);
  solve_all(m, data);
  const ForceAnalysis f = solve_forces(m, data);
  const Eigen::Vector2d A = testing::polar(s.r, s.theta);
  const Eigen::Vector2d B(A.x() + std::sqrt(s.l * s.l - A.y() * A.y()), 0.0);
  const Eigen::Vector2d u = (A - B) / s.l;
  const double F = s.load / (-u.x() - mu * u.y()), F0 = s.load / -u.x();
  const double arm = cross(A, u);
  EXPECT_NEAR(f.effort_virtual_power[0], F * arm, 1e-9);
  EXPECT_NEAR(f.effort_lagrange[0], F * arm, 1e-9);
  EXPECT_NEAR(f.friction->effort_ideal[0], F0 * arm, 1e-9);
  EXPECT_NEAR(f.friction->forward.efficiency[0], F0 / F, 1e-12);
  ASSERT_EQ(f.two_force_members.size(), 1u);  // the rod, whose pins have no friction
  EXPECT_NEAR(f.two_force_members[0].axial_force, F, 1e-9);
  EXPECT_NEAR(std::abs(f.friction->joints[0].normal), F * u.y(), 1e-9);
}

// The journal friction of the crank's main bearing: the crank's pin force is the rod force F0
// (frictionless slider), and the friction circle rho = r sin(atan mu) adds the couple rho F0:
// T = F0 (A x u) + rho F0 when the crank turns counter-clockwise, minus when clockwise.
TEST(Friction, FrictionCircleOfTheCrankBearingByHand) {
  const SliderCrank s;
  const double mu = 0.15, radius = 0.01, rho = radius * mu / std::sqrt(1 + mu * mu);
  for (const double omega : {0.0, 10.0, -10.0}) {
    Model m = slider_crank(s, omega);
    m.add_friction({*m.constraint_index("O"), mu, radius, 0.0});
    Data data(m);
    solve_all(m, data);
    const ForceAnalysis f = solve_forces(m, data);
    const Eigen::Vector2d A = testing::polar(s.r, s.theta);
    const Eigen::Vector2d B(A.x() + std::sqrt(s.l * s.l - A.y() * A.y()), 0.0);
    const Eigen::Vector2d u = (A - B) / s.l;
    const double F0 = s.load / -u.x();
    const double sense = omega < 0 ? -1.0 : 1.0;  // quasi-static: increasing input (ccw)
    EXPECT_NEAR(f.effort_virtual_power[0], F0 * cross(A, u) + sense * rho * F0, 1e-9) << omega;
    EXPECT_NEAR(f.effort_lagrange[0], f.effort_virtual_power[0], 1e-9);
    EXPECT_NEAR(f.friction->joints[0].normal, F0, 1e-9);              // |pin force|
    EXPECT_NEAR(f.friction->joints[0].friction, -sense * rho * F0, 1e-9);  // couple on the crank
    EXPECT_NEAR(f.friction->dissipated_power, rho * F0 * std::abs(omega), 1e-9);
  }
}

// Energy balance with friction everywhere, moving and accelerating, with masses: the driver's
// power with friction exceeds the frictionless one by exactly the power dissipated in the joints;
// and the multipliers agree with virtual power.
TEST(Friction, DissipatedPowerClosesTheEnergyBalance) {
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
  loaded.add_torque({2, -3.0, "brake"});
  for (const char* pin : {"O2", "A", "B", "O4"}) loaded.add_friction({*loaded.constraint_index(pin), 0.2, 0.006, 0.0});
  Data data(loaded);
  solve_all(loaded, data);
  const ForceAnalysis f = solve_forces(loaded, data);
  ASSERT_TRUE(f.friction);
  const double omega = data.qd(2);
  EXPECT_NEAR(f.effort_virtual_power[0], f.effort_lagrange[0], 1e-9);
  EXPECT_NEAR((f.effort_virtual_power[0] - f.friction->effort_ideal[0]) * omega, f.friction->dissipated_power, 1e-9);
  EXPECT_GT(f.friction->dissipated_power, 0.0);
  // Each joint's dissipation is |M_f| times its relative angular velocity.
  for (const JointFrictionForce& j : f.friction->joints) EXPECT_NEAR(j.power, std::abs(j.friction * j.sliding), 1e-12);
  // Without friction the same model gives the ideal effort.
  Model ideal = loaded;
  Model clean;
  clean.ground() = ideal.ground();
  for (const Body& b : ideal.bodies()) clean.add_body(b);
  for (const ModelConstraint& c : ideal.constraints()) clean.add_constraint(c.name, c.constraint);
  clean.set_driver(ideal.drivers()[0].constraint, DriverQuantity::angle, ideal.drivers()[0].value);
  clean.set_gravity({0, -9.81});
  clean.add_torque({2, -3.0, "brake"});
  Data d2(clean);
  solve_all(clean, d2);
  EXPECT_NEAR(solve_forces(clean, d2).effort_virtual_power[0], f.friction->effort_ideal[0], 1e-9);
}

// Wedge brake (seed 004, paper D, exercise 1): a drum of radius r, a massless wedge pushed by F0
// along a vertical frictionless guide, the contact normal at alpha above the horizontal. The
// wedge's balance N sin(alpha) -/+ mu N cos(alpha) = F0 gives N; the drum's torque is mu N r.
// Turning the drum clockwise (the wedge pushed out) takes T = mu F0 r / (sin alpha + mu cos alpha);
// counter-clockwise N -> infinity as mu -> tan(alpha): it wedges from mu = tan(alpha).
TEST(Friction, WedgeBrakeByHand) {
  const double r = 0.06, F0 = 15.0, alpha = 15 * kDeg;
  for (const double mu : {0.1, 0.2, 0.4}) {
    Model m;
    m.ground().points = {{"O", {0, 0}}, {"G", {-r * std::cos(alpha) - 0.02, r * std::sin(alpha)}}};
    const int drum = testing::add_link(m, "drum", 0.0, {{"O", {0, 0}}});
    const Eigen::Vector2d A(-r * std::cos(alpha), r * std::sin(alpha));
    const int wedge = testing::add_link(m, "wedge", 0.0, {{"A", A}, {"S", A + Eigen::Vector2d(-0.02, 0)}});
    testing::pin(m, "O", drum, "O", kGround, "O");
    m.add_constraint("guide", std::make_shared<Prismatic>(testing::at(m, wedge, "S"), testing::at(m, kGround, "G"),
                                                          Eigen::Vector2d(0, 1), 0.0));
    const int contact = m.add_constraint("A", std::make_shared<Contact>(testing::at(m, drum, "O"), r, testing::at(m, wedge, "A"),
                                                                         Eigen::Vector2d(std::cos(75 * kDeg), std::sin(75 * kDeg)), -1));
    const int drv = m.add_constraint("drum", std::make_shared<AngleDriver>(drum, kGround, Motion{-1.0, 0.0}));
    m.set_driver(drv, DriverQuantity::angle, 0.0);
    m.add_force({testing::at(m, wedge, "S"), {0.0, -F0}, "F0"});
    m.add_friction({contact, mu, 0.0, 0.0});
    Data data(m);
    solve_all(m, data);
    const ForceAnalysis f = solve_forces(m, data);
    ASSERT_TRUE(f.friction);
    const double N = F0 / (std::sin(alpha) + mu * std::cos(alpha));
    EXPECT_NEAR(f.effort_virtual_power[0], -mu * N * r, 1e-12) << mu;  // clockwise
    EXPECT_NEAR(f.friction->joints[0].normal, N, 1e-9);
    EXPECT_TRUE(std::isinf(f.friction->forward.wedging_factor));  // N falls as mu grows: never wedges
    EXPECT_EQ(f.friction->reverse.wedged, mu >= std::tan(alpha));
    EXPECT_NEAR(f.friction->reverse.critical_factor * mu, std::tan(alpha), 1e-12);
    if (mu < std::tan(alpha)) {
      const double N_ccw = F0 / (std::sin(alpha) - mu * std::cos(alpha));
      EXPECT_NEAR(f.friction->reverse.effort[0], mu * N_ccw * r, 1e-12);
    } else {
      EXPECT_TRUE(std::isnan(f.friction->reverse.effort[0]));
    }
  }
}

// Door retainer (seed 004, paper B, exercise 1): a lever resting at O (vertical support only)
// with the edges A, B of its hole (diameter d_i, tilt alpha, cos alpha = d_e/d_i) on the faces
// of a rod (diameter d_e) at horizontal distances e and e + d_e from O; a spring torque tau tilts
// it. Pulling the rod up, the lever's balance about O gives
// tau + mu N (2e + d_e) - N d_e tan(alpha) = 0: N = tau / (d_e tan(alpha) - mu (2e + d_e)), the
// rod needs 2 mu N, and N grows without bound at mu_min = d_e tan(alpha) / (2e + d_e).
TEST(Friction, LeverWedgedOnARodByHand) {
  const double de = 0.010, di = 0.0103, e = 0.013, tau = 0.01;
  const double alpha = std::acos(de / di), t = std::tan(alpha);
  const double mu_min = de * t / (2 * e + de);
  for (const double mu : {0.03, 0.06, 0.09}) {
    Model m;
    m.ground().points = {{"O", {0, 0}}, {"G", {e + de / 2, 0}}};
    const int rod = testing::add_link(m, "rod", 0.0, {{"L", {e, 0}}, {"C", {e + de / 2, 0}}, {"R", {e + de, 0}}});
    const int lever = testing::add_link(m, "lever", alpha, {{"O", {0, 0}}, {"A", {e, e * t}}, {"B", {e + de, (e + de) * t}}});
    const Eigen::Vector2d up(0, 1);
    const int guide = m.add_constraint("guide", std::make_shared<Prismatic>(testing::at(m, rod, "C"), testing::at(m, kGround, "G"), up, 0.0));
    m.add_constraint("O", std::make_shared<PinInSlot>(testing::at(m, lever, "O"), testing::at(m, kGround, "O"), Eigen::Vector2d(1, 0)));
    const int a = m.add_constraint("A", std::make_shared<Contact>(testing::at(m, lever, "A"), 0.0, testing::at(m, rod, "L"), up, 1));
    const int b = m.add_constraint("B", std::make_shared<Contact>(testing::at(m, lever, "B"), 0.0, testing::at(m, rod, "R"), up, -1));
    const int drv = m.add_constraint("pull", std::make_shared<DisplacementDriver>(testing::at(m, rod, "C"), testing::at(m, kGround, "G"),
                                                                               up, Motion{0.0, 0.0}));
    m.set_driver(drv, DriverQuantity::displacement, 0.0);
    m.add_torque({lever, tau, "spring"});
    m.add_friction({a, mu, 0.0, 0.0});
    m.add_friction({b, mu, 0.0, 0.0});
    (void)guide;
    Data data(m);
    solve_all(m, data);
    const ForceAnalysis f = solve_forces(m, data);
    ASSERT_TRUE(f.friction);
    EXPECT_NEAR(f.friction->forward.wedging_factor * mu, mu_min, 1e-12) << mu;
    EXPECT_EQ(f.friction->forward.wedged, mu >= mu_min);
    EXPECT_TRUE(std::isinf(f.friction->reverse.wedging_factor));  // pushing the rod down never wedges
    if (mu < mu_min) {
      const double N = tau / (de * t - mu * (2 * e + de));
      EXPECT_NEAR(f.effort_virtual_power[0], 2 * mu * N, 1e-9);
      EXPECT_NEAR(f.effort_lagrange[0], 2 * mu * N, 1e-9);
      for (const JointFrictionForce& j : f.friction->joints) EXPECT_NEAR(j.normal, N, 1e-9);
    } else {
      EXPECT_TRUE(std::isnan(f.effort_virtual_power[0]));
      EXPECT_FALSE(f.warnings.empty());
    }
  }
}

}  // namespace
}  // namespace gearkit::kin
