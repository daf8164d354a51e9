// The mechanism file reader (gearkit/mechanism/reader.hpp): structure, units, placement of the
// first guess, and errors with file:line:column.
#include <gearkit/mechanism/reader.hpp>
#include <gearkit/kin/dof.hpp>
#include <gearkit/kin/solve.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace gearkit::mechanism {
namespace {

using io::load_yaml_text;

const char* kSliderCrank = R"(mechanism: slider-crank
ground:
  O: [0, 0]
links:
  crank:
    points: {O: [0, 0], A: [0.05 m, 0]}
    angle: 30 deg
  rod:
    points: {A: [0, 0], B: [200, 0]}
    angle: -7 deg
    mass: 300 g
    centre_of_mass: B
  piston:
    points: {B: [0, 0]}
joints:
  - {name: O, type: revolute, at: [crank.O, ground.O]}
  - {name: A, type: revolute, at: [crank.A, rod.A]}
  - {name: B, type: revolute, at: [rod.B, piston.B]}
  - {name: cyl, type: prismatic, slider: piston.B, guide: ground.O, axis: 0 deg}
drivers:
  - {name: in, type: angle, link: crank, speed: 600 rpm, range: [0, 180, 10]}
loads:
  gravity: [0, -9.81]
  springs: [{between: [piston.B, ground.O], stiffness: 1000 N/m, free_length: 100 mm}]
outputs:
  - {name: x, type: slider, joint: cyl}
)";

Mechanism read(const std::string& text) { return read_mechanism(load_yaml_text(text, "m.yaml"), nullptr); }

std::string error_of(const std::string& text) {
  try {
    read(text);
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(MechanismYaml, ReadsUnitsAndStructure) {
  const Mechanism m = read(kSliderCrank);
  EXPECT_EQ(m.title, "slider-crank");
  ASSERT_EQ(m.model.bodies().size(), 3u);
  EXPECT_NEAR(m.model.bodies()[0].point("A")->x(), 0.05, 1e-15);
  EXPECT_NEAR(m.model.bodies()[1].point("B")->x(), 0.200, 1e-15);  // bare number: mm
  EXPECT_NEAR(m.model.bodies()[1].mass, 0.3, 1e-15);
  EXPECT_NEAR(m.model.bodies()[1].centre_of_mass.x(), 0.2, 1e-15);
  EXPECT_NEAR(m.model.bodies()[0].angle_guess, 30 * M_PI / 180, 1e-15);
  EXPECT_EQ(m.model.equations(), 9);
  ASSERT_EQ(m.drivers.size(), 1u);
  ASSERT_TRUE(m.drivers[0].range);
  EXPECT_NEAR(m.drivers[0].range->step, 10 * M_PI / 180, 1e-15);
  EXPECT_NEAR(m.model.springs()[0].stiffness, 1000.0, 1e-12);
  EXPECT_NEAR(m.model.gravity().y(), -9.81, 1e-12);
  ASSERT_EQ(m.outputs.size(), 1u);
  // The rod was placed from the crank's drawn A (no position given): A at 50 mm, 30 deg.
  EXPECT_NEAR(m.model.bodies()[1].position_guess.x(), 0.05 * std::cos(M_PI / 6), 1e-12);
  kin::Data data(m.model);
  ASSERT_TRUE(kin::solve_position(m.model, data, 0.0).converged);
  EXPECT_EQ(kin::dof(m.model, data).gruebler, 1);
  // Piston: 50 cos 0 + 200 = 250 mm at the range's start (crank angle 0).
  EXPECT_NEAR(data.q(6), 0.250, 1e-12);
}

TEST(MechanismYaml, ErrorsNameFileLineAndColumn) {
  EXPECT_EQ(error_of(with(kSliderCrank, "[rod.B, piston.B]", "[rod.B, pistn.B]")).rfind("m.yaml:18:", 0), 0u)
      << error_of(with(kSliderCrank, "[rod.B, piston.B]", "[rod.B, pistn.B]"));
  EXPECT_NE(error_of(with(kSliderCrank, "[rod.B, piston.B]", "[rod.B, pistn.B]")).find("unknown link 'pistn'"), std::string::npos);
  EXPECT_NE(error_of(with(kSliderCrank, "[crank.A, rod.A]", "[crank.Z, rod.A]")).find("link 'crank' has no point 'Z'"), std::string::npos);
  EXPECT_NE(error_of(with(kSliderCrank, "[crank.A, rod.A]", "[crankA, rod.A]")).find("expected a point reference"), std::string::npos);
  EXPECT_NE(error_of(with(kSliderCrank, "angle: 30 deg", "angle: 30 mm")).find("m.yaml:7:"), std::string::npos);
  EXPECT_NE(error_of(with(kSliderCrank, "type: revolute, at: [crank.O", "type: hinge, at: [crank.O")).find("hinge"), std::string::npos);
  EXPECT_NE(error_of(with(kSliderCrank, "joint: cyl}", "joint: A}")).find("prismatic"), std::string::npos);
  EXPECT_NE(error_of(with(kSliderCrank, "range: [0, 180, 10]", "range: [0, 180, 0]")).find("step > 0"), std::string::npos);
  EXPECT_NE(error_of(with(kSliderCrank, "  piston:\n", "  crank:\n")).find("duplicate link 'crank'"), std::string::npos);
  EXPECT_NE(error_of(with(kSliderCrank, "{name: A, type", "{name: O, type")).find("duplicate"), std::string::npos);
  EXPECT_NE(error_of(with(kSliderCrank, "mass: 300 g", "mass: -3 kg")).find("mass >= 0"), std::string::npos);
  EXPECT_NE(error_of(with(kSliderCrank, "outputs:", "elements:\n  - {type: gear_mesh}\noutputs:")).find("unknown element type 'gear_mesh'"),
            std::string::npos);
  EXPECT_NE(error_of("links: {}\n").find("links"), std::string::npos);
  EXPECT_NE(error_of(with(kSliderCrank, "{name: A, type: revolute, at: [crank.A, rod.A]}", "{name: A, type: revolute, at: [crank.A, crank.O]}"))
                .find("two different links"),
            std::string::npos);
}

}  // namespace
}  // namespace gearkit::mechanism
