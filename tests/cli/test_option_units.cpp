// Units that cannot be misread (issue 25, section 1), end to end: a bare power, torque or speed in
// an option is refused in every command (`gear --power 7.5` was 7.5 kW, `train --power sun=7.5`
// 7.5 W), the same value with its unit gives the same load in both commands, and an abbreviated or
// misspelt option is refused with the nearest whole name instead of being guessed.
#include <run_gearkit.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>
#include <string>

using gearkit::testing::count_lines;
using gearkit::testing::run_gearkit;
using gearkit::testing::RunResult;

namespace {

const std::string kExamples = std::string(GEARKIT_SOURCE_DIR) + "/examples/";
const std::string kGear =
    "gear --z1 20 --z2 60 --module 3 --face-width 30 --quality 6 --material1 42CrMo4 --material2 42CrMo4 ";
const std::string kTrain = "train " + kExamples + "trains/simple_planetary.yaml --fix ring --output-member carrier ";

/// Status 2, one stderr line, nothing on stdout, and the line is exactly `reason`.
void expect_refused(const RunResult& r, const std::string& reason) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out.substr(0, 300);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err, "gearkit: " + reason + "\n");
}

}  // namespace

TEST(OptionUnits, ABarePowerIsRefusedInGearAndInTrain) {
  expect_refused(run_gearkit(kGear + "--power 7.5 --speed1 1450rpm"),
                 "option '--power': expected a power with its unit (7.5kW, 7500 W), found '7.5'");
  expect_refused(run_gearkit(kTrain + "--input sun=1450rpm --power sun=7.5"),
                 "option '--power': expected a power with its unit (7.5kW, 7500 W), found '7.5'");
}

TEST(OptionUnits, ABareTorqueOrSpeedIsRefusedInEveryCommand) {
  expect_refused(run_gearkit(kGear + "--torque1 40 --speed1 1450rpm"),
                 "option '--torque1': expected a torque with its unit (36.6 N*m, 0.5 kN*m), found '40'");
  expect_refused(run_gearkit(kGear + "--torque1 40N*m --speed1 1450"),
                 "option '--speed1': expected an angular velocity with its unit (1450rpm, 152 rad/s), found '1450'");
  expect_refused(run_gearkit("gear size --ratio 3 --torque1 40N*m --speed1 1450 --material1 C45 --material2 C45"),
                 "option '--speed1': expected an angular velocity with its unit (1450rpm, 152 rad/s), found '1450'");
  expect_refused(run_gearkit(kTrain + "--input sun=1450rpm --torque sun=40"),
                 "option '--torque': expected a torque with its unit (36.6 N*m, 0.5 kN*m), found '40'");
  expect_refused(run_gearkit(kTrain + "--input sun=1450"),
                 "option '--input': input speed of 'sun': expected an angular velocity with its unit (1450rpm, 152 rad/s), "
                 "found '1450'");
  expect_refused(run_gearkit("kin " + kExamples + "mechanisms/four_bar.yaml --sweep 0:360:10 --speed 60"),
                 "option '--speed': expected an angular velocity with its unit (1450rpm, 152 rad/s), found '60'");
  expect_refused(run_gearkit("cam " + kExamples + "cams/translating_roller_cycloidal.yaml --feed 300"),
                 "option '--feed': expected a velocity with its unit (200 mm/min, 0.5 m/s), found '300'");
}

// 7.5 kW at 1450 rpm: T = P / omega = 7500 W / (1450 * 2 pi / 60 rad/s) = 49.393 N*m (by hand).
// Both commands must turn the same typed power into that torque on the driven member.
TEST(OptionUnits, TheSamePowerWithItsUnitGivesTheSameLoadInGearAndTrain) {
  const double T = 7500.0 / (1450.0 * 2.0 * std::numbers::pi / 60.0);
  const RunResult gear = run_gearkit(kGear + "--power 7.5kW --speed1 1450rpm --format json");
  ASSERT_EQ(gear.status, 0) << gear.err;
  EXPECT_NEAR(nlohmann::json::parse(gear.out)["rating"]["T_1_Nm"].get<double>(), T, 1e-9 * T);
  const RunResult train = run_gearkit(kTrain + "--input sun=1450rpm --power sun=7.5kW --format json");
  ASSERT_EQ(train.status, 0) << train.err;
  EXPECT_NEAR(nlohmann::json::parse(train.out)["torques"]["ideal_Nm"]["sun"].get<double>(), T, 1e-9 * T);
  // 7500 W, 10.0576 hp (745.699872 W each) and 0.0075 MW are the same power.
  for (const std::string power : {"7500W", "0.0075MW"}) {
    const RunResult again = run_gearkit(kGear + "--power " + power + " --speed1 1450rpm --format json");
    ASSERT_EQ(again.status, 0) << again.err;
    EXPECT_NEAR(nlohmann::json::parse(again.out)["rating"]["T_1_Nm"].get<double>(), T, 1e-9 * T) << power;
  }
}

TEST(OptionUnits, AnAbbreviatedOptionIsRefusedWithTheWholeName) {
  const std::string pair = "gear --z1 20 --z2 60 ";
  expect_refused(run_gearkit(pair + "--modul 3"),
                 "option '--modul': expected an option listed by --help, found an unknown one; did you mean '--module'?");
  expect_refused(run_gearkit(pair + "--modlue 3"),
                 "option '--modlue': expected an option listed by --help, found an unknown one; did you mean '--module'?");
  expect_refused(run_gearkit(pair + "--module 3 --helix 12"),
                 "option '--helix': expected an option listed by --help, found an unknown one; did you mean '--helix-angle' or '--helix-modification'?");
  expect_refused(run_gearkit(pair + "--module 3 --frobnicate 12"),
                 "option '--frobnicate': expected an option listed by --help, found an unknown one");
  expect_refused(run_gearkit(kTrain + "--input sun=1450rpm --mesh-eff 0.9"),
                 "option '--mesh-eff': expected an option listed by --help, found an unknown one; did you mean "
                 "'--mesh-efficiency'?");
  // The global options too.
  const RunResult global = run_gearkit("--versoin");
  EXPECT_EQ(global.status, 2) << global.err;
  EXPECT_NE(global.err.find("did you mean '--version'? See 'gearkit --help'"), std::string::npos) << global.err;
}
