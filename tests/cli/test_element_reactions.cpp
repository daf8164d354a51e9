// `gearkit kin` reports what the elements of the plugins carry (Constraint::reaction): a gear
// mesh's tooth forces and a cam follower's contact force, against hand calculations; and a bad
// element parameter is placed at its key.
#include <run_gearkit.hpp>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

namespace {

using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;

std::string write(const std::string& name, const std::string& text) {
  const auto dir = gearkit::testing::scratch_dir("element_reactions_" + name);
  std::ofstream(dir / name) << text;
  return shell_quote((dir / name).string());
}

const nlohmann::json& reaction(const nlohmann::json& report, const std::string& name) {
  for (const auto& r : report["positions"][0]["reactions"])
    if (r["joint"] == name) return r;
  throw std::runtime_error("no reaction " + name);
}

// Pinion z1 = 20 driven, gear z2 = 40 loaded with -10 N m, module 2 mm, alpha 20 deg (spur):
// r2 = 40 mm, F_t = 10/0.04 = 250 N, F_r = 250 tan 20 deg = 90.9926 N, F_n = 250/cos 20 deg =
// 266.0444 N; the pinion needs 5 N m (ISO 6336-1 nominal tangential load on the reference circle).
TEST(ElementReactions, GearMeshToothForcesInTheKinReport) {
  const std::string file = write("gears.yaml", R"(ground: {O1: [0, 0], O2: [60, 0]}
links:
  pinion: {points: {O1: [0, 0]}}
  gear: {points: {O2: [0, 0]}}
joints:
  - {name: O1, type: revolute, at: [pinion.O1, ground.O1]}
  - {name: O2, type: revolute, at: [gear.O2, ground.O2]}
elements:
  - {name: mesh, type: gear_mesh, gear1: pinion, gear2: gear, z1: 20, z2: 40, module: 2 mm}
drivers:
  - {name: input, type: angle, link: pinion, speed: 100 rpm}
loads:
  torques: [{link: gear, torque: -10 N*m}]
)");
  const auto r = run_gearkit("kin " + file + " --at 30 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& values = reaction(j, "mesh")["values"];
  EXPECT_NEAR(values["F_t_N"].get<double>(), 250.0, 1e-9);
  EXPECT_NEAR(values["F_r_N"].get<double>(), 90.99256, 1e-5);
  EXPECT_NEAR(values["F_n_N"].get<double>(), 266.04444, 1e-5);
  EXPECT_NEAR(values["T_2_Nm"].get<double>(), 10.0, 1e-9);
  EXPECT_NEAR(std::abs(j["positions"][0]["driving_torque_Nm"].get<double>()), 5.0, 1e-9);
  const auto text = run_gearkit("kin " + file + " --at 30");
  EXPECT_NE(text.out.find("Element reactions"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("normal tooth force"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("266.044"), std::string::npos) << text.out;
}

// A flat-faced follower of 2 kg on a vertical guide, lifted by a cam at 10 rad/s with a simple
// harmonic rise of 20 mm over 180 deg, under gravity and a 100 N load. At 60 deg: s'' = (h/2)
// cos 60 deg = 5 mm/rad^2, a = s'' omega^2 = 0.5 m/s^2, so the contact force along the guide is
// F = m (a + g) + 100 N = 2 (0.5 + 9.81) + 100 = 120.62 N (the face is normal to the guide, so
// this is the whole contact force); the cam shaft torque is F s' = 120.62 (10 mm) sin 60 deg.
TEST(ElementReactions, CamContactForceInTheKinReport) {
  const std::string file = write("cam.yaml", R"(ground: {O: [0, 0], G: [0, 0]}
links:
  cam: {points: {O: [0, 0]}}
  follower: {points: {P: [0, 0]}, position: [0, 55], mass: 2 kg, centre_of_mass: P}
joints:
  - {name: shaft, type: revolute, at: [cam.O, ground.O]}
  - {name: guide, type: prismatic, slider: follower.P, guide: ground.G, axis: 90 deg}
elements:
  - name: contact
    type: cam_follower
    cam: cam
    follower_type: translating
    point: follower.P
    guide: ground.G
    axis: 90 deg
    base: 50 mm
    motion:
      - {type: rise, from: 0 deg, to: 180 deg, law: simple_harmonic, lift: 20 mm}
      - {type: return, from: 180 deg, to: 360 deg, law: simple_harmonic}
drivers:
  - {name: cam angle, type: angle, link: cam, speed: 10 rad/s}
loads:
  gravity: 9.81 m/s^2
  forces: [{at: follower.P, force: [0, -100 N]}]
)");
  const auto r = run_gearkit("kin " + file + " --at 60 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& values = reaction(j, "contact")["values"];
  EXPECT_NEAR(values["F_N"].get<double>(), 120.62, 1e-9);
  const double torque = 120.62 * 0.010 * std::sin(60 * std::numbers::pi / 180);
  EXPECT_NEAR(values["T_cam_Nm"].get<double>(), -torque, 1e-9);
  EXPECT_NEAR(j["positions"][0]["driving_torque_Nm"].get<double>(), torque, 1e-9);
}

// A builder's complaint is placed at the key it names (kin::ElementError -> file:line:column).
TEST(ElementReactions, BadElementParameterIsPlacedAtItsKey) {
  const std::string file = write("bad.yaml", R"(ground: {O1: [0, 0], O2: [60, 0]}
links:
  pinion: {points: {O1: [0, 0]}}
  ring: {points: {O2: [0, 0]}}
joints:
  - {name: O1, type: revolute, at: [pinion.O1, ground.O1]}
  - {name: O2, type: revolute, at: [ring.O2, ground.O2]}
elements:
  - name: mesh
    type: gear_mesh
    gear1: pinion
    gear2: ring
    z1: 20
    z2: 18
    internal: true
drivers:
  - {name: input, type: angle, link: pinion}
)");
  const auto r = run_gearkit("kin " + file);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("bad.yaml:14:9: 'z2': expected the internal gear 2 to have more teeth than gear 1 (20), found 18"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(gearkit::testing::count_lines(r.err), 1) << r.err;
}

// The cam follower's drawing keys (docs/kin.md): a negative roller radius and a roller centre on
// another link than the follower are bad input at their keys.
TEST(ElementReactions, BadRollerIsPlacedAtItsKey) {
  const std::string example = gearkit::testing::slurp(std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/cam_rocker.yaml");
  ASSERT_NE(example.find("    roller_radius: 10 mm\n"), std::string::npos);
  ASSERT_NE(example.find("    roller: rocker.R\n"), std::string::npos);
  const auto line_of = [&](const std::string& text, const std::string& key) {
    return std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(text.find(key)), '\n') + 1;
  };
  std::string radius = example;
  radius.replace(radius.find("roller_radius: 10 mm"), 20, "roller_radius: -3 mm");
  const auto r = run_gearkit("kin " + write("bad_radius.yaml", radius));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(fmt::format("bad_radius.yaml:{}:20: 'roller_radius': expected a radius >= 0, found -3 mm",
                                   line_of(radius, "roller_radius:"))),
            std::string::npos)
      << r.err;
  EXPECT_EQ(gearkit::testing::count_lines(r.err), 1) << r.err;
  std::string roller = example;
  roller.replace(roller.find("roller: rocker.R"), 16, "roller: cam.Oc");
  const auto c = run_gearkit("kin " + write("bad_roller.yaml", roller));
  EXPECT_EQ(c.status, 2);
  EXPECT_NE(c.err.find(fmt::format("bad_roller.yaml:{}:13: 'roller': expected a point of the follower 'rocker', found a point of 'cam'",
                                   line_of(roller, "roller: cam"))),
            std::string::npos)
      << c.err;
}

// The flat face's keys (docs/kin.md) are bad input at their keys: a roller radius with face:
// flat, a face point on a translating follower, an unknown face; an oscillating flat face runs.
TEST(ElementReactions, BadFlatFaceIsPlacedAtItsKey) {
  const std::string example = gearkit::testing::slurp(std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/cam_flat_face.yaml");
  ASSERT_NE(example.find("    face: flat\n"), std::string::npos);
  const auto line_of = [&](const std::string& text, const std::string& key) {
    return std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(text.find(key)), '\n') + 1;
  };
  const auto expect_error = [&](const std::string& name, const std::string& text, const std::string& key, int column,
                                const std::string& message) {
    const auto r = run_gearkit("kin " + write(name, text));
    EXPECT_EQ(r.status, 2) << name;
    EXPECT_NE(r.err.find(fmt::format("{}:{}:{}: {}", name, line_of(text, key), column, message)), std::string::npos) << r.err;
    EXPECT_EQ(gearkit::testing::count_lines(r.err), 1) << r.err;
  };
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string t = example;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  expect_error("flat_roller.yaml", with("    face: flat\n", "    face: flat\n    roller_radius: 5 mm\n"), "roller_radius:", 20,
               "'roller_radius': expected none with face: flat (the face touches the cam), found 5 mm");
  expect_error("flat_point.yaml", with("    face: flat\n", "    face: flat\n    face_point: tappet.T\n"), "face_point:", 17,
               "'face_point': expected none on a translating follower");
  expect_error("flat_angle.yaml", with("    face: flat\n", "    face: flat\n    face_angle: 10 deg\n"), "face_angle:", 17,
               "'face_angle': expected none on a translating follower");
  expect_error("round.yaml", with("    face: flat\n", "    face: round\n"), "face: round", 11, "");
  // The cam-rocker with a flat face on the rocker instead of its roller.
  std::string rocker = gearkit::testing::slurp(std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/cam_rocker.yaml");
  const std::string roller = "    roller: rocker.R\n    roller_radius: 10 mm\n";
  ASSERT_NE(rocker.find(roller), std::string::npos);
  rocker.replace(rocker.find(roller), roller.size(), "    face: flat\n    face_point: rocker.R\n    face_angle: 0 deg\n");
  EXPECT_EQ(run_gearkit("kin " + write("rocker_flat.yaml", rocker) + " --animate " + write("rocker_flat.svg", "")).status, 0);
  std::string other = rocker;
  other.replace(other.find("face_point: rocker.R"), 20, "face_point: cam.Oc");
  expect_error("rocker_face.yaml", other, "face_point: cam", 17, "'face_point': expected a point of the follower 'rocker', found a point of 'cam'");
}

}  // namespace
