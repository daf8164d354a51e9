// Tests for gearkit/elements/epicyclic_train.hpp: Willis' equation of a simple planetary built
// from C++, its speeds and torques against the textbook ratio.
#include "element_fixtures.hpp"

#include <gearkit/elements/epicyclic_train.hpp>
#include <gearkit/kin/kinetostatics.hpp>

namespace gearkit::elements {
namespace {

using namespace testing;

// Simple planetary, sun 24, planet 18, ring 60 held (the ground), carrier output: tau0 =
// -z_s/z_r = -0.4 (one external mesh), i = 1 + z_r/z_s = 3.5 (e.g. Shigley, Mechanical
// Engineering Design, sec. 13-13). A load of -7 N m on the carrier needs 7/3.5 = 2 N m on the
// sun, and the ring is held with 7 - 2 = 5 N m.
TEST(EpicyclicTrain, SimplePlanetarySpeedsAndTorques) {
  kin::Model model;
  model.ground().points = {{"O", {0, 0}}};
  const int sun = add_body(model, "sun", {0, 0}, 0.0, {{"O", {0, 0}}});
  const int carrier = add_body(model, "carrier", {0, 0}, 0.0, {{"O", {0, 0}}});
  revolute(model, "sun bearing", sun, "O", kin::kGround, "O");
  revolute(model, "carrier bearing", carrier, "O", kin::kGround, "O");
  EpicyclicTrainParameters p;
  p.input = sun;
  p.output = kin::kGround;
  p.arm = carrier;
  p.driving = {24, 18};
  p.driven = {18, 60};
  p.externals = 1;
  EXPECT_DOUBLE_EQ(basic_ratio(p), -0.4);
  add_epicyclic_train(model, "planetary", p);
  drive_angle(model, sun, 0.7, 35.0);
  model.add_torque({carrier, -7.0, "load"});
  kin::Data data(model);
  solve_all(model, data);
  EXPECT_NEAR(data.qd(3 * carrier + 2), 10.0, 1e-9);  // 35 rad/s / 3.5
  EXPECT_NEAR(data.q(3 * carrier + 2), 0.2, 1e-12);   // from the drawing (both at 0)
  const kin::ForceAnalysis f = kin::solve_forces(model, data);
  EXPECT_NEAR(f.effort_virtual_power[0], 2.0, 1e-9);
  for (const auto& r : f.reactions)
    if (r.kind == "epicyclic_train") {
      EXPECT_NEAR(value_of(r.values, "T_arm"), 7.0, 1e-9);
      EXPECT_NEAR(value_of(r.values, "T_in"), -2.0, 1e-9);
      EXPECT_NEAR(value_of(r.values, "T_out"), -5.0, 1e-9);
    }
}

// The field a builder's kin::ElementError names, or "" when it builds.
std::string field_of(const kin::Model& model, const EpicyclicTrainParameters& q) {
  try {
    make_epicyclic_train(model, q);
  } catch (const kin::ElementError& e) {
    return e.field();
  }
  return "";
}

TEST(EpicyclicTrain, ImpossibleParametersNameTheirField) {
  kin::Model model;
  const int a = add_body(model, "a", {0, 0}, 0.0, {{"O", {0, 0}}});
  const int b = add_body(model, "b", {0, 0}, 0.0, {{"O", {0, 0}}});
  EpicyclicTrainParameters p;
  p.input = a;
  p.output = b;
  p.arm = kin::kGround;
  p.driving = {20};
  p.driven = {40};
  EXPECT_EQ(field_of(model, p), "");
  EpicyclicTrainParameters q = p;
  q.arm = a;
  EXPECT_EQ(field_of(model, q), "arm");
  q = p;
  q.driven = {};
  EXPECT_EQ(field_of(model, q), "driven");
  q = p;
  q.driving = {20, 0};
  EXPECT_EQ(field_of(model, q), "driving");
  q = p;
  q.externals = -1;
  EXPECT_EQ(field_of(model, q), "externals");
}

// Drawings get the central members with the teeth at the ends of the chain (the input's first
// driving gear, the output's last driven gear) and the arm.
TEST(EpicyclicTrain, DrawingGivesTheCentralMembersAndTheArm) {
  kin::Model model;
  const int sun = add_body(model, "sun", {0, 0}, 0.0, {{"O", {0, 0}}});
  const int carrier = add_body(model, "carrier", {0, 0}, 0.0, {{"O", {0, 0}}});
  EpicyclicTrainParameters p;
  p.input = sun;
  p.output = kin::kGround;
  p.arm = carrier;
  p.driving = {24, 18};
  p.driven = {18, 60};
  p.externals = 1;
  const kin::ConstraintDrawing d = make_epicyclic_train(model, p)->drawing();
  ASSERT_EQ(d.central.size(), 2u);
  EXPECT_EQ(d.central[0].body, sun);
  EXPECT_EQ(d.central[0].teeth, 24);
  EXPECT_EQ(d.central[1].body, kin::kGround);
  EXPECT_EQ(d.central[1].teeth, 60);
  EXPECT_EQ(d.arm, carrier);
  EXPECT_FALSE(d.cam);
}

}  // namespace
}  // namespace gearkit::elements

namespace gearkit::elements {
namespace {

// Phi_q, Phi_t and gamma of Willis' equation against finite differences of its Phi (issue 27,
// item 7): with a fixed member (the ground) and with all three members moving.
TEST(EpicyclicTrain, DerivativesMatchFiniteDifferences) {
  kin::Model model;
  const int sun = add_body(model, "sun", {0, 0}, 0.0, {});
  const int carrier = add_body(model, "carrier", {0, 0}, 0.0, {});
  const int ring = add_body(model, "ring", {0, 0}, 0.0, {});
  EpicyclicTrainParameters p;
  p.input = sun;
  p.output = kin::kGround;
  p.arm = carrier;
  p.driving = {24, 18};
  p.driven = {18, 60};
  p.externals = 1;
  expect_derivatives(*make_epicyclic_train(model, p));
  p.output = ring;
  expect_derivatives(*make_epicyclic_train(model, p));
}

}  // namespace
}  // namespace gearkit::elements
