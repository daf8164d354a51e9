// Tests for gearkit/sym/loop_equations.hpp through `gearkit kin FILE --equations`: the
// equations the seed 004 writes by hand for the pantograph, the lifting platform, the spring
// compressor and the feeder arm, compared term by term after symbolic simplification (rows of
// Phi may differ in sign and order: Phi = 0 either way; a row's Jacobian follows its sign).
// The seed's own text is typed below from 004_b4a8ce5a956e12a3.txt.
#include <gearkit/sym/expression.hpp>

#include <run_gearkit.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;
using nlohmann::json;

namespace {

constexpr double kDeg = std::numbers::pi / 180;

json equations(const std::string& file, const std::string& at) {
  const auto r = run_gearkit("kin " + shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/" + file) +
                             " --at " + at + " --equations --format json");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  return json::parse(r.out)["equations"];
}

// Each seed row of Phi equals +-one generated row, and the Jacobian row with the same sign.
void expect_seed_equations(const json& eq, const std::vector<std::string>& phi,
                           const std::vector<std::vector<std::string>>& phi_q) {
  ASSERT_EQ(eq["phi"].size(), phi.size());
  std::vector<bool> used(phi.size());
  for (std::size_t i = 0; i < phi.size(); ++i) {
    bool found = false;
    for (std::size_t k = 0; k < phi.size() && !found; ++k) {
      const std::string ours = eq["phi"][k]["text"];
      if (used[k] || !gearkit::sym::equivalent_up_to_sign(ours, phi[i])) continue;
      found = used[k] = true;
      const bool same_sign = gearkit::sym::equivalent(ours, phi[i]);
      for (std::size_t j = 0; j < phi_q[i].size(); ++j) {
        const std::string seed = same_sign ? phi_q[i][j] : "-(" + phi_q[i][j] + ")";
        EXPECT_TRUE(gearkit::sym::equivalent(eq["phi_q"][k][j]["text"], seed))
            << "Phi_q(" << k + 1 << "," << j + 1 << "): ours " << eq["phi_q"][k][j]["text"] << ", seed " << seed;
      }
    }
    EXPECT_TRUE(found) << "seed row " << phi[i] << " not among ours: " << eq["phi"].dump();
  }
}

const json& ratio(const json& eq, const std::string& name) {
  for (const auto& r : eq["ratios"])
    if (r["ratio"] == name) return r;
  static const json none;
  ADD_FAILURE() << "no ratio " << name;
  return none;
}

// The solver's velocities and accelerations (kin, body coordinates) must satisfy the generated
// velocity and acceleration equations: Phi_q q' = 0 and Phi_q q'' = gamma.
void expect_solver_consistent(const json& eq) {
  const std::size_t m = eq["phi"].size(), n = eq["coordinates"].size();
  for (std::size_t i = 0; i < m; ++i) {
    double v = 0, a = 0, scale = 1;
    for (std::size_t j = 0; j < n; ++j) {
      const json& c = eq["coordinates"][j];
      const bool angle = c["kind"] == "angle";
      const double g = eq["phi_q"][i][j]["value"];
      v += g * c[angle ? "rate_rad_s" : "rate_mm_s"].get<double>();
      a += g * c[angle ? "acceleration_rad_s2" : "acceleration_mm_s2"].get<double>();
      scale = std::max(scale, std::abs(g));
    }
    EXPECT_NEAR(eq["phi"][i]["value"].get<double>(), 0.0, 1e-7 * scale);
    EXPECT_NEAR(v, 0.0, 1e-7 * scale) << "row " << i + 1;
    EXPECT_NEAR(a, eq["gamma"][i]["value"].get<double>(), 1e-6 * scale) << "row " << i + 1;
  }
}

double coordinate(const json& eq, const std::string& name) {
  for (const auto& c : eq["coordinates"])
    if (c["name"] == name) return c.contains("value_rad") ? c["value_rad"].get<double>() : c["value_mm"].get<double>();
  ADD_FAILURE() << "no coordinate " << name;
  return 0;
}

}  // namespace

// Seed 004, exam 2020-21, exercise 1 b) and e): the pantograph, q = {phi1, phi2, s}.
TEST(LoopEquations, PantographAsTheSeedWritesIt) {
  const json eq = equations("pantograph.yaml", "-60");
  expect_seed_equations(eq, {"-l3*cos(phi2)-l1*cos(phi1)+d", "l3*sin(phi2)-l1*sin(phi1)-s"},
                        {{"l1*sin(phi1)", "l3*sin(phi2)", "0"}, {"-l1*cos(phi1)", "l3*cos(phi2)", "-1"}});
  // d) the dead point of s: phi1 = -60 deg, phi2 = 60 deg, s_max = 346.4 mm.
  EXPECT_NEAR(coordinate(eq, "phi1") / kDeg, -60.0, 1e-9);
  EXPECT_NEAR(coordinate(eq, "phi2") / kDeg, 60.0, 5e-3);
  EXPECT_NEAR(coordinate(eq, "s"), 346.4, 0.05);
  // e) phi2'/phi1' = l1/l3 = 0.6 there.
  EXPECT_NEAR(ratio(eq, "phi2'/phi1'")["value"].get<double>(), 0.6, 5e-5);
  EXPECT_TRUE(gearkit::sym::equivalent(ratio(eq, "phi2'/phi1'")["text"], "-l1*sin(phi1)/(l3*sin(phi2))"));
  expect_solver_consistent(eq);
}

// Seed 004, exam 2021, exercise 2 a) and b): the lifting platform, q = {phi1, phi2, phi3}.
TEST(LoopEquations, LiftingPlatformAsTheSeedWritesIt) {
  const json eq = equations("lifting_platform.yaml", "69.5");
  expect_seed_equations(eq, {"l1*cos(phi1)-l2*cos(phi2)-l3*cos(phi3)+d", "l1*sin(phi1)+l2*sin(phi2)-l3*sin(phi3)-h"},
                        {{"-l1*sin(phi1)", "l2*sin(phi2)", "l3*sin(phi3)"},
                         {"l1*cos(phi1)", "l2*cos(phi2)", "-l3*cos(phi3)"}});
  // b) phi1'/phi3' = l3 sin(phi2 + phi3) / (l1 sin(phi2 + phi1)), at q = {30, 42.6, 69.5} deg.
  const json& r = ratio(eq, "phi1'/phi3'");
  EXPECT_TRUE(gearkit::sym::equivalent(r["text"], "l3*sin(phi2+phi3)/(l1*sin(phi2+phi1))")) << r["text"];
  EXPECT_NEAR(r["value"].get<double>(), 275 * std::sin(112.1 * kDeg) / (400 * std::sin(72.6 * kDeg)), 1e-6);
  EXPECT_NEAR(coordinate(eq, "phi1") / kDeg, 30.0, 1e-6);
  EXPECT_NEAR(coordinate(eq, "phi2") / kDeg, 42.6, 1e-6);
  expect_solver_consistent(eq);
}

// Seed 004, 2020-21 second paper, exercise 2 a) and b): the spring compressor, angles from the
// vertical and clockwise as the seed measures them.
TEST(LoopEquations, SpringCompressorAsTheSeedWritesIt) {
  const json eq = equations("spring_compressor.yaml", "46.24");
  expect_seed_equations(eq, {"l1*sin(phi1)-l2*cos(phi2)+l3*cos(phi3)-d", "l1*cos(phi1)+l2*sin(phi2)-l3*sin(phi3)-h"},
                        {{"l1*cos(phi1)", "l2*sin(phi2)", "-l3*sin(phi3)"},
                         {"-l1*sin(phi1)", "l2*cos(phi2)", "-l3*cos(phi3)"}});
  const json& r = ratio(eq, "phi3'/phi1'");
  EXPECT_TRUE(gearkit::sym::equivalent(r["text"], "-l1*cos(phi2-phi1)/(l3*sin(phi2-phi3))")) << r["text"];
  EXPECT_NEAR(coordinate(eq, "phi1") / kDeg, 43.76, 1e-6);
  EXPECT_NEAR(coordinate(eq, "phi3") / kDeg, 0.0, 1e-6);
  expect_solver_consistent(eq);
}

// Seed 004, 2020-21 third paper, exercise 2 b): the feeder arm, q = {phi1, phi2, phi3, x}; the
// third row is the seed's "projection of O2R on the horizontal" (the jaw's vertical slide
// eliminated).
TEST(LoopEquations, FeederArmAsTheSeedWritesIt) {
  const json eq = equations("feeder_arm.yaml", "90");
  expect_seed_equations(eq,
                        {"l1*cos(phi1)-l2*cos(phi2)-l3*cos(phi3)+d", "l1*sin(phi1)-l2*sin(phi2)-l3*sin(phi3)+h1",
                         "l4*cos(phi3+alpha)+x"},
                        {{"-l1*sin(phi1)", "l2*sin(phi2)", "l3*sin(phi3)", "0"},
                         {"l1*cos(phi1)", "-l2*cos(phi2)", "-l3*cos(phi3)", "0"},
                         {"0", "0", "-l4*sin(phi3+alpha)", "1"}});
  expect_solver_consistent(eq);
}

// Markdown carries LaTeX; without an equations: section every link angle is a coordinate.
TEST(LoopEquations, MarkdownLatexAndDefaultCoordinates) {
  const std::string file = shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/four_bar.yaml");
  const auto md = run_gearkit("kin " + file + " --at 40 --equations --format md");
  ASSERT_EQ(md.status, 0) << md.err;
  EXPECT_NE(md.out.find("\\cos(\\varphi_{1})"), std::string::npos) << md.out;
  const auto j = run_gearkit("kin " + file + " --at 40 --equations --format json");
  ASSERT_EQ(j.status, 0) << j.err;
  const json eq = json::parse(j.out)["equations"];
  EXPECT_EQ(eq["phi"].size(), eq["coordinates"].size() - 1);  // a four-bar: n - 1 rows
  expect_solver_consistent(eq);
}
