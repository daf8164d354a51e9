// `gearkit kin` sweeps streamed from the solver to the report (issue 13 item 1): the rows are
// the closed-form four-bar in every format, and a million positions run in constant memory.
#include <run_gearkit.hpp>

#include "mechanisms.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace {

using gearkit::kin::testing::four_bar_closed_form;
using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;

const std::string kFourBar = shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/four_bar.yaml");
constexpr double kDeg = M_PI / 180.0;
// examples/mechanisms/four_bar.yaml: Norton's crank-rocker, crank turning at 25 rad/s.
const gearkit::kin::testing::FourBarDims kDims{0.040, 0.120, 0.080, 0.100};
constexpr double kOmega2 = 25.0;

// theta4 and its rate from Norton's closed form; the rate by central differences of it.
std::pair<double, double> rocker(double theta2) {
  const double h = 1e-6;
  const double theta4 = four_bar_closed_form(kDims, theta2).second;
  const double d = (four_bar_closed_form(kDims, theta2 + h).second - four_bar_closed_form(kDims, theta2 - h).second) / (2 * h);
  return {theta4, d * kOmega2};
}

}  // namespace

TEST(KinStreaming, JsonRowsAreTheClosedForm) {
  const auto r = run_gearkit("kin " + kFourBar + " --sweep 0:360:0.5 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const auto& positions = j["positions"];
  ASSERT_EQ(positions.size(), 721u);
  for (std::size_t k = 0; k < positions.size(); k += 7) {
    const auto& p = positions[k];
    const double theta2 = p["input_deg"].get<double>() * kDeg;
    EXPECT_NEAR(p["input_deg"].get<double>(), 0.5 * static_cast<double>(k), 1e-9);
    const auto [theta4, omega4] = rocker(theta2);
    EXPECT_NEAR(std::remainder(p["outputs"]["theta4_deg"].get<double>() - theta4 / kDeg, 360.0), 0.0, 1e-7) << k;
    EXPECT_NEAR(p["qd"]["rocker.omega_rad_s"].get<double>(), omega4, 1e-5) << k;
    EXPECT_NEAR(p["outputs"]["theta4_rate_rad_s"].get<double>(), omega4, 1e-5) << k;
  }
  EXPECT_EQ(j["dof"], 1);
  // The one warning: the mechanism summary's least transmission angle, 26.38 deg at theta2 = 0 (360)
  // (closed form in KinSummary.FourBarTransmissionAngleExtremesAreTheClosedForm), below 40 deg.
  ASSERT_EQ(j["warnings"].size(), 1u) << j["warnings"];
  EXPECT_EQ(j["warnings"][0].get<std::string>().rfind("transmission angle down to 26.38 deg at theta2 = ", 0), 0u)
      << j["warnings"];
}

// The same sweep as CSV, Markdown and text: one row per position, the JSON's values to the
// printed precision.
TEST(KinStreaming, EveryFormatHasEveryRow) {
  const auto json = nlohmann::json::parse(run_gearkit("kin " + kFourBar + " --sweep 0:90:0.25 --format json").out);
  const auto csv = run_gearkit("kin " + kFourBar + " --sweep 0:90:0.25 --format csv");
  ASSERT_EQ(csv.status, 0) << csv.err;
  std::istringstream lines(csv.out);
  std::string line;
  // A CSV file is one table (the positions); its first line is the header.
  std::getline(lines, line);
  EXPECT_EQ(line.rfind("theta2 [deg],crank [deg],coupler [deg],rocker [deg],theta4 [deg]", 0), 0u) << line;
  for (std::size_t k = 0; k < 361; ++k) {
    ASSERT_TRUE(std::getline(lines, line)) << k;
    double input = 0, crank = 0, coupler = 0, rocker_deg = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf", &input, &crank, &coupler, &rocker_deg), 4) << line;
    EXPECT_NEAR(input, json["positions"][k]["input_deg"].get<double>(), 5e-5);
    EXPECT_NEAR(rocker_deg, json["positions"][k]["q"]["rocker.angle_deg"].get<double>(), 5e-5);
  }
  EXPECT_FALSE(std::getline(lines, line)) << "361 rows and nothing else: " << line;
  for (const char* format : {"md", "text"}) {
    const auto r = run_gearkit("kin " + kFourBar + " --sweep 0:90:0.25 --format " + format);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string last_row = std::string(format) == "md" ? "| 90.0000 |" : "\n  90.0000 ";
    EXPECT_NE(r.out.find(last_row), std::string::npos) << format;
  }
}

// Issue 13 acceptance: a million positions to standard output under a 1 GB address-space limit
// (the report used to hold 19-24 kB per position: 22 GB).
TEST(KinStreaming, AMillionPositionsRunInConstantMemory) {
#ifdef GEARKIT_SANITIZED
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: ulimit -v cannot apply";
#endif
  for (const char* format : {"csv", "json"}) {
    const auto r = run_gearkit("kin " + kFourBar + " --sweep 0:359.99964:0.00036 --format " + format, "ulimit -v 1000000;",
                               "/dev/null", "/dev/null");
    EXPECT_EQ(r.status, 0) << format << ": " << r.err;
    // A successful run prints only marked warnings (the CSV names the tables it left out).
    std::istringstream err(r.err);
    for (std::string line; std::getline(err, line);) EXPECT_EQ(line.rfind("gearkit: warning: ", 0), 0u) << line;
  }
}

// A bad equations: section is found before anything is printed, even in a sweep.
TEST(KinStreaming, NothingIsPrintedBeforeTheInputIsKnownGood) {
  const auto r = run_gearkit("kin " + kFourBar + " --sweep 0:360:1 --plot /nonexistent-folder/p.svg");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("option '--plot'"), std::string::npos) << r.err;
}
