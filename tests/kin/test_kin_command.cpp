// `gearkit kin` end to end through the executable (GEARKIT_EXE): the examples, the plugin
// elements (gear mesh, epicyclic train, cam follower), plots and animations, bad input.
#include <run_gearkit.hpp>

#include "mechanisms.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>
#include <fmt/format.h>

#include <cmath>
#include <map>
#include <sstream>
#include <filesystem>
#include <fstream>

namespace {

using gearkit::testing::run_gearkit;
using gearkit::testing::scratch_dir;
using gearkit::testing::shell_quote;
using gearkit::testing::slurp;

const std::string kExamples = std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/";

nlohmann::json run_json(const std::string& args) {
  const auto r = run_gearkit("kin " + args + " --format json");
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

std::string write(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  const auto p = dir / name;
  std::ofstream(p) << text;
  return p.string();
}

void expect_bad_input(const gearkit::testing::RunResult& r, const std::string& part) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
}

// Seed 004 pantograph: s_max = 346.4 mm at phi1 = -60 deg, phi2'/phi1' = 0.6 (phi2 clockwise).
TEST(KinCommand, PantographLimitPosition) {
  const auto j = run_json(shell_quote(kExamples + "pantograph.yaml"));
  EXPECT_EQ(j["dof"], 1);
  EXPECT_EQ(j["gruebler"], 1);
  EXPECT_EQ(j["redundant"], 0);
  bool found = false;
  for (const auto& e : j["limit_positions"])
    if (e["output"] == "s") {
      found = true;
      EXPECT_EQ(e["kind"], "max");
      EXPECT_NEAR(e["input_deg"].get<double>(), -60.0, 1e-5);
      EXPECT_NEAR(e["value_mm"].get<double>(), 346.4, 0.05);
      const double ratio = -e["angular_velocity_ratios"]["coupler.omega_ratio"].get<double>();
      EXPECT_NEAR(ratio, 0.6, 1e-5);
    }
  EXPECT_TRUE(found);
  EXPECT_EQ(j["positions"].size(), 41u);
  EXPECT_TRUE(j["warnings"].empty());
}

// Seed 004 lifting platform: T_m = 113.4 N m and F_PQ = 445.1 N in tension at phi3 = 69.5 deg.
TEST(KinCommand, LiftingPlatformTorqueAndRodForce) {
  const auto j = run_json(shell_quote(kExamples + "lifting_platform.yaml") + " --at 69.5");
  ASSERT_EQ(j["positions"].size(), 1u);
  const auto& p = j["positions"][0];
  EXPECT_NEAR(p["driving_torque_Nm"].get<double>(), 113.4, 0.05);
  EXPECT_NEAR(p["driving_torque_lagrange_Nm"].get<double>(), 113.4, 0.05);
  EXPECT_NEAR(p["q"]["arm1.angle_deg"].get<double>(), 30.0, 1e-4);
  bool rod = false;
  for (const auto& m : p["two_force_members"])
    if (m["link"] == "rod") {
      rod = true;
      EXPECT_EQ(m["state"], "tension");
      EXPECT_NEAR(m["axial_force_N"].get<double>(), 445.1, 0.1);
    }
  EXPECT_TRUE(rod);
}

// Seed 004 spring compressor: half of T = 20 N m for F_m = 441.8 N; F_PQ = 1112 N tension.
TEST(KinCommand, SpringCompressor) {
  const auto j = run_json(shell_quote(kExamples + "spring_compressor.yaml"));
  const auto& p = j["positions"][0];
  EXPECT_NEAR(p["driving_torque_Nm"].get<double>(), -10.0, 0.01);
  EXPECT_NEAR(p["two_force_members"][0]["axial_force_N"].get<double>(), 1112.0, 1.0);
  EXPECT_EQ(p["two_force_members"][0]["state"], "tension");
}

// Gear plugin: external mesh z1 = 20, z2 = 40 makes the second crank turn at -z1/z2 = -1/2.
TEST(KinCommand, GearedFiveBarThroughThePlugin) {
  const auto j = run_json(shell_quote(kExamples + "geared_five_bar.yaml") + " --at 120");
  EXPECT_EQ(j["dof"], 1);
  EXPECT_EQ(j["gruebler"], 1);
  const auto& p = j["positions"][0];
  EXPECT_NEAR(p["outputs"]["gear2 angle_ratio"].get<double>(), -0.5, 1e-9);
  EXPECT_NEAR(p["qd"]["gear2.omega_rad_s"].get<double>(), -5.0, 1e-9);  // driver 10 rad/s
  // The drawing has both cranks at 90 deg; 30 deg more on gear 1 is 15 deg less on gear 2.
  EXPECT_NEAR(p["q"]["gear2.angle_deg"].get<double>(), 75.0, 1e-9);
}

// Cam plugin: cycloidal rise of 20 deg over 120 deg of cam turn (cam clockwise). At 60 deg of
// cam rotation u = 1/2, y = u - sin(2 pi u)/(2 pi) = 1/2, so the rocker is at 100 + 10 deg, and
// d(psi)/d(theta) = L (1 - cos 2 pi u) / beta = 20 * 2 / 120 = 1/3 (Norton eq. 8.12).
TEST(KinCommand, CamRockerThroughThePlugin) {
  const auto j = run_json(shell_quote(kExamples + "cam_rocker.yaml") + " --at -60");
  EXPECT_EQ(j["dof"], 1);
  const auto& p = j["positions"][0];
  EXPECT_NEAR(p["outputs"]["rocker angle_deg"].get<double>(), 110.0, 1e-8);
  EXPECT_NEAR(p["outputs"]["rocker angle_ratio"].get<double>(), -1.0 / 3.0, 1e-9);
  // A full turn: the follower rises 20 deg and comes back.
  const auto sweep = run_json(shell_quote(kExamples + "cam_rocker.yaml"));
  double lo = 1e9, hi = -1e9;
  for (const auto& q : sweep["positions"]) {
    lo = std::min(lo, q["outputs"]["rocker angle_deg"].get<double>());
    hi = std::max(hi, q["outputs"]["rocker angle_deg"].get<double>());
  }
  EXPECT_NEAR(lo, 100.0, 1e-9);
  EXPECT_NEAR(hi, 120.0, 1e-9);
}

// Train plugin: seed 004 (exam 2020-21, exercise 2) Willis equation for planet 3, satellite 4,
// ring 5 and arm b, tau2 = -z3 z4/(z4 z5) = -1/3. With the ring fixed (omega5 = 0):
// tau2 omega3 + (1 - tau2) omega_b = 0 -> omega_b/omega3 = -tau2/(1 - tau2) = 1/4.
TEST(KinCommand, EpicyclicTrainThroughThePlugin) {
  const auto dir = scratch_dir("kin-train");
  const std::string file = write(dir, "planetary.yaml", R"(
mechanism: planetary, ring fixed
ground: {O: [0, 0]}
links:
  sun: {points: {O: [0, 0]}}
  arm: {points: {O: [0, 0], planet: [40, 0]}}
joints:
  - {type: revolute, at: [sun.O, ground.O]}
  - {type: revolute, at: [arm.O, ground.O]}
elements:
  - {type: epicyclic_train, input: sun, output: ground, arm: arm, driving: [30, 45], driven: [45, 90], externals: 1}
drivers:
  - {name: sun angle, type: angle, link: sun, speed: 4 rad/s}
outputs:
  - {name: arm angle, type: angle, link: arm}
)");
  const auto j = run_json(shell_quote(file) + " --at 40");
  const auto& p = j["positions"][0];
  EXPECT_NEAR(p["outputs"]["arm angle_ratio"].get<double>(), 0.25, 1e-12);
  EXPECT_NEAR(p["qd"]["arm.omega_rad_s"].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(p["q"]["arm.angle_deg"].get<double>(), 10.0, 1e-9);
}

TEST(KinCommand, PlotAndAnimationAreSvg) {
  const auto dir = scratch_dir("kin-svg");
  const std::string plot = (dir / "plot.svg").string(), anim = (dir / "anim.svg").string();
  const auto r = run_gearkit("kin " + shell_quote(kExamples + "four_bar.yaml") + " --sweep 0:360:10 --plot " +
                             shell_quote(plot) + " --animate " + shell_quote(anim));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string p = slurp(plot), a = slurp(anim);
  EXPECT_NE(p.find("<svg"), std::string::npos);
  EXPECT_NE(a.find("<svg"), std::string::npos);
  EXPECT_NE(a.find("<animate attributeName=\"points\""), std::string::npos);
  EXPECT_NE(a.find("repeatCount=\"indefinite\""), std::string::npos);
}

TEST(KinCommand, DeadPointInASweepIsAWarning) {
  const auto dir = scratch_dir("kin-dead");
  std::string text = slurp(kExamples + "pantograph.yaml");
  // Drive the slider instead of the crank: s cannot pass s_max = 346.4 mm.
  const auto at = text.find("drivers:");
  text = text.substr(0, at) +
         "drivers:\n  - {name: s, type: displacement, joint: guide, range: [330 mm, 360 mm, 2 mm]}\n"
         "outputs:\n  - {name: phi1, type: angle, link: crank}\n";
  const std::string file = write(dir, "pantograph_slider.yaml", text);
  const auto r = run_gearkit("kin " + shell_quote(file) + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["dead_points"].size(), 1u);
  EXPECT_NEAR(j["dead_points"][0]["input_mm"].get<double>(), 346.41, 0.01);
  ASSERT_FALSE(j["warnings"].empty());
  EXPECT_NE(j["warnings"][0].get<std::string>().find("dead point"), std::string::npos);
  EXPECT_EQ(run_gearkit("kin " + shell_quote(file) + " --strict").status, 3);
}

// A crank-rocker (Norton's four-bar: crank 40, coupler 120, rocker 80, ground 100 mm) driven by
// its rocker with masses on the links: the rocker cannot pass the position where crank and
// coupler overlap in line, |B O2| = 120 - 40 = 80 mm; with |B O2|^2 = 100^2 + 80^2 + 2 100 80
// cos(theta4) (law of cosines at O4), theta4 = acos((80^2 - 100^2 - 80^2) / (2 100 80)) = 128.68 deg. Approaching it the crank's speed and so the driving
// torque grow without bound; the value at the located dead point (about 1e15 N m) is no torque.
TEST(KinCommand, DeadPointTorqueIsAGapInThePlotNotASpike) {
  const auto dir = scratch_dir("kin-dead-torque");
  // examples/mechanisms/four_bar.yaml (masses, gravity) with the rocker as the driver.
  std::string text = slurp(kExamples + "four_bar.yaml");
  const std::string crank_driver = "  - {name: theta2, type: angle, link: crank, speed: 25 rad/s, range: [0 deg, 360 deg, 2 deg]}";
  ASSERT_NE(text.find(crank_driver), std::string::npos);
  text.replace(text.find(crank_driver), crank_driver.size(),
               "  - {name: theta4d, type: angle, link: rocker, speed: 5 rad/s, range: [60 deg, 130 deg, 1 deg]}");
  const std::string file = write(dir, "rocker_driven.yaml", text);
  const std::string plot = (dir / "plot.svg").string();
  const auto j = run_json(shell_quote(file) + " --plot " + shell_quote(plot));
  ASSERT_EQ(j["dead_points"].size(), 1u);
  const double dead = j["dead_points"][0]["input_deg"].get<double>();
  EXPECT_NEAR(dead, std::acos((80.0 * 80 - 100 * 100 - 80 * 80) / (2.0 * 100 * 80)) * 180 / M_PI, 1e-6);
  // JSON and tables keep the row at the dead point (docs/kin.md), the driving torque included.
  EXPECT_NEAR(j["positions"].back()["input_deg"].get<double>(), dead, 1e-9);
  EXPECT_TRUE(j["positions"].back()["driving_torque_Nm"].is_number());
  // The plot: no y tick of 1000 or more (the spike made the torque axis run to 3500T, "T" for
  // tera), and the dead point's note says the effort is not plotted there.
  const std::string svg = slurp(plot);
  std::size_t ticks = 0;
  for (std::size_t at = svg.find("text-anchor=\"end\">"); at != std::string::npos; at = svg.find("text-anchor=\"end\">", at + 1)) {
    const std::size_t from = svg.find('>', at) + 1, to = svg.find('<', from);
    const std::string label = svg.substr(from, to - from);
    ++ticks;
    EXPECT_EQ(label.find_first_of("kMGTP"), std::string::npos) << label;
    EXPECT_LT(std::abs(std::stod(label)), 1000.0) << label;
  }
  EXPECT_GT(ticks, 20u);
  EXPECT_NE(svg.find("(effort unbounded: not plotted)"), std::string::npos);
}

// A Grashof double rocker (ground 100, input 80, coupler 40, output 90 mm: the coupler is the
// shortest link). The input stops where coupler and output rocker are in line, |A O4| = 90 + 40
// or 90 - 40 mm: with |A O4|^2 = 80^2 + 100^2 - 2 80 100 cos(theta2), theta2 = acos(-500/16000)
// = 91.790 deg and acos(13900/16000) = 29.685 deg (law of cosines; issue 13 item 3).
// A pin-jointed four-bar file: ground O2 O4 of length d along x, links (lengths in mm, drawn
// angles in deg) named as given, the driver theta2 on the first.
struct FourBarFile {
  std::string name, input = "crank", coupler = "coupler", output = "rocker";
  double a = 0, b = 0, c = 0, d = 0, theta2 = 0, theta3 = 0, theta4 = 0;
};

std::string four_bar_yaml(const FourBarFile& f) {
  std::ostringstream y;
  y << "mechanism: " << f.name << "\nground: {O2: [0, 0], O4: [" << f.d << ", 0]}\nlinks:\n"
    << "  " << f.input << ": {points: {O2: [0, 0], A: [" << f.a << ", 0]}, angle: " << f.theta2 << " deg}\n"
    << "  " << f.coupler << ": {points: {A: [0, 0], B: [" << f.b << ", 0]}, angle: " << f.theta3 << " deg}\n"
    << "  " << f.output << ": {points: {O4: [0, 0], B: [" << f.c << ", 0]}, angle: " << f.theta4 << " deg}\n"
    << "joints:\n"
    << "  - {name: O2, type: revolute, at: [" << f.input << ".O2, ground.O2]}\n"
    << "  - {name: A, type: revolute, at: [" << f.input << ".A, " << f.coupler << ".A]}\n"
    << "  - {name: B, type: revolute, at: [" << f.coupler << ".B, " << f.output << ".B]}\n"
    << "  - {name: O4, type: revolute, at: [" << f.output << ".O4, ground.O4]}\n"
    << "drivers:\n  - {name: theta2, type: angle, link: " << f.input << "}\n";
  return y.str();
}

const std::string kDoubleRocker =
    four_bar_yaml({"double rocker", "input", "coupler", "output", 80, 40, 90, 100, 60, 26, 105});

TEST(KinCommand, AnUnreachableSweepStartSweepsTheReachableRange) {
  const double lower = std::acos(13900.0 / 16000.0) * 180 / M_PI, upper = std::acos(-500.0 / 16000.0) * 180 / M_PI;
  const std::string file = write(scratch_dir("kin-double-rocker"), "double_rocker.yaml", kDoubleRocker);
  // The grid's inputs 30 .. 91 deg, then perhaps the last configuration reached at the dead point.
  const auto expect_inputs = [](const nlohmann::json& positions, double first, double last, double limit) {
    const double step = last > first ? 1.0 : -1.0;
    const auto grid = static_cast<std::size_t>(std::abs(last - first)) + 1;
    ASSERT_TRUE(positions.size() == grid || positions.size() == grid + 1) << positions.size();
    for (std::size_t k = 0; k < grid; ++k)
      EXPECT_NEAR(positions[k]["input_deg"].get<double>(), first + step * static_cast<double>(k), 1e-9) << k;
    if (positions.size() > grid) {
      EXPECT_NEAR(positions[grid]["input_deg"].get<double>(), limit, 1e-4);
    }
  };
  const auto j = run_json(shell_quote(file) + " --sweep 0:120:1");
  expect_inputs(j["positions"], 30, 91, upper);
  ASSERT_EQ(j["dead_points"].size(), 2u);
  EXPECT_NEAR(j["dead_points"][0]["input_deg"].get<double>(), lower, 1e-4);
  EXPECT_NEAR(j["dead_points"][1]["input_deg"].get<double>(), upper, 1e-4);
  bool said = false;
  for (const auto& w : j["warnings"]) said = said || w.get<std::string>().find("start 0 deg is not reachable") != std::string::npos;
  EXPECT_TRUE(said) << j["warnings"];
  // Swept the other way the limits come in the other order.
  const auto back = run_json(shell_quote(file) + " --sweep 120:0:1");
  expect_inputs(back["positions"], 91, 30, lower);
  EXPECT_NEAR(back["dead_points"][0]["input_deg"].get<double>(), upper, 1e-4);
  // A range wholly beyond a limit: no position, the limit named.
  const auto none = run_json(shell_quote(file) + " --sweep 0:20:1");
  EXPECT_TRUE(none["positions"].empty());
  ASSERT_EQ(none["dead_points"].size(), 1u);
  EXPECT_NEAR(none["dead_points"][0]["input_deg"].get<double>(), lower, 1e-4);
  // An unreachable --at names its dead point in dead_points[] too, not only in the warnings.
  const auto at = run_json(shell_quote(file) + " --at 10");
  EXPECT_TRUE(at["positions"].empty());
  ASSERT_EQ(at["dead_points"].size(), 1u);
  EXPECT_NEAR(at["dead_points"][0]["input_deg"].get<double>(), lower, 1e-4);
}

// The crossed (anti-parallelogram) branch of the 40/100/40/100 four-bar at crank angle theta2
// [deg]: B is the mirror image of the parallelogram's B = O4 + (A - O2) in the line A O4 (both
// satisfy |AB| = 100 and |O4 B| = 40); returns the rocker angle [deg] (hand derivation).
double anti_parallelogram_theta4(double theta2_deg) {
  const double t = theta2_deg * M_PI / 180;
  const double ax = 40 * std::cos(t), ay = 40 * std::sin(t), bx = 100 + ax, by = ay;
  const double ux = 100 - ax, uy = -ay, l = std::hypot(ux, uy), ex = ux / l, ey = uy / l;
  const double vx = bx - ax, vy = by - ay, along = vx * ex + vy * ey;
  const double rx = ax + 2 * along * ex - vx, ry = ay + 2 * along * ey - vy;
  return std::atan2(ry, rx - 100) * 180 / M_PI;
}

double angle_gap_deg(double a, double b) { return std::abs(std::remainder(a - b, 360.0)); }

// A parallelogram four-bar (40/100/40/100 mm): on the drawn branch the rocker stays parallel to
// the crank, theta4 = theta2 exactly, through 180 deg where all links lie flat and the
// anti-parallelogram branch crosses (issue 13 item 3): the sweep goes on along the branch whose
// motion is smooth and notes the change point; --branch switch takes the crossed branch there.
TEST(KinCommand, AParallelogramCrossesItsChangePoints) {
  const FourBarFile parallelogram{"parallelogram", "crank", "coupler", "rocker", 40, 100, 40, 100, 40, 0, 40};
  const std::string file = write(scratch_dir("kin-parallelogram"), "parallelogram.yaml", four_bar_yaml(parallelogram));
  const auto j = run_json(shell_quote(file) + " --sweep 10:350:10");
  ASSERT_EQ(j["positions"].size(), 35u);
  for (const auto& p : j["positions"]) {
    EXPECT_LT(angle_gap_deg(p["q"]["rocker.angle_deg"].get<double>(), p["input_deg"].get<double>()), 1e-6);
    EXPECT_LT(angle_gap_deg(p["q"]["coupler.angle_deg"].get<double>(), 0.0), 1e-6);
  }
  EXPECT_TRUE(j["dead_points"].empty());
  ASSERT_EQ(j["change_points"].size(), 1u);
  EXPECT_NEAR(j["change_points"][0]["input_deg"].get<double>(), 180.0, 1e-6);
  EXPECT_EQ(j["change_points"][0]["branch"], "continued");
  EXPECT_TRUE(j["change_points"][0]["bifurcation"].get<bool>());
  // A change point is a note, not a warning; the one warning is the transmission angle, which is
  // 0 there (all four links collinear at theta2 = 180 deg, below the default 40 deg limit).
  ASSERT_EQ(j["warnings"].size(), 1u) << j["warnings"];
  EXPECT_NE(j["warnings"][0].get<std::string>().find("transmission angle down to 0.00 deg at theta2 = 180"),
            std::string::npos) << j["warnings"];
  const auto text = run_gearkit("kin " + shell_quote(file) + " --sweep 10:350:10");
  EXPECT_NE(text.out.find("change point at input 180.000000 deg"), std::string::npos) << text.out;

  // The other branch past 180 deg: the anti-parallelogram.
  const auto k = run_json(shell_quote(file) + " --sweep 10:350:10 --branch switch");
  ASSERT_EQ(k["positions"].size(), 35u);
  for (const auto& p : k["positions"]) {
    const double theta2 = p["input_deg"].get<double>(), theta4 = p["q"]["rocker.angle_deg"].get<double>();
    EXPECT_LT(angle_gap_deg(theta4, theta2 <= 180 ? theta2 : anti_parallelogram_theta4(theta2)), 1e-5) << theta2;
  }
  EXPECT_EQ(k["change_points"][0]["branch"], "switched");

  // A sweep that starts on the flat position at 0 deg and ends on the one at 360 deg.
  const auto z = run_json(shell_quote(file) + " --sweep 0:360:10");
  ASSERT_EQ(z["positions"].size(), 37u);
  for (const auto& p : z["positions"])
    EXPECT_LT(angle_gap_deg(p["q"]["rocker.angle_deg"].get<double>(), p["input_deg"].get<double>()), 1e-5);
  ASSERT_EQ(z["change_points"].size(), 3u);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(z["change_points"][c]["input_deg"].get<double>(), 180.0 * c, 1e-6);
}

// Drawn as an anti-parallelogram (the crossed branch at 40 deg: theta3 = -40.68, theta4 =
// -80.68 deg), the sweep stays on it through the flat position at 180 deg (it used to jump to
// the parallelogram there silently), from a start on the flat position at 0 deg too.
TEST(KinCommand, AnAntiParallelogramStaysOnItsBranch) {
  FourBarFile anti{"anti-parallelogram", "crank", "coupler", "rocker", 40, 100, 40, 100, 40, -40.68, -80.68};
  const std::string file = write(scratch_dir("kin-anti-parallelogram"), "anti.yaml", four_bar_yaml(anti));
  for (const std::string sweep : {"40:300:10", "40:300:7", "0:360:1"}) {
    const auto k = run_json(shell_quote(file) + " --sweep " + sweep);
    ASSERT_FALSE(k["positions"].empty()) << sweep;
    for (const auto& p : k["positions"]) {
      const double theta2 = p["input_deg"].get<double>();
      EXPECT_LT(angle_gap_deg(p["q"]["rocker.angle_deg"].get<double>(), anti_parallelogram_theta4(theta2)), 1e-5)
          << sweep << " at " << theta2;
    }
    EXPECT_TRUE(k["dead_points"].empty()) << sweep;
    bool at_180 = false;
    for (const auto& c : k["change_points"]) at_180 = at_180 || std::abs(c["input_deg"].get<double>() - 180) < 1e-5;
    EXPECT_TRUE(at_180) << sweep << k["change_points"];
  }
}

// A triple parallelogram (a third crank O6 C parallel to the other two, rod A B C): Gruebler
// says 0, it moves with one redundant constraint, and only the parallelogram branch exists.
// Its flat positions are singular but no branch crosses: the sweep passes them, says so, and
// every crank stays parallel (theta4 = theta6 = theta2).
TEST(KinCommand, ATripleParallelogramPassesItsFlatPositions) {
  const std::string yaml =
      "mechanism: triple parallelogram\nground: {O2: [0, 0], O4: [100, 0], O6: [200, 0]}\nlinks:\n"
      "  crank: {points: {O2: [0, 0], A: [40, 0]}, angle: 40 deg}\n"
      "  rod: {points: {A: [0, 0], B: [100, 0], C: [200, 0]}, angle: 0 deg}\n"
      "  rocker: {points: {O4: [0, 0], B: [40, 0]}, angle: 40 deg}\n"
      "  third: {points: {O6: [0, 0], C: [40, 0]}, angle: 40 deg}\njoints:\n"
      "  - {name: O2, type: revolute, at: [crank.O2, ground.O2]}\n  - {name: A, type: revolute, at: [crank.A, rod.A]}\n"
      "  - {name: B, type: revolute, at: [rod.B, rocker.B]}\n  - {name: O4, type: revolute, at: [rocker.O4, ground.O4]}\n"
      "  - {name: C, type: revolute, at: [rod.C, third.C]}\n  - {name: O6, type: revolute, at: [third.O6, ground.O6]}\n"
      "drivers:\n  - {name: theta2, type: angle, link: crank}\n";
  const auto j = run_json(shell_quote(write(scratch_dir("kin-triple"), "triple.yaml", yaml)) + " --sweep 10:350:10");
  ASSERT_EQ(j["positions"].size(), 35u);
  for (const auto& p : j["positions"]) {
    const double theta2 = p["input_deg"].get<double>();
    EXPECT_LT(angle_gap_deg(p["q"]["rocker.angle_deg"].get<double>(), theta2), 1e-6);
    EXPECT_LT(angle_gap_deg(p["q"]["third.angle_deg"].get<double>(), theta2), 1e-6);
  }
  EXPECT_TRUE(j["dead_points"].empty());
  ASSERT_EQ(j["change_points"].size(), 1u);
  EXPECT_NEAR(j["change_points"][0]["input_deg"].get<double>(), 180.0, 1e-5);
  EXPECT_FALSE(j["change_points"][0]["bifurcation"].get<bool>());
}

// A weighted parallelogram driven at constant speed: the coupler translates on a circle (its
// inertia force is radial and does no work), crank and rocker turn uniformly, so the driving
// torque is the weights' alone, T = g a cos(theta2) (m_crank / 2 + m_coupler + m_rocker / 2)
// (virtual work, centres of mass at mid-link). It holds through the change point at 180 deg,
// where Phi_q is singular and the torque comes by virtual power along the branch followed.
TEST(KinCommand, TheDrivingTorqueIsContinuousThroughAChangePoint) {
  std::string yaml = four_bar_yaml({"parallelogram", "crank", "coupler", "rocker", 40, 100, 40, 100, 40, 0, 40});
  const auto weigh = [&](const std::string& link, double kg, double half) {
    const std::string from = "  " + link + ": {points:";
    const auto at = yaml.find(from);
    ASSERT_NE(at, std::string::npos);
    const auto close = yaml.find(" deg}", at);
    yaml.insert(close + 4, fmt::format(", mass: {} kg, centre_of_mass: [{}, 0], inertia: 1e-4 kg*m^2", kg, half));
  };
  weigh("crank", 0.1, 20);
  weigh("coupler", 0.3, 50);
  weigh("rocker", 0.2, 20);
  yaml.replace(yaml.find("link: crank}"), 12, "link: crank, speed: 25 rad/s}");
  yaml += "loads:\n  gravity: 9.81 m/s^2\n";
  const auto j = run_json(shell_quote(write(scratch_dir("kin-weighted-parallelogram"), "p.yaml", yaml)) + " --sweep 170:190:2.5");
  ASSERT_EQ(j["positions"].size(), 9u);
  for (const auto& p : j["positions"]) {
    const double theta2 = p["input_deg"].get<double>() * M_PI / 180;
    const double expected = 9.81 * 0.040 * std::cos(theta2) * (0.1 / 2 + 0.3 + 0.2 / 2);
    EXPECT_NEAR(p["driving_torque_Nm"].get<double>(), expected, 1e-9) << p["input_deg"];
    if (std::abs(p["input_deg"].get<double>() - 180) > 1e-9)
      EXPECT_NEAR(p["driving_torque_lagrange_Nm"].get<double>(), expected, 1e-9) << p["input_deg"];
    else
      EXPECT_TRUE(p["driving_torque_lagrange_Nm"].is_null() && p["reactions"].empty() && p["on_change_point"].get<bool>());
  }
  for (const auto& w : j["warnings"]) EXPECT_EQ(w.get<std::string>().find("non-finite"), std::string::npos) << w;

  // --at on the change point itself: the position is the crossing's (all links on the ground
  // line, rocker at 180 deg), with the same torque.
  const auto at = run_json(shell_quote(write(scratch_dir("kin-weighted-parallelogram"), "p.yaml", yaml)) + " --at 180");
  ASSERT_EQ(at["positions"].size(), 1u) << at["warnings"];
  EXPECT_NEAR(at["positions"][0]["q"]["rocker.angle_deg"].get<double>(), 180.0, 1e-6);
  EXPECT_NEAR(at["positions"][0]["driving_torque_Nm"].get<double>(), -9.81 * 0.040 * (0.1 / 2 + 0.3 + 0.2 / 2), 1e-9);
  EXPECT_TRUE(at["positions"][0]["on_change_point"].get<bool>());
}

// The seed-004 pantograph's parallelogram O P R S lies flat where the coupler QP is square to
// the crank OP: then |OP|^2 = Q.P and |QP|^2 = |OP|^2 + |OQ|^2 - 2 Q.P give s^2 = 2 l1^2 (s =
// 212.132 mm) and 200 cos(phi1) - s sin(phi1) = 150, phi1 = acos(150 / 291.548) - 46.686 =
// 12.3501 deg (hand derivation). Reaching --at 60 from the drawing at -80 deg crosses it on the
// parallelogram (the arm RS turns with the crank: arm = phi1 + 180 deg; the link OS with PR:
// link = coupler + 90 deg); with --branch switch on the crossed one, where S is the mirror of
// the parallelogram's S in the line O R: link angle 2 * atan2(R) - 210 deg.
TEST(KinCommand, PantographReachesPastItsChangePoint) {
  const std::string file = shell_quote(kExamples + "pantograph.yaml") + " --driver phi1 --at 60";
  const auto j = run_json(file);
  ASSERT_EQ(j["positions"].size(), 1u);
  ASSERT_EQ(j["change_points"].size(), 1u);
  EXPECT_NEAR(j["change_points"][0]["input_deg"].get<double>(), std::acos(150 / std::hypot(200.0, 150 * M_SQRT2)) * 180 / M_PI -
                                                                       std::atan2(150 * M_SQRT2, 200.0) * 180 / M_PI, 1e-5);
  const auto& q = j["positions"][0]["q"];
  EXPECT_NEAR(q["arm.angle_deg"].get<double>(), 240.0, 1e-6);
  EXPECT_NEAR(q["link.angle_deg"].get<double>(), q["coupler.angle_deg"].get<double>() + 90.0, 1e-6);
  const auto k = run_json(file + " --branch switch");
  ASSERT_EQ(k["positions"].size(), 1u);
  // R = P + 100 (cos 210, sin 210) with P = 150 (cos 60, sin 60), coupler at 120 deg.
  const double rx = 75 - 50 * std::sqrt(3.0), ry = 75 * std::sqrt(3.0) - 50;
  const double mirrored = 2 * std::atan2(ry, rx) * 180 / M_PI - 210;
  EXPECT_LT(angle_gap_deg(k["positions"][0]["q"]["link.angle_deg"].get<double>(), mirrored), 1e-6);
  EXPECT_EQ(k["change_points"][0]["branch"], "switched");
}

// Norton's four-bar with coupler and rocker drawn at 0 deg (only the crank drawn at 40 deg), and
// with every angle drawn 0: both assemble (issue 13 item 3; they failed with "singular Jacobian"
// and "under-driven ... rank of Phi_q 7"). At --at 40 the angles are one of the two closed-form
// branches: theta3 = 20.298, theta4 = 57.325 (open) or -60.978, -98.005 deg (crossed),
// triangle A B O4 by the law of cosines.
TEST(KinCommand, ALazyDrawingAssembles) {
  const auto dir = scratch_dir("kin-lazy");
  std::string text = slurp(kExamples + "four_bar.yaml");
  const auto set_angle = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  set_angle("angle: 20 deg", "angle: 0 deg");
  set_angle("angle: 75 deg", "angle: 0 deg");
  const std::string half = write(dir, "lazy.yaml", text);
  set_angle("angle: 40 deg", "angle: 0 deg");
  const std::string flat = write(dir, "flat.yaml", text);
  for (const std::string& file : {half, flat}) {
    const auto j = run_json(shell_quote(file) + " --at 40");
    ASSERT_EQ(j["positions"].size(), 1u) << file << j["warnings"];
    const double theta3 = j["positions"][0]["q"]["coupler.angle_deg"], theta4 = j["positions"][0]["q"]["rocker.angle_deg"];
    const bool open = std::abs(theta4 - 57.32488) < 1e-3;
    EXPECT_TRUE(open || std::abs(theta4 + 98.00496) < 1e-3) << theta4;
    EXPECT_NEAR(theta3, open ? 20.29788 : -60.97797, 1e-3);
    EXPECT_EQ(j["dof"], 1);
  }
  // The half-lazy drawing is nearer the open branch (|20| + |57| deg against |61| + |98|).
  EXPECT_NEAR(run_json(shell_quote(half) + " --at 40")["positions"][0]["q"]["rocker.angle_deg"].get<double>(), 57.32488, 1e-3);
}

// The pantograph's crank cannot pass the position where the coupler QP lies horizontal, with P
// 250 mm left of the guide x = 200 mm: 150 cos(phi1) = -50, phi1 = acos(-1/3) = 109.4712 deg.
TEST(KinCommand, CannotAssembleIsAWarning) {
  const auto r = run_gearkit("kin " + shell_quote(kExamples + "pantograph.yaml") + " --driver phi1 --at 120 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["positions"].empty());
  ASSERT_FALSE(j["warnings"].empty());
  bool cannot = false;
  for (const auto& w : j["warnings"]) cannot = cannot || w.get<std::string>().find("cannot") != std::string::npos;
  EXPECT_TRUE(cannot) << j["warnings"];
  ASSERT_EQ(j["dead_points"].size(), 1u);
  EXPECT_NEAR(j["dead_points"][0]["input_deg"].get<double>(), std::acos(-1.0 / 3.0) * 180 / M_PI, 1e-4);
}

TEST(KinCommand, BadInput) {
  const auto dir = scratch_dir("kin-bad");
  const std::string base = slurp(kExamples + "four_bar.yaml");
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string t = base;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  expect_bad_input(run_gearkit("kin " + shell_quote(write(dir, "a.yaml", replaced("at: [coupler.B, rocker.B]", "at: [coupler.B, rockr.B]")))),
                   "a.yaml:31:");
  expect_bad_input(run_gearkit("kin " + shell_quote(write(dir, "b.yaml", replaced("at: [coupler.B, rocker.B]", "at: [coupler.X, rocker.B]")))),
                   "link 'coupler' has no point 'X'");
  expect_bad_input(run_gearkit("kin " + shell_quote(write(dir, "c.yaml", replaced("  - {name: O4, type: revolute, at: [rocker.O4, ground.O4]}\n", "")))),
                   "under-driven");
  expect_bad_input(run_gearkit("kin " + shell_quote(write(dir, "d.yaml", replaced("drivers:\n", "drivers:\n  - {name: extra, type: angle, link: rocker}\n")))),
                   "over-constrained");
  expect_bad_input(run_gearkit("kin " + shell_quote(write(dir, "e.yaml", replaced("mass: 0.1 kg", "mass: 0.1 mm")))), "e.yaml:");
  expect_bad_input(run_gearkit("kin " + shell_quote(write(dir, "f.yaml", replaced("joints:", "elements:\n  - {type: warp_drive}\njoints:")))),
                   "unknown element type 'warp_drive'");
  expect_bad_input(run_gearkit("kin " + shell_quote(write(dir, "g.yaml", replaced("angle: 40 deg", "angel: 40 deg")))), "unknown key 'angel'");
  expect_bad_input(run_gearkit("kin " + shell_quote(kExamples + "four_bar.yaml") + " --sweep 0:360"), "option '--sweep'");
  expect_bad_input(run_gearkit("kin " + shell_quote(kExamples + "four_bar.yaml") + " --sweep 0:360:0"), "option '--sweep'");
  expect_bad_input(run_gearkit("kin " + shell_quote(kExamples + "four_bar.yaml") + " --at 3 mm"), "");
  expect_bad_input(run_gearkit("kin " + shell_quote(kExamples + "four_bar.yaml") + " --at 10 --sweep 0:1:1"), "--at");
  expect_bad_input(run_gearkit("kin " + shell_quote(kExamples + "four_bar.yaml") + " --outputs nope"), "option '--outputs'");
  expect_bad_input(run_gearkit("kin " + shell_quote((dir / "missing.yaml").string())), "missing.yaml");
  expect_bad_input(run_gearkit("kin"), "expected the FILE argument, found none");
  // A failed --plot leaves no file and says which option.
  expect_bad_input(run_gearkit("kin " + shell_quote(kExamples + "four_bar.yaml") + " --plot /nonexistent/dir/p.svg"), "--plot");
}

const std::string kSeeds = std::string(GEARKIT_SOURCE_DIR) + "/examples/seeds/";

// Seed 004 B1 (door retainer, deduced dimensions): the lever's free body is the seed's diagram,
// N_A = N_B horizontal (its horizontal balance -N_A + N_B = 0), T_A and T_B along the rod, and
// the casing's vertical force V = T_A + T_B at O; the rod pulled up wedges from mu = 0.06855.
TEST(KinCommand, DoorRetainerFrictionAndFreeBodies) {
  const auto j = run_json(shell_quote(kSeeds + "etseib2021_b1_door_retainer.yaml"));
  const auto& fr = j["positions"][0]["friction"];
  EXPECT_FALSE(fr["forward"]["wedged"].get<bool>());
  const double mu_min = 10 * std::sqrt(10.3 * 10.3 - 100) / 10 / 36;  // d_e tan(alpha) / (2e + d_e)
  EXPECT_NEAR(fr["forward"]["critical_friction"][0]["mu"].get<double>(), mu_min, 1e-12);
  EXPECT_TRUE(fr["reverse"]["wedging_factor"].is_null());
  const nlohmann::json* lever = nullptr;
  for (const auto& b : j["free_bodies"])
    if (b["link"] == "lever") lever = &b;
  ASSERT_NE(lever, nullptr);
  std::map<std::string, nlohmann::json> f;
  for (const auto& x : (*lever)["forces"]) f[x["from"].get<std::string>()] = x;
  EXPECT_NEAR(f["A"]["force_N"][0].get<double>(), -f["B"]["force_N"][0].get<double>(), 1e-9);
  EXPECT_NEAR(f["O"]["force_N"][0].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(-f["O"]["force_N"][1].get<double>(), f["A"]["force_N"][1].get<double>() + f["B"]["force_N"][1].get<double>(), 1e-9);
  EXPECT_NEAR(f["A"]["friction"].get<double>(), 0.05 * f["A"]["normal_N"].get<double>(), 1e-9);
}

// Seed 004 D1 (wedge brake): T_min = F0 r / (2 cos(alpha)) clockwise at mu = tan(alpha); counter-
// clockwise it wedges. Seed 000 P1 (gym machine): the point driver V_A = 2 m/s and the speed of
// the seat. Seed 004 B2 d): the spring force from the given torque.
TEST(KinCommand, WedgeBrakePointDriverAndInverseKinetostatics) {
  auto j = run_json(shell_quote(kSeeds + "etseib2021_d1_wedge_brake.yaml"));
  EXPECT_NEAR(j["positions"][0]["driving_torque_Nm"].get<double>(), -15 * 0.06 / (2 * std::cos(15 * M_PI / 180)), 1e-9);
  EXPECT_TRUE(j["positions"][0]["friction"]["reverse"]["wedged"].get<bool>());
  EXPECT_TRUE(j["positions"][0]["friction"]["reverse"][std::string("driving_torque_Nm")].is_null());
  j = run_json(shell_quote(kSeeds + "otm2015_p1_gym.yaml"));
  const auto& o = j["positions"][0]["outputs"];
  EXPECT_NEAR(o["omega_2_rate_rad_s"].get<double>(), 2.0 / 1.2, 1e-6);  // omega_2 = V_A / O2A, clockwise
  EXPECT_NEAR(o["V_B_mm_s"].get<double>(), 2000.0 * 0.3 / 1.2, 1e-3);
  EXPECT_NEAR(o["V_5_mm_s"].get<double>(), o["V_C_mm_s"].get<double>() * 100 / 75, 1e-6);  // homology O4D/O4C
  EXPECT_TRUE(o["a_5_ratio"].is_null());
  EXPECT_TRUE(j["warnings"].empty()) << j["warnings"].dump();
  j = run_json(shell_quote(kSeeds + "etseib2021_b2d_spring_compressor_inverse.yaml"));
  EXPECT_NEAR(j["positions"][0]["driving_torque_Nm"].get<double>(), -10.0, 1e-9);
  EXPECT_EQ(j["positions"][0]["unknown_loads"][0]["name"], "F_m");
}

TEST(KinCommand, BadFrictionAndContactInput) {
  const auto dir = scratch_dir("kin-bad-friction");
  const std::string base = slurp(kSeeds + "etseib2021_b1_door_retainer.yaml");
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string t = base;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  expect_bad_input(run_gearkit("kin " + shell_quote(write(dir, "a.yaml", replaced("axis: 90 deg, side: left, ", "axis: 90 deg, ")))),
                   "side: left");
  expect_bad_input(run_gearkit("kin " + shell_quote(write(dir, "b.yaml", replaced("side: left, friction: 0.05", "side: left, friction: -1")))),
                   "friction coefficient >= 0");
  expect_bad_input(run_gearkit("kin " + shell_quote(write(dir, "c.yaml", replaced("side: left", "side: up")))), "c.yaml:");
  expect_bad_input(run_gearkit("kin " + shell_quote(write(dir, "d.yaml", replaced("speed: 0 m/s}", "speed: 0 m/s, effort: 3 N}")))),
                   "unknown load");
}

TEST(KinCommand, EveryExampleRuns) {
  for (const auto& entry : std::filesystem::directory_iterator(kExamples)) {
    if (entry.path().extension() != ".yaml") continue;
    const auto r = run_gearkit("kin " + shell_quote(entry.path().string()) + " --format json");
    EXPECT_EQ(r.status, 0) << entry.path() << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["dof"].get<int>(), 1) << entry.path();
    EXPECT_FALSE(j["positions"].empty()) << entry.path();
    // The only warning an example may give: a four-bar's transmission angle below the summary's
    // 40 deg limit (four_bar.yaml: 26.38 deg, issue 32), which its summary must show.
    for (const auto& w : j["warnings"]) {
      EXPECT_EQ(w.get<std::string>().rfind("transmission angle down to", 0), 0u) << entry.path() << j["warnings"].dump();
      EXPECT_LT(j["summary"]["transmission_angle_min_deg"].get<double>(), 40.0) << entry.path();
    }
  }
}

// `--example chain:N` writes the chain of N four-bar loops: Gruebler 3 (2N + 1) - 2 (3N + 1) = 1,
// and every loop closes at Freudenstein's open-branch angle (Norton eq. 4.10) with the previous
// rocker angle as its input.
TEST(KinCommand, ExampleChainOfLoops) {
  const auto dir = scratch_dir("kin_example_chain");
  const std::string file = (dir / "chain.yaml").string();
  ASSERT_EQ(run_gearkit("kin --example chain:4 --output " + shell_quote(file)).status, 0);
  const auto j = run_json(shell_quote(file) + " --at 30");
  EXPECT_EQ(j["gruebler"], 1);
  EXPECT_EQ(j["dof"], 1);
  EXPECT_EQ(j["redundant"], 0);
  double theta = 30.0 * M_PI / 180.0;
  for (int k = 0; k < 4; ++k) {
    const auto [theta3, theta4] = gearkit::kin::testing::four_bar_closed_form({0.040, 0.120, 0.080, 0.100}, theta);
    const std::string i = std::to_string(k);
    EXPECT_NEAR(j["positions"][0]["q"]["coupler" + i + ".angle_deg"].get<double>(), theta3 * 180 / M_PI, 1e-8) << k;
    EXPECT_NEAR(j["positions"][0]["q"]["rocker" + i + ".angle_deg"].get<double>(), theta4 * 180 / M_PI, 1e-8) << k;
    theta = theta4;
  }
  expect_bad_input(run_gearkit("kin --example chain:0"), "option '--example'");
  expect_bad_input(run_gearkit("kin --example chain:12x"), "option '--example'");
  expect_bad_input(run_gearkit("kin --example lattice:3"), "option '--example'");
  expect_bad_input(run_gearkit("kin " + shell_quote(file) + " --example chain:3"), "option '--example'");
}

}  // namespace
