// Tests for gearkit/elements/gear_mesh.hpp: a geared five-bar built and solved from C++ with no
// YAML, the tooth forces against hand calculations, and the parameter checks.
#include "element_fixtures.hpp"

#include <gearkit/elements/gear_mesh.hpp>
#include <gearkit/kin/kinetostatics.hpp>

namespace gearkit::elements {
namespace {

using namespace testing;

// The geared five-bar of examples/mechanisms/geared_five_bar.yaml, built with the typed
// builders: cranks O1A = 40 mm and O2B = 60 mm on pivots 150 mm apart, coupled by spur gears
// z1 = 20, z2 = 40 (module 5 mm), links AC = 130 mm and BC = 120 mm.
struct GearedFiveBar {
  kin::Model model;
  int gear1, gear2, link1, link2;
};

GearedFiveBar geared_five_bar(double theta1) {
  GearedFiveBar m;
  kin::Model& model = m.model;
  model.ground().points = {{"O1", {0, 0}}, {"O2", {0.150, 0}}};
  m.gear1 = add_body(model, "gear1", {0, 0}, 90 * kDeg, {{"O1", {0, 0}}, {"A", {0.040, 0}}});
  m.gear2 = add_body(model, "gear2", {0.150, 0}, 90 * kDeg, {{"O2", {0, 0}}, {"B", {0.060, 0}}});
  m.link1 = add_body(model, "link1", {0, 0.040}, 60 * kDeg, {{"A", {0, 0}}, {"C", {0.130, 0}}});
  m.link2 = add_body(model, "link2", {0.150, 0.060}, 110 * kDeg, {{"B", {0, 0}}, {"C", {0.120, 0}}});
  revolute(model, "O1", m.gear1, "O1", kin::kGround, "O1");
  revolute(model, "O2", m.gear2, "O2", kin::kGround, "O2");
  revolute(model, "A", m.gear1, "A", m.link1, "A");
  revolute(model, "B", m.gear2, "B", m.link2, "B");
  revolute(model, "C", m.link1, "C", m.link2, "C");
  GearMeshParameters mesh;
  mesh.gear1 = m.gear1;
  mesh.gear2 = m.gear2;
  mesh.z1 = 20;
  mesh.z2 = 40;
  mesh.module = 0.005;
  add_gear_mesh(model, "mesh", mesh);
  drive_angle(model, m.gear1, theta1, 10.0);
  return m;
}

// Closed form: theta2 from the gear ratio (the drawing, 90 deg and 90 deg, is a meshing
// position: theta2 + theta1/2 = 135 deg), then C as the upper intersection of the circles of
// radius AC about A and BC about B.
TEST(GearMesh, GearedFiveBarFromCppMatchesTheClosedForm) {
  for (const double theta1_deg : {90.0, 120.0, 200.0, 330.0}) {
    const double theta1 = theta1_deg * kDeg;
    GearedFiveBar m = geared_five_bar(theta1);
    kin::Data data(m.model);
    solve_all(m.model, data);
    const double theta2 = 135 * kDeg - theta1 / 2;
    EXPECT_NEAR(std::remainder(data.q(3 * m.gear2 + 2) - theta2, 2 * std::numbers::pi), 0.0, 1e-10);
    const Eigen::Vector2d A = 0.040 * Eigen::Vector2d(std::cos(theta1), std::sin(theta1));
    const Eigen::Vector2d B = Eigen::Vector2d(0.150, 0) + 0.060 * Eigen::Vector2d(std::cos(theta2), std::sin(theta2));
    const double d = (B - A).norm(), a = (0.130 * 0.130 - 0.120 * 0.120 + d * d) / (2 * d);
    const Eigen::Vector2d mid = A + a * (B - A) / d, n = kin::perp((B - A) / d);
    const Eigen::Vector2d C1 = mid + std::sqrt(0.130 * 0.130 - a * a) * n, C2 = mid - std::sqrt(0.130 * 0.130 - a * a) * n;
    const Eigen::Vector2d C = C1.y() > C2.y() ? C1 : C2;
    const Eigen::Vector2d solved = kin::point_position(data, point(m.model, m.link1, "C"));
    EXPECT_NEAR((solved - C).norm(), 0.0, 1e-9) << theta1_deg;
    // Velocities: omega2 = -omega1/2.
    EXPECT_NEAR(data.qd(3 * m.gear2 + 2), -5.0, 1e-9);
  }
}

// A pinion z1 = 20 driven against a torque of -10 N m on the gear z2 = 40 (module 2 mm,
// alpha_n = 20 deg), fixed axes, no masses. Hand calculation (ISO 6336-1 nominal load):
// r2 = m z2 / 2 = 40 mm, F_t = 10 / 0.040 = 250 N, F_r = F_t tan 20 deg = 90.9926 N,
// F_n = F_t / cos 20 deg = 266.0444 N; the pinion needs T = 10 z1/z2 = 5 N m.
kin::ForceAnalysis loaded_pair(GearMeshParameters mesh, double load) {
  kin::Model model;
  model.ground().points = {{"O1", {0, 0}}, {"O2", {0.060, 0}}};
  mesh.gear1 = add_body(model, "pinion", {0, 0}, 0.0, {{"O1", {0, 0}}});
  mesh.gear2 = add_body(model, "gear", {0.060, 0}, 0.0, {{"O2", {0, 0}}});
  revolute(model, "O1", mesh.gear1, "O1", kin::kGround, "O1");
  revolute(model, "O2", mesh.gear2, "O2", kin::kGround, "O2");
  add_gear_mesh(model, "mesh", mesh);
  drive_angle(model, mesh.gear1, 0.3);
  model.add_torque({mesh.gear2, load, "load"});
  kin::Data data(model);
  solve_all(model, data);
  return kin::solve_forces(model, data);
}

const kin::ConstraintReaction& mesh_reaction(const kin::ForceAnalysis& f) {
  for (const auto& r : f.reactions)
    if (r.kind == "gear_mesh") return r;
  throw std::logic_error("no gear mesh reaction");
}

GearMeshParameters spur(double module) {
  GearMeshParameters p;
  p.z1 = 20;
  p.z2 = 40;
  p.module = module;
  return p;
}

TEST(GearMesh, SpurToothForcesMatchTheHandCalculation) {
  const kin::ForceAnalysis f = loaded_pair(spur(0.002), -10.0);
  const auto& values = mesh_reaction(f).values;
  EXPECT_NEAR(value_of(values, "T_2"), 10.0, 1e-9);  // the mesh balances the load on the gear
  EXPECT_NEAR(value_of(values, "T_1"), 5.0, 1e-9);   // and resists the driver on the pinion
  EXPECT_NEAR(value_of(values, "F_t"), 250.0, 1e-9);
  EXPECT_NEAR(value_of(values, "F_r"), 90.99256, 1e-5);
  EXPECT_NEAR(value_of(values, "F_n"), 266.04444, 1e-5);
  EXPECT_TRUE(std::isnan(value_of(values, "F_a")));  // spur: no axial force
  EXPECT_NEAR(std::abs(f.effort_virtual_power[0]), 5.0, 1e-9);
}

// Helical, beta = 15 deg: r2 = m_n z2 / (2 cos beta) = 41.4110 mm, F_t = 241.4814 N,
// tan alpha_t = tan 20 deg / cos 15 deg -> F_r = F_t tan alpha_t = 90.9926 N, F_n = F_t /
// (cos 20 deg cos 15 deg) = 266.0444 N (= T / (r_b2 cos beta_b), the same as spur),
// F_a = F_t tan 15 deg = 64.7048 N.
TEST(GearMesh, HelicalToothForcesMatchTheHandCalculation) {
  GearMeshParameters p = spur(0.002);
  p.helix_angle = 15 * kDeg;
  const kin::ForceAnalysis f = loaded_pair(p, -10.0);  // the reaction refers into it
  const auto& values = mesh_reaction(f).values;
  EXPECT_NEAR(value_of(values, "F_t"), 241.48146, 1e-5);
  EXPECT_NEAR(value_of(values, "F_r"), 90.99256, 1e-5);
  EXPECT_NEAR(value_of(values, "F_n"), 266.04444, 1e-5);
  EXPECT_NEAR(value_of(values, "F_a"), 64.70476, 1e-5);
}

TEST(GearMesh, WithoutAModuleOnlyTorques) {
  const kin::ForceAnalysis with_module = loaded_pair(spur(0.002), -10.0);
  const auto& values = mesh_reaction(with_module).values;
  GearMeshParameters p = spur(0.002);
  p.module.reset();
  const kin::ForceAnalysis without_module = loaded_pair(p, -10.0);
  const auto& bare = mesh_reaction(without_module).values;
  EXPECT_EQ(bare.size(), 2u);
  EXPECT_EQ(value_of(bare, "T_2"), value_of(values, "T_2"));
}

kin::Model two_bodies() {
  kin::Model model;
  add_body(model, "a", {0, 0}, 0.0, {{"O", {0, 0}}});
  add_body(model, "b", {0, 0}, 0.0, {{"O", {0, 0}}});
  return model;
}

std::string field_of(GearMeshParameters p) {
  try {
    make_gear_mesh(two_bodies(), p);
  } catch (const kin::ElementError& e) {
    return e.field();
  }
  return "";
}

TEST(GearMesh, ImpossibleParametersNameTheirField) {
  GearMeshParameters p = spur(0.002);
  p.gear1 = 0;
  p.gear2 = 1;
  EXPECT_EQ(field_of(p), "");
  GearMeshParameters q = p;
  q.gear2 = 7;
  EXPECT_EQ(field_of(q), "gear2");
  q = p;
  q.gear2 = 0;
  EXPECT_EQ(field_of(q), "gear2");
  q = p;
  q.z1 = 0;
  EXPECT_EQ(field_of(q), "z1");
  q = p;
  q.internal = true;  // a ring of 40 teeth round a pinion of 20 is fine, of 10 not
  EXPECT_EQ(field_of(q), "");
  q.z2 = 10;
  EXPECT_EQ(field_of(q), "z2");
  q = p;
  q.module = 0.0;
  EXPECT_EQ(field_of(q), "module");
  q = p;
  q.pressure_angle = 45 * kDeg;
  EXPECT_EQ(field_of(q), "pressure_angle");
  q = p;
  q.helix_angle = -50 * kDeg;
  EXPECT_EQ(field_of(q), "helix_angle");
}

}  // namespace
}  // namespace gearkit::elements

namespace gearkit::elements {
namespace {

// Phi_q, Phi_t and gamma of the mesh against finite differences of its Phi (issue 27, item 7):
// external and internal pairs, on fixed axes and on a moving carrier.
TEST(GearMesh, DerivativesMatchFiniteDifferences) {
  expect_derivatives(geared_five_bar(90 * kDeg).model, "mesh");
  kin::Model model;
  const int sun = add_body(model, "sun", {0, 0}, 0.3, {});
  const int ring = add_body(model, "ring", {0, 0}, -0.2, {});
  const int arm = add_body(model, "arm", {0, 0}, 0.1, {});
  GearMeshParameters p;
  p.gear1 = sun;
  p.gear2 = ring;
  p.carrier = arm;
  p.z1 = 18;
  p.z2 = 72;
  p.internal = true;
  expect_derivatives(*make_gear_mesh(model, p));
}

}  // namespace
}  // namespace gearkit::elements
