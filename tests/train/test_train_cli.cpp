// The `gearkit train` command end to end: runs GEARKIT_EXE, checks JSON, messages and exit codes.
#include <gtest/gtest.h>

#include <unistd.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int status = -1;
  std::string out;
  std::string err;
};

fs::path scratch() {
  // One folder per process: ctest runs several test processes at once.
  const fs::path dir = fs::path(GEARKIT_BINARY_DIR) / "test-scratch" / ("train-cli-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

CliRun gearkit(const std::string& args) {
  const fs::path err = scratch() / "stderr.txt";
  const std::string command = std::string("'") + GEARKIT_EXE + "' " + args + " 2>'" + err.string() + "'";
  CliRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) run.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err);
  std::stringstream ss;
  ss << in.rdbuf();
  run.err = ss.str();
  return run;
}

std::string example(const std::string& name) {
  return std::string("'") + GEARKIT_SOURCE_DIR + "/examples/trains/" + name + "'";
}

std::string write_yaml(const std::string& name, const std::string& text) {
  const fs::path p = scratch() / name;
  std::ofstream(p) << text;
  return "'" + p.string() + "'";
}

nlohmann::json json_of(const CliRun& run) {
  try {
    return nlohmann::json::parse(run.out);
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not JSON: " << e.what() << "\n" << run.out << run.err;
    return {};
  }
}

// Seed 004 (CVT train): w_b/w_1 = 47/72 with w5 = w1, input 1000 rpm -> arm at 652.78 rpm.
TEST(TrainCli, SeedCvtTrainJson) {
  const CliRun run = gearkit("train " + example("seed_cvt_train.yaml") + " --format json");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto j = json_of(run);
  EXPECT_EQ(j["dof"], 2);
  EXPECT_EQ(j["ratio"]["exact"], "47/72");
  EXPECT_NEAR(j["ratio"]["value"].get<double>(), 47.0 / 72.0, 1e-15);
  EXPECT_NEAR(j["speeds_rpm"]["b"].get<double>(), 1000.0 * 47.0 / 72.0, 1e-9);
  EXPECT_NEAR(j["speeds_rpm"]["23"].get<double>(), -1000.0 * 35.0 / 90.0, 1e-9);
  EXPECT_EQ(j["equations"].size(), 3u);
  EXPECT_TRUE(j["warnings"].empty());
}

TEST(TrainCli, SeedCvtTrainTextShowsFractionAndDecimal) {
  const CliRun run = gearkit("train " + example("seed_cvt_train.yaml"));
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("47/72 = 0.652778"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("w_23 / w_1 = -35/90"), std::string::npos) << run.out;
}

// Seed 004, exam C exercise 1 a): the Willis equations in u = {w1, wb, w45, w7}, planets
// eliminated, as the exam writes them ([1] and [2] of its solution).
TEST(TrainCli, SeedWillisInTheUsersVector) {
  const CliRun run = gearkit("train " + example("seed_two_epicyclic_stages.yaml") + " --willis w_1,w_b,w_45,w_7 --format json");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto j = json_of(run);
  ASSERT_EQ(j["willis_in_vector"].size(), 2u);
  EXPECT_EQ(j["willis_in_vector"][0]["tau"], "-2/5");
  EXPECT_EQ(j["willis_in_vector"][0]["equation"], "-2/5 w_1 + 7/5 w_b - w_45 = 0");
  EXPECT_EQ(j["willis_in_vector"][1]["tau"], "-7/2");
  EXPECT_EQ(j["willis_in_vector"][1]["equation"], "-7/2 w_45 + 9/2 w_b - w_7 = 0");
  EXPECT_TRUE(j["warnings"].empty());
  // Exam A exercise 2 b): the relation among w3 (member 23), w5 and wb only.
  const CliRun cvt = gearkit("train " + example("seed_cvt_train.yaml") + " --willis 23,5,b --format json");
  ASSERT_EQ(cvt.status, 0) << cvt.err;
  const auto k = json_of(cvt);
  ASSERT_EQ(k["willis_in_vector"].size(), 1u);
  EXPECT_EQ(k["willis_in_vector"][0]["equation"], "-1/3 w_23 + 4/3 w_b - w_5 = 0");
  const CliRun bad = gearkit("train " + example("seed_cvt_train.yaml") + " --willis 23,4");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("planet '4'"), std::string::npos) << bad.err;
}

// Seed 004 second exam: modes 7/5, 9/7 and 1.
TEST(TrainCli, SeedModes) {
  const CliRun run = gearkit("train " + example("seed_two_epicyclic_stages.yaml") +
                          " --input 1 --output-member 7 --modes --format json");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto j = json_of(run);
  ASSERT_EQ(j["modes"].size(), 3u);
  EXPECT_EQ(j["modes"][0]["exact"], "7/5");
  EXPECT_EQ(j["modes"][1]["exact"], "9/7");
  EXPECT_EQ(j["modes"][2]["exact"], "1");
  EXPECT_EQ(j["modes"][2]["condition"], "w_b = w_45");
}

// OTM 2015 problem 3 by synthesis: z1 = 15 -> z2 = 60, z3 = 18, z4 = 72.
TEST(TrainCli, SynthesisOtmReducer) {
  const CliRun run = gearkit("train synth reducer --m1 6 --m2 5 --ratio 1/16 --z1 15 --format json");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto j = json_of(run);
  ASSERT_FALSE(j["candidates"].empty());
  EXPECT_EQ(j["candidates"][0]["z2"], 60);
  EXPECT_EQ(j["candidates"][0]["z3"], 18);
  EXPECT_EQ(j["candidates"][0]["z4"], 72);
  EXPECT_EQ(j["candidates"][0]["ratio_exact"], "1/16");
}

// Torques on the simple planetary example, 10 N*m on the sun, ring held (hand derivation in
// test_torques.cpp): carrier -35 N*m, ring reaction 25 N*m; efficiency (24 + eta0 60)/84.
TEST(TrainCli, TorquesAndEfficiency) {
  const CliRun run = gearkit("train " + example("simple_planetary.yaml") + " --torque sun=10N*m --format json");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto j = json_of(run);
  EXPECT_NEAR(j["torques"]["ideal_Nm"]["carrier"].get<double>(), -35.0, 1e-12);
  EXPECT_NEAR(j["torques"]["ideal_Nm"]["ring"].get<double>(), 25.0, 1e-12);
  EXPECT_NEAR(j["torques"]["efficiency"].get<double>(), (24 + 0.98 * 0.99 * 60) / 84.0, 1e-12);
  EXPECT_FALSE(j["torques"]["power_circulation"].get<bool>());
}

// LECAD test run (lecad.uni-lj.si/~leon/FS/PlanetryTransmissions/node8.html): ratio 6.14286 and
// centre distance a = 56.8 mm with shifts x = 0.4380 (sun), 0.0426 (planet), 0 (ring), m = 1.75 mm.
// The working centre distances come from libgear; both meshes must agree (coaxial) at 56.8 mm.
TEST(TrainCli, LjubljanaPlanetaryWithProfileShift) {
  const CliRun run = gearkit("train " + example("ljubljana_planetary.yaml") + " --format json");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto j = json_of(run);
  EXPECT_NEAR(1.0 / j["ratio"]["value"].get<double>(), 6.14286, 5e-6);
  bool coaxial = false;
  for (const auto& check : j["assembly"])
    if (check["condition"] == "coaxiality") {
      coaxial = check["checked"].get<bool>() && check["satisfied"].get<bool>();
      EXPECT_NE(check["detail"].get<std::string>().find("= 56.80"), std::string::npos) << check["detail"];
    }
  EXPECT_TRUE(coaxial);
  EXPECT_TRUE(j["warnings"].empty()) << j["warnings"];
}

// The coaxiality check takes the pressure angle from the file. Sun z = 20 (x = 0.3) with planet
// z = 16 (x = 0), m = 2 mm, alpha = 25 deg (ISO 21771): a_d = 2 (20 + 16)/2 = 36 mm,
// inv alpha_w = inv 25 deg + 2 tan 25 deg 0.3/36 -> alpha_w = 26.8803 deg,
// a = 36 cos 25 deg / cos alpha_w = 36.5794 mm (at 20 deg it would be 36.5679 mm).
TEST(TrainCli, CentreDistanceUsesTheFilesPressureAngle) {
  const std::string model =
      "members: [sun, carrier, {name: planet, carried_by: carrier}, ring]\n"
      "gears:\n  - {name: s, member: sun, z: 20, module: 2, x: 0.3}\n  - {name: p, member: planet, z: 16, module: 2}\n"
      "  - {name: r, member: ring, z: 52, type: internal, module: 2}\n"
      "meshes:\n  - {gears: [s, p], carrier: carrier}\n  - {gears: [p, r], carrier: carrier}\n"
      "analysis: {fix: [ring], input: sun = 100 rpm, output: carrier}\n";
  const CliRun run = gearkit("train " + write_yaml("alpha25.yaml", "pressure_angle: 25 deg\n" + model) + " --format json");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto j = json_of(run);
  std::string detail;
  for (const auto& check : j["assembly"])
    if (check["condition"] == "coaxiality") detail = check["detail"].get<std::string>();
  EXPECT_NE(detail.find("a(s-p) = 36.5794"), std::string::npos) << detail;
  // Without the key the documented default, 20 deg, applies.
  const CliRun standard = gearkit("train " + write_yaml("alpha20.yaml", model) + " --format json");
  ASSERT_EQ(standard.status, 0) << standard.err;
  EXPECT_NE(standard.out.find("a(s-p) = 36.5679"), std::string::npos) << standard.out;
}

// A helical planetary: m_n = 2 mm, beta = 15 deg, sun 20, planet 16, ring 52, no shift. The
// reference centre distance is a = m_n (z_s + z_p)/(2 cos beta) = 36/cos 15 deg = 37.2699 mm for
// both meshes (ISO 21771), not the spur value 36 mm. Sun right-hand, planet and ring left-hand.
TEST(TrainCli, HelicalPlanetaryCentreDistance) {
  const CliRun run = gearkit(
      "train " +
      write_yaml("helical.yaml",
                 "helix_angle: -15 deg\nmembers: [sun, carrier, {name: planet, carried_by: carrier, count: 3}, ring]\n"
                 "gears:\n  - {name: s, member: sun, z: 20, module: 2, helix_angle: 15 deg}\n"
                 "  - {name: p, member: planet, z: 16, module: 2}\n"
                 "  - {name: r, member: ring, z: 52, type: internal, module: 2}\n"
                 "meshes:\n  - {gears: [s, p], carrier: carrier}\n  - {gears: [p, r], carrier: carrier}\n"
                 "analysis: {fix: [ring], input: sun = 100 rpm, output: carrier}\n") +
      " --format json");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto j = json_of(run);
  bool coaxial = false;
  for (const auto& check : j["assembly"])
    if (check["condition"] == "coaxiality") {
      coaxial = check["checked"].get<bool>() && check["satisfied"].get<bool>();
      EXPECT_NE(check["detail"].get<std::string>().find("a(s-p) = 37.2699"), std::string::npos) << check["detail"];
    }
  EXPECT_TRUE(coaxial);
}

TEST(TrainCli, UnderDeterminedIsAWarning) {
  const CliRun run = gearkit("train " + example("simple_planetary.yaml") + " --input sun=100rpm --format json");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto j = json_of(run);
  ASSERT_FALSE(j["warnings"].empty());
  EXPECT_NE(j["warnings"][0].get<std::string>().find("'carrier'"), std::string::npos);
  const CliRun strict = gearkit("train " + example("simple_planetary.yaml") + " --input sun=100rpm --strict");
  EXPECT_EQ(strict.status, 3);
}

TEST(TrainCli, OverDeterminedNamesTheOption) {
  const CliRun run = gearkit("train " + example("simple_planetary.yaml") + " --fix ring --fix carrier --input sun=100rpm");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("option '--input'"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("over-determines"), std::string::npos) << run.err;
}

TEST(TrainCli, BadOptions) {
  const CliRun unknown = gearkit("train " + example("simple_planetary.yaml") + " --fix rign");
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("option '--fix'"), std::string::npos) << unknown.err;
  EXPECT_NE(unknown.err.find("'rign'"), std::string::npos) << unknown.err;
  const CliRun speed = gearkit("train " + example("simple_planetary.yaml") + " --input sun=fast");
  EXPECT_EQ(speed.status, 2);
  EXPECT_NE(speed.err.find("option '--input'"), std::string::npos) << speed.err;
  const CliRun ratio = gearkit("train synth reducer --m1 6 --m2 5 --ratio 1/0");
  EXPECT_EQ(ratio.status, 2);
  EXPECT_NE(ratio.err.find("option '--ratio'"), std::string::npos) << ratio.err;
  const CliRun missing = gearkit("train /nonexistent/train.yaml");
  EXPECT_EQ(missing.status, 2);
  const CliRun no_file = gearkit("train");
  EXPECT_EQ(no_file.status, 2);
  EXPECT_NE(no_file.err.find("expected the FILE argument, found none"), std::string::npos) << no_file.err;
  const CliRun modes = gearkit("train " + example("simple_planetary.yaml") + " --modes --input sun --input ring");
  EXPECT_EQ(modes.status, 2);
  EXPECT_NE(modes.err.find("option '--modes'"), std::string::npos) << modes.err;
}

// Bad models: each error names file:line:column and the culprit, exit status 2.
struct BadModel {
  const char* name;
  const char* yaml;
  const char* expected_place;  // "file.yaml:L:"
  const char* expected_words;
};

class TrainCliBadModel : public ::testing::TestWithParam<BadModel> {};

TEST_P(TrainCliBadModel, ReportsFileLineAndCulprit) {
  const BadModel& bad = GetParam();
  const CliRun run = gearkit("train " + write_yaml(bad.name, bad.yaml));
  EXPECT_EQ(run.status, 2) << run.out;
  EXPECT_NE(run.err.find(bad.expected_place), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(bad.expected_words), std::string::npos) << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
}

constexpr const char* planetary_head =
    "members: [sun, carrier, {name: planet, carried_by: carrier}, ring]\n";

INSTANTIATE_TEST_SUITE_P(
    Cases, TrainCliBadModel,
    ::testing::Values(
        BadModel{"same_member.yaml",
                 "members: [a]\ngears:\n  - {name: g1, member: a, z: 20}\n  - {name: g2, member: a, z: 30}\n"
                 "meshes:\n  - {gears: [g1, g2]}\n",
                 "same_member.yaml:6:", "both on member 'a'"},
        BadModel{"unknown_member.yaml",
                 "members: [a]\ngears:\n  - {name: g1, member: a, z: 20}\n  - {name: g2, member: b, z: 30}\n"
                 "meshes: []\n",
                 "unknown_member.yaml:4:", "unknown member 'b'"},
        BadModel{"zero_teeth.yaml", "members: [a]\ngears:\n  - {name: g1, member: a, z: 0}\nmeshes: []\n",
                 "zero_teeth.yaml:3:", "z > 0"},
        BadModel{"unknown_carrier.yaml",
                 "members: [sun, {name: planet, carried_by: arm}]\ngears: []\nmeshes: []\n",
                 "unknown_carrier.yaml:1:", "unknown member 'arm'"},
        BadModel{"unknown_mesh_carrier.yaml",
                 "members: [sun, planet]\ngears:\n  - {name: s, member: sun, z: 20}\n"
                 "  - {name: p, member: planet, z: 20}\nmeshes:\n  - {gears: [s, p], carrier: arm}\n",
                 "unknown_mesh_carrier.yaml:6:", "carrier 'arm' is not a member"},
        BadModel{"internal_internal.yaml",
                 "members: [sun, carrier, {name: planet, carried_by: carrier}, ring]\ngears:\n"
                 "  - {name: p, member: planet, z: 20, type: internal}\n"
                 "  - {name: r, member: ring, z: 60, type: internal}\nmeshes:\n  - {gears: [p, r], carrier: carrier}\n",
                 "internal_internal.yaml:6:", "both internal"},
        BadModel{"typo_key.yaml", "members: [a]\ngears:\n  - {name: g1, member: a, z: 20, modul: 2}\nmeshes: []\n",
                 "typo_key.yaml:3:", "unknown key 'modul'"},
        BadModel{"wrong_type.yaml", "members: [a]\ngears:\n  - {name: g1, member: a, z: twelve}\nmeshes: []\n",
                 "wrong_type.yaml:3:", "whole number"},
        BadModel{"mixed_pressure_angles.yaml",
                 "pressure_angle: 25 deg\nmembers: [a, b]\ngears:\n  - {name: g1, member: a, z: 20}\n"
                 "  - {name: g2, member: b, z: 30, pressure_angle: 20}\nmeshes:\n  - {gears: [g1, g2]}\n",
                 "mixed_pressure_angles.yaml:7:", "pressure angles 25 deg and 20 deg"},
        BadModel{"same_hand_external.yaml",
                 "members: [a, b]\ngears:\n  - {name: g1, member: a, z: 20, helix_angle: 15}\n"
                 "  - {name: g2, member: b, z: 30, helix_angle: 15}\nmeshes:\n  - {gears: [g1, g2]}\n",
                 "same_hand_external.yaml:6:", "opposite helix angles"},
        BadModel{"pressure_angle_range.yaml", "pressure_angle: 50 deg\nmembers: [a]\ngears:\n  - {name: g1, member: a, z: 20}\nmeshes: []\n",
                 "pressure_angle_range.yaml:1:", "pressure angle in (0, 45) deg"},
        BadModel{"bad_type_choice.yaml",
                 "members: [a]\ngears:\n  - {name: g1, member: a, z: 20, type: inner}\nmeshes: []\n",
                 "bad_type_choice.yaml:3:", "external, internal"}));

TEST(TrainCli, LockedLoopIsAWarningNamingTheMembers) {
  const CliRun run = gearkit("train " +
                          write_yaml("locked.yaml",
                                     "members: [a, b, c]\ngears:\n  - {name: ga, member: a, z: 20}\n"
                                     "  - {name: gb, member: b, z: 30}\n  - {name: gc, member: c, z: 40}\n"
                                     "meshes:\n  - {gears: [ga, gb]}\n  - {gears: [gb, gc]}\n  - {gears: [gc, ga]}\n") +
                          " --format json");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto j = json_of(run);
  EXPECT_EQ(j["dof"], 0);
  ASSERT_FALSE(j["warnings"].empty());
  EXPECT_NE(j["warnings"][0].get<std::string>().find("locked"), std::string::npos);
  EXPECT_EQ(j["locked_members"].size(), 3u);
}

TEST(TrainCli, AssemblyFailureIsAWarning) {
  // 25 + 61 = 86 teeth cannot be shared by 3 equally spaced planets.
  const CliRun run = gearkit("train " +
                          write_yaml("spacing.yaml", std::string(planetary_head).replace(
                                                         std::string(planetary_head).find("carrier}"), 8,
                                                         "carrier, count: 3}") +
                                                         "gears:\n  - {name: s, member: sun, z: 25}\n"
                                                         "  - {name: p, member: planet, z: 18}\n"
                                                         "  - {name: r, member: ring, z: 61, type: internal}\n"
                                                         "meshes:\n  - {gears: [s, p], carrier: carrier}\n"
                                                         "  - {gears: [p, r], carrier: carrier}\n") +
                          " --format json");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto j = json_of(run);
  bool found = false;
  for (const auto& w : j["warnings"]) found = found || w.get<std::string>().find("equal spacing") != std::string::npos;
  EXPECT_TRUE(found) << j["warnings"];
}

}  // namespace

namespace {
std::string model_file(const std::string& name, const std::string& text) {
  const fs::path p = scratch() / name;
  std::ofstream(p) << text;
  return "'" + p.string() + "'";
}
}  // namespace

// Issue 11 item 8: two planets on a carrier that mesh no central gear crashed the assembly check
// (exit 139). The train is analysed; the spacing is reported as not checked.
TEST(TrainCli, PlanetsMeshingNoCentralGearDoNotCrash) {
  const CliRun run = gearkit("train " + model_file("lonely_planets.yaml",
                                                    "members: [a, {name: p, carried_by: a, count: 2}]\n"
                                                    "gears: []\nmeshes: []\n"));
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("not checked: the planet meshes no central gear"), std::string::npos) << run.out;
}

// Issue 11 item 11: a torque can only be given where the train is driven, loaded, held or
// coupled (torques.hpp); on a planet of the Ravigneaux set every torque came out indeterminate
// with exit 0 and a mesh table saying "no relative motion".
TEST(TrainCli, TorqueOnAMemberNobodyActsOnIsRefused) {
  const CliRun run = gearkit("train " + example("ravigneaux.yaml") + " --power short=136kW");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("option '--power': expected a member the train is driven, loaded, held or coupled at "
                         "(ring, s1, s2), found 'short'"),
            std::string::npos)
      << run.err;
  const CliRun ok = gearkit("train " + example("ravigneaux.yaml") + " --torque ring=-100N*m");
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_EQ(ok.out.find("indeterminate"), std::string::npos) << ok.out;
}

// Issue 11 item 11: a train of nothing but the implicit ground was "locked" with exit 0.
TEST(TrainCli, AnEmptyTrainIsAnInputError) {
  const CliRun run = gearkit("train " + model_file("empty.yaml", "members: []\ngears: []\nmeshes: []\n"));
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("empty.yaml:1:10: 'members': expected at least one member, found none"), std::string::npos)
      << run.err;
}

// Issue 11 item 11: the Wolfrom train of examples/ driven backwards (ring2 in, sun out) with
// eta_0 = 0.9 in every mesh. With losses the sun would take power in as well: the train locks,
// which must be said, not shown as an "efficiency" of -1.74. Driven forwards it does not lock.
TEST(TrainCli, ABackDrivenWolfromTrainIsSelfLocking) {
  std::ifstream in(std::string(GEARKIT_SOURCE_DIR) + "/examples/trains/wolfrom.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string model = text.str();
  for (const std::string efficiency : {", efficiency: 0.98", ", efficiency: 0.99", ", efficiency: 0.99"})
    model.erase(model.find(efficiency), efficiency.size());
  model.replace(model.find("input: sun = 3000 rpm"), 21, "input: ring2 = 100 rpm");
  model.replace(model.find("output: ring2"), 13, "output: sun");
  const CliRun back = gearkit("train " + model_file("wolfrom_back.yaml", model) +
                              " --mesh-efficiency 0.9 --torque ring2=100N*m --format json");
  EXPECT_EQ(back.status, 0) << back.err;
  const auto j = nlohmann::json::parse(back.out);
  EXPECT_LE(j["torques"]["efficiency"].get<double>(), 0.0);
  bool warned = false;
  for (const auto& w : j["warnings"]) warned = warned || w.get<std::string>().rfind("self-locking:", 0) == 0;
  EXPECT_TRUE(warned) << j["warnings"];
  const CliRun forward = gearkit("train " + example("wolfrom.yaml") + " --torque sun=10N*m");
  EXPECT_EQ(forward.out.find("self-locking"), std::string::npos) << forward.out;
}

// Issue 11 item 9: with more than two degrees of freedom every mode leaves the train free; the
// 100-stage train tried 19,900 pairs that all said so. Now it is said once. Too many members to
// hold or couple is refused before any work.
TEST(TrainCli, ModesOfAFreeTrainAreSaidOnceAndTheirNumberIsBounded) {
  std::string free = "members: [a, b, c, d, e]\ngears:\n";
  for (const std::string m : {"a", "b", "c", "d", "e"}) free += "  - {name: g" + m + ", member: " + m + ", z: 20}\n";
  free += "meshes:\n  - {gears: [ga, gb]}\n";  // a-b geared; c, d, e free: 4 degrees of freedom
  const CliRun once = gearkit("train " + model_file("free.yaml", free) + " --input a=1rpm --output-member b --modes");
  EXPECT_EQ(once.status, 0) << once.err;
  EXPECT_NE(once.out.find("any member held or pair coupled  2 degree(s) of freedom left in every mode"),
            std::string::npos)
      << once.out;
  std::string chain = "members: [";
  for (int i = 0; i <= 42; ++i) chain += (i ? ", m" : "m") + std::to_string(i);
  chain += "]\ngears:\n";
  for (int i = 0; i <= 42; ++i) chain += "  - {name: g" + std::to_string(i) + ", member: m" + std::to_string(i) + ", z: 20}\n";
  chain += "meshes:\n";
  for (int i = 0; i < 42; ++i) chain += "  - {gears: [g" + std::to_string(i) + ", g" + std::to_string(i + 1) + "]}\n";
  const CliRun many = gearkit("train " + model_file("chain.yaml", chain) + " --input m0=1rpm --output-member m42 --modes");
  EXPECT_EQ(many.status, 2);
  EXPECT_NE(many.err.find("option '--modes': expected at most 40 members"), std::string::npos) << many.err;
}

// A chain of `stages` 21:20 meshes (members m0..mN, each with gears of 20 and 21 teeth), the
// train of issue 11 item A: exact speeds grow by 2.6 digits a stage, so the work grows with the
// square of the stages. Line numbers: "members:" is line 1, member k line k + 2.
std::string chain_of(int stages) {
  std::string t = "members:\n";
  for (int i = 0; i <= stages; ++i) t += "  - m" + std::to_string(i) + "\n";
  t += "gears:\n";
  for (int i = 0; i <= stages; ++i) {
    t += "  - {name: a" + std::to_string(i) + ", member: m" + std::to_string(i) + ", z: 20}\n";
    t += "  - {name: b" + std::to_string(i) + ", member: m" + std::to_string(i) + ", z: 21}\n";
  }
  t += "meshes:\n";
  for (int i = 0; i < stages; ++i) t += "  - {gears: [b" + std::to_string(i) + ", a" + std::to_string(i + 1) + "]}\n";
  return t + "analysis: {fix: [], input: m0 = 100 rpm, output: m" + std::to_string(stages) + "}\n";
}

TEST(TrainCli, TheEntriesOfATrainFileAreBounded) {
  // At the limit (2,000 meshes) the chain is solved: each external mesh turns the next member
  // at -21/20 of the speed of the one before (Willis), so w_m2 / w_m0 = (21/20)^2.
  const CliRun at = gearkit("train " + write_yaml("chain2000.yaml", chain_of(2000)) + " --format json");
  ASSERT_EQ(at.status, 0) << at.err;
  const auto speeds = nlohmann::json::parse(at.out)["speeds_per_input"];
  EXPECT_EQ(speeds["m1"], "-21/20");
  EXPECT_EQ(speeds["m2"], "441/400");
  // One mesh more: refused at the 2,001st mesh, line 1 + 2002 members + 1 + 4002 gears + 1 + 2001.
  const CliRun over = gearkit("train " + write_yaml("chain2001.yaml", chain_of(2001)));
  EXPECT_EQ(over.status, 2);
  EXPECT_NE(over.err.find("chain2001.yaml:8010:5: 'meshes': expected at most 2000 entries"), std::string::npos)
      << over.err;
  // Members and gears are bounded before the meshes are read (the 20,000-stage chain of the issue
  // took 26 s and 3.2 GB): the 4,001st member is refused.
  const CliRun members = gearkit("train " + write_yaml("chain5000.yaml", chain_of(5000)));
  EXPECT_EQ(members.status, 2);
  EXPECT_NE(members.err.find("chain5000.yaml:4002:5: 'members': expected at most 4000 entries"), std::string::npos)
      << members.err;
  std::string gears = "members: [a, b]\ngears:\n";
  for (int i = 0; i <= 8000; ++i) gears += "  - {name: g" + std::to_string(i) + ", member: a, z: 20}\n";
  const CliRun too_many_gears = gearkit("train " + write_yaml("gears.yaml", gears + "meshes: []\n"));
  EXPECT_EQ(too_many_gears.status, 2);
  EXPECT_NE(too_many_gears.err.find("gears.yaml:8003:5: 'gears': expected at most 8000 entries"), std::string::npos)
      << too_many_gears.err;
}

namespace {

int largest_tooth_count(const nlohmann::json& candidates) {
  int most = 0;
  for (const auto& c : candidates)
    for (const char* z : {"z1", "z2", "z3", "z4"}) most = std::max(most, c[z].get<int>());
  return most;
}

}  // namespace

// Issue 25: --z-max defaulted to max(150, --z-min) while its help said 150. The help states the
// rule, and the search follows it: alone, --z-min 160 searches 160 teeth only, so ratio 1 with
// equal modules is z1 = z2 = z3 = z4 = 160 (m (z1 + z2) = m (z3 + z4) holds); without it no
// candidate passes 150 teeth (ratio 1/100 = 15/150 * 15/150 needs them all).
TEST(TrainCli, SynthZMaxDefaultIsWhatTheHelpSays) {
  const CliRun help = gearkit("train synth --help");
  ASSERT_EQ(help.status, 0) << help.err;
  std::string words;  // the help wrapped into lines, read as one line
  for (char c : help.out)
    if (!std::isspace(static_cast<unsigned char>(c)) || (!words.empty() && words.back() != ' ')) words += std::isspace(static_cast<unsigned char>(c)) ? ' ' : c;
  EXPECT_NE(words.find("most teeth (default 150, or the --z-min value if that is larger)"), std::string::npos) << help.out;
  const CliRun high = gearkit("train synth reducer --m1 1 --m2 1 --ratio 1 --z-min 160 --format json");
  ASSERT_EQ(high.status, 0) << high.err;
  const auto j = json_of(high);
  ASSERT_EQ(j["candidates"].size(), 1u) << j;
  for (const char* z : {"z1", "z2", "z3", "z4"}) EXPECT_EQ(j["candidates"][0][z], 160) << z;
  const CliRun plain = gearkit("train synth reducer --m1 1 --m2 1 --ratio 1/100 --max-results 200 --format json");
  ASSERT_EQ(plain.status, 0) << plain.err;
  const auto p = json_of(plain);
  ASSERT_FALSE(p["candidates"].empty());
  EXPECT_EQ(largest_tooth_count(p["candidates"]), 150);
}

// Issue 25: a planet that meshes nothing said "not checked" in the assembly table and then
// "Warnings: none". The train is suspect: the report warns.
TEST(TrainCli, PlanetMeshingNoCentralGearIsAWarning) {
  const std::string model = model_file("lonely_planet_warning.yaml", "members: [a, {name: p, carried_by: a, count: 2}]\n"
                                                                     "gears: []\nmeshes: []\n");
  const CliRun text = gearkit("train " + model);
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_EQ(text.out.find("Warnings: none"), std::string::npos) << text.out;
  const CliRun json = gearkit("train " + model + " --format json");
  ASSERT_EQ(json.status, 0) << json.err;
  const auto w = json_of(json)["warnings"];
  ASSERT_EQ(w.size(), 1u) << w;
  EXPECT_EQ(w[0], "assembly of planet 'p' on carrier 'a' (equal spacing) not checked: the planet meshes no central gear");
  EXPECT_EQ(gearkit("train " + model + " --strict").status, 3);
}
