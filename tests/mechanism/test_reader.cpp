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
  // The drawn input is the crank's drawn angle, 30 deg (not the range's start): the drawing is
  // assembled there. Piston: 50 cos 30 + sqrt(200^2 - (50 sin 30)^2) = 241.7326 mm.
  EXPECT_NEAR(m.model.drivers()[0].value, 30 * M_PI / 180, 1e-15);
  EXPECT_NEAR(data.q(6), 0.050 * std::cos(M_PI / 6) + std::sqrt(0.2 * 0.2 - std::pow(0.05 * std::sin(M_PI / 6), 2)), 1e-12);
}

// docs/cli.md: a value in a message is quoted with at most 60 characters of it (issue 26,
// section 3: a 400-character link name was quoted whole).
TEST(MechanismYaml, NamesInMessagesAreCutAtSixtyCharacters) {
  const std::string name(400, 'q');
  const std::string shown = "'" + std::string(60, 'q') + "...'";
  const std::string unknown = error_of(with(kSliderCrank, "[rod.B, piston.B]", "[rod.B, " + name + ".B]"));
  EXPECT_NE(unknown.find("unknown link " + shown + " in '" + std::string(60, 'q') + "...'"), std::string::npos) << unknown;
  const std::string point = error_of(with(kSliderCrank, "[crank.A, rod.A]", "[crank." + name + ", rod.A]"));
  EXPECT_NE(point.find("link 'crank' has no point " + shown), std::string::npos) << point;
  const std::string duplicate = error_of(with(with(kSliderCrank, "  piston:\n", "  " + name + ":\n"), "  rod:\n", "  " + name + ":\n"));
  EXPECT_NE(duplicate.find("duplicate link " + shown), std::string::npos) << duplicate;
  EXPECT_LT(duplicate.size(), 120u) << duplicate;
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

// A crank whose two pins coincide has zero length (issue 13 item 3): Grashof would call the
// four-bar a crank-rocker whose rocker never moves. Refused at the second pin's reference; one
// point shared by two joints (a compound pin) stays allowed.
TEST(MechanismYaml, AZeroLengthLinkIsRefusedNamingIt) {
  const std::string zero = with(kSliderCrank, "A: [0.05 m, 0]", "A: [0, 0]");
  const std::string e = error_of(zero);
  EXPECT_EQ(e.rfind("m.yaml:17:", 0), 0u) << e;  // the joint A line: crank.A is the second pin
  EXPECT_NE(e.find("link 'crank' has zero length: its pins crank.O and crank.A are at the same point"), std::string::npos) << e;
  // rod.B pinned twice at one point (the piston and a spring-loaded arm, say): not degenerate.
  const std::string compound = with(with(kSliderCrank, "  piston:\n", "  arm:\n    points: {B: [0, 0], C: [30, 0]}\n  piston:\n"),
                                    "  - {name: cyl,", "  - {name: B2, type: revolute, at: [rod.B, arm.B]}\n  - {name: cyl,");
  EXPECT_EQ(error_of(compound).find("zero length"), std::string::npos) << error_of(compound);
}

// Friction keys, contacts (side from the drawing or given), point drivers, given efforts with
// unknown loads and the course's output conventions.
TEST(MechanismYaml, FrictionContactsPointDriversAndConventions) {
  const std::string text = with(with(with(kSliderCrank,
      "  - {name: cyl, type: prismatic, slider: piston.B, guide: ground.O, axis: 0 deg}",
      "  - {name: cyl, type: prismatic, slider: piston.B, guide: ground.O, axis: 0 deg, friction: 0.1, length: 40}\n"
      "  - {name: roll, type: contact, circle: crank.A, radius: 10, line: ground.T, axis: 0 deg, friction: 0.2}"),
      "  O: [0, 0]\n", "  O: [0, 0]\n  T: [0, 80]\n"),
      "  - {name: x, type: slider, joint: cyl}",
      "  - {name: x, type: slider, joint: cyl}\n"
      "  - {name: xa, type: x, point: crank.A, from: piston.B}\n"
      "  - {name: phi, type: angle, along: [rod.B, rod.A], clockwise: true, zero: 90 deg}\n"
      "  - {name: v, type: speed, point: rod.B}\n"
      "  - {name: a, type: acceleration, point: rod.B}");
  const Mechanism m = read(text);
  ASSERT_EQ(m.model.frictions().size(), 2u);
  EXPECT_NEAR(m.model.frictions()[0].mu, 0.1, 1e-15);
  EXPECT_NEAR(m.model.frictions()[0].length, 0.040, 1e-15);
  const auto* contact = dynamic_cast<const kin::Contact*>(m.model.constraints()[*m.model.constraint_index("roll")].constraint.get());
  ASSERT_NE(contact, nullptr);
  EXPECT_EQ(contact->side(), -1);  // A is drawn below the line y = 80 mm
  EXPECT_NEAR(contact->radius(), 0.010, 1e-15);
  ASSERT_EQ(m.outputs.size(), 5u);
  ASSERT_TRUE(m.outputs[1].from);
  EXPECT_EQ(m.outputs[1].from->body, 2);
  EXPECT_EQ(m.outputs[2].sense, -1);
  EXPECT_NEAR(m.outputs[2].zero, M_PI / 2, 1e-15);
  EXPECT_NEAR(m.outputs[2].offset, M_PI, 1e-15);  // B -> A along the rod's -x
  EXPECT_EQ(m.outputs[3].kind, kin::OutputKind::point_speed);
  EXPECT_EQ(m.outputs[4].kind, kin::OutputKind::point_acceleration);
  // A point driver: A's height, its drawn value 50 sin 30 deg = 25 mm; an effort and an unknown load.
  const Mechanism p = read(with(with(kSliderCrank,
      "  - {name: in, type: angle, link: crank, speed: 600 rpm, range: [0, 180, 10]}",
      "  - {name: in, type: point, point: crank.A, axis: 90 deg, speed: -2 m/s, effort: 3 N}"),
      "  springs:", "  forces: [{name: F, at: piston.B, direction: 180 deg, unknown: true}]\n  springs:"));
  EXPECT_NEAR(p.model.drivers()[0].value, 0.025, 1e-12);
  EXPECT_EQ(p.model.drivers()[0].quantity, kin::DriverQuantity::displacement);
  ASSERT_TRUE(p.model.drivers()[0].effort);
  EXPECT_NEAR(*p.model.drivers()[0].effort, 3.0, 1e-15);
  EXPECT_TRUE(p.model.forces()[0].unknown);
  EXPECT_NEAR(p.model.forces()[0].force.x(), -1.0, 1e-15);
  // Errors at the key.
  EXPECT_NE(error_of(with(text, "friction: 0.1, length: 40", "friction: -0.1")).find("friction coefficient >= 0"), std::string::npos);
  EXPECT_NE(error_of(with(kSliderCrank, "{name: O, type: revolute, at: [crank.O, ground.O]}",
                          "{name: O, type: revolute, at: [crank.O, ground.O], friction: 0.1}")).find("journal radius"),
            std::string::npos);
  EXPECT_NE(error_of(with(kSliderCrank, "{name: O, type: revolute, at: [crank.O, ground.O]}",
                          "{name: O, type: revolute, at: [crank.O, ground.O], radius: 5}")).find("only with 'friction'"),
            std::string::npos);
  EXPECT_NE(error_of(with(text, "circle: crank.A, radius: 10, line: ground.T", "circle: crank.A, radius: 10, line: crank.O"))
                .find("same link"), std::string::npos);
  EXPECT_NE(error_of(with(with(text, "  T: [0, 80]", "  T: [0, 25]"), "radius: 10,", "radius: 0,")).find("side"), std::string::npos);
  EXPECT_NE(error_of(with(kSliderCrank, "speed: 600 rpm,", "speed: 600 rpm, effort: 2 N*m,")).find("unknown load"), std::string::npos);
  EXPECT_NE(error_of(with(kSliderCrank, "  springs:", "  forces: [{at: piston.B, direction: 0, unknown: true}]\n  springs:"))
                .find("effort"), std::string::npos);
}

}  // namespace
}  // namespace gearkit::mechanism
