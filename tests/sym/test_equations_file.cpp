// Tests for gearkit/sym/equations_file.hpp: a bad equations: section stops `kin --equations`
// with one line naming file:line:column, status 2.
#include <gearkit/sym/expression.hpp>

#include <run_gearkit.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;

namespace {

const char* kFourBar = R"(mechanism: four-bar
ground: {O2: [0, 0], O4: [100, 0]}
links:
  crank: {points: {O2: [0, 0], A: [40, 0]}, angle: 40 deg}
  coupler: {points: {A: [0, 0], B: [120, 0]}, angle: 20 deg}
  rocker: {points: {O4: [0, 0], B: [80, 0]}, angle: 75 deg}
joints:
  - {name: O2, type: revolute, at: [crank.O2, ground.O2]}
  - {name: A, type: revolute, at: [crank.A, coupler.A]}
  - {name: B, type: revolute, at: [coupler.B, rocker.B]}
  - {name: O4, type: revolute, at: [rocker.O4, ground.O4]}
drivers:
  - {name: theta2, type: angle, link: crank}
)";

const char* kGood = "equations:\n  coordinates:\n    - {name: phi1, angle: [crank.O2, crank.A]}\n"
                    "    - {name: phi2, angle: [coupler.A, coupler.B]}\n    - {name: phi3, angle: [rocker.O4, rocker.B]}\n"
                    "  symbols:\n    - {name: a, length: [crank.O2, crank.A]}\n";

gearkit::testing::RunResult run_with(const std::string& section, bool json = false) {
  const std::filesystem::path dir = gearkit::testing::scratch_dir("sym-equations-file");
  const std::filesystem::path p = dir / "m.yaml";
  std::ofstream(p) << kFourBar << section;
  return run_gearkit("kin " + shell_quote(p.string()) + " --equations" + (json ? " --format json" : ""));
}

nlohmann::json run_with_json() {
  const auto r = run_with(kGood, true);
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(r.out)["equations"];
}

void expect_bad(const std::string& section, const std::string& part) {
  const auto r = run_with(section);
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
  EXPECT_EQ(r.err.rfind("gearkit: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace

TEST(EquationsFile, GoodSectionWorks) {
  // Loop O2 - A - B - O4 with the crank written as a, the rest as numbers (mm).
  const auto j = run_with_json();
  EXPECT_TRUE(gearkit::sym::equivalent_up_to_sign(j["phi"][0]["text"], "a*cos(phi1)+120*cos(phi2)-80*cos(phi3)-100"))
      << j["phi"].dump();
}

TEST(EquationsFile, BadSectionsNameTheirPlace) {
  expect_bad("equations:\n  coordinates:\n    - {name: phi1, angle: [crank.O2, wheel.A]}\n", "m.yaml:16:");
  expect_bad("equations:\n  coordinates:\n    - {name: phi1, angle: [crank.O2, wheel.A]}\n", "unknown link 'wheel'");
  expect_bad("equations:\n  coordinates:\n    - {name: s, slide: A}\n", "expected the name of a prismatic joint");
  expect_bad("equations:\n  coordinates:\n    - {name: phi1, angle: [crank.O2, coupler.A]}\n", "same link");
  expect_bad("equations:\n  coordinates:\n    - {name: phi1, angle: [crank.O2, crank.A]}\n"
             "    - {name: phi1, angle: [rocker.O4, rocker.B]}\n", "used twice");
  expect_bad("equations:\n  coordinates:\n    - {name: 'sin', angle: [crank.O2, crank.A]}\n", "symbol name");
  expect_bad("equations:\n  coordinates: []\n  bogus: 1\n", "unknown key 'bogus'");
}
