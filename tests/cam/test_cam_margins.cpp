// `gearkit cam` margins and forces (issue 32 item 4): the spring sized for a jump margin over the
// design speed, the follower's axial force beside the normal contact force, and the speed every
// plot is drawn at; against hand derivations from Norton's relations.
#include "cam_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

namespace {

namespace fs = std::filesystem;
using gearkit::cam::testing::gearkit;
using gearkit::cam::testing::quoted;
using gearkit::cam::testing::run;
using gearkit::cam::testing::scratch_dir;

constexpr double pi = std::numbers::pi;

fs::path write_model(const std::string& name, const std::string& text) {
  const fs::path p = scratch_dir() / name;
  std::ofstream(p) << text;
  return p;
}

nlohmann::json run_json(const std::string& args) {
  const auto r = run(gearkit() + args + " --format json");
  EXPECT_EQ(r.status, 0) << r.errors;
  return nlohmann::json::parse(r.output);
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

// The CSV as columns by name.
std::map<std::string, std::vector<double>> read_csv(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::stringstream h(line); std::getline(h, line, ',');) names.push_back(line);
  std::map<std::string, std::vector<double>> cols;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string cell;
    for (const std::string& n : names) {
      std::getline(row, cell, ',');
      cols[n].push_back(cell.empty() || cell == "inf" ? NAN : std::stod(cell));
    }
  }
  return cols;
}

// A radial (zero-offset) translating roller follower: cycloidal rise and return of L = 20 mm
// over beta = 120 deg each, 300 rpm.
const std::string kRadialRoller = R"(cam: {base_radius: 40 mm, speed: 300 rpm}
follower: {type: translating, contact: roller, roller_radius: 10 mm, offset: 0 mm}
motion:
  - {type: rise, from: 0 deg, to: 120 deg, law: cycloidal, lift: 20 mm}
  - {type: dwell, from: 120 deg, to: 180 deg}
  - {type: return, from: 180 deg, to: 300 deg, law: cycloidal, lift: 20 mm}
  - {type: dwell, from: 300 deg, to: 360 deg}
)";

// With the rate given as 0 and no damping, load or least force, the sized preload must hold
// Q = M s'' w^2 + F_0 >= 0 up to w = m omega (m the jump margin): F_0 = M (m omega)^2 max(-s''),
// and for a cycloidal rise s'' = (2 pi L / beta^2) sin(2 pi theta / beta) (Norton, Design of
// Machinery, eq. 8.15), so F_0 = 2 pi M L (m omega)^2 / beta^2. That spring lets go exactly at
// m omega (where the deceleration peaks, theta = 3 beta / 4 of the rise): the jump speed.
TEST(CamMargins, JumpMarginSizesTheSpringForThatSpeed) {
  const auto model = write_model("margin.yaml", kRadialRoller + R"(dynamics:
  mass: 1 kg
  spring_rate: 0 N/mm
  jump_margin: 1.3
)");
  const double M = 1, L = 0.020, beta = 120 * pi / 180, omega = 300 * pi / 30, m = 1.3;
  const double F0 = 2 * pi * M * L * (m * omega) * (m * omega) / (beta * beta);
  const auto j = run_json(quoted(model));
  const auto& d = j["dynamics"];
  EXPECT_TRUE(d["preload_sized"].get<bool>());
  EXPECT_NEAR(d["preload_N"].get<double>(), F0, 1e-6 * F0);
  EXPECT_EQ(d["jump_margin"].get<double>(), 1.3);
  EXPECT_NEAR(d["spring_sized_for_rpm"].get<double>(), 390.0, 1e-9);
  EXPECT_NEAR(d["jump_speed_rpm"].get<double>(), 390.0, 1e-3);
  EXPECT_NEAR(d["jump_speed_over_design_speed"].get<double>(), 1.3, 1e-5);
  // The option overrides the file; without either the spring holds to the design speed only.
  const auto opt = run_json(quoted(model) + " --jump-margin 1.5");
  EXPECT_NEAR(opt["dynamics"]["preload_N"].get<double>(), F0 * (1.5 / 1.3) * (1.5 / 1.3), 1e-6 * F0);
  EXPECT_NEAR(opt["dynamics"]["jump_speed_rpm"].get<double>(), 450.0, 1e-3);
  const auto plain = write_model("margin1.yaml", kRadialRoller + "dynamics: {mass: 1 kg, spring_rate: 0 N/mm}\n");
  EXPECT_NEAR(run_json(quoted(plain))["dynamics"]["jump_speed_rpm"].get<double>(), 300.0, 1e-3);
}

TEST(CamMargins, BadJumpMarginIsOneLine) {
  const auto model = write_model("bad_margin.yaml", kRadialRoller + "dynamics: {mass: 1 kg, jump_margin: 0.8}\n");
  auto r = run(gearkit() + quoted(model));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.errors.find("bad_margin.yaml:"), std::string::npos) << r.errors;
  EXPECT_NE(r.errors.find("expected a jump margin from 1 to 10"), std::string::npos) << r.errors;
  const auto good = write_model("good_margin.yaml", kRadialRoller + "dynamics: {mass: 1 kg}\n");
  for (const char* bad : {"0.5", "11", "nan", "x"}) {
    r = run(gearkit() + quoted(good) + " --jump-margin " + bad);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.errors.find("--jump-margin"), std::string::npos) << r.errors;
    EXPECT_EQ(std::count(r.errors.begin(), r.errors.end(), '\n'), 1) << r.errors;
  }
  const auto none = write_model("no_dynamics.yaml", kRadialRoller);
  r = run(gearkit() + quoted(none) + " --jump-margin 1.2");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.errors.find("expected a dynamics: section"), std::string::npos) << r.errors;
}

// Norton's force relations for a translating roller follower: the lumped model's cam force acts
// along the follower's axis, F_c = M s'' omega^2 + k s + F_0 (eq. 15.8, no damping or load), and
// the contact force along the common normal at pressure angle phi is F_n = F_c / cos phi, so
// F_c = F_n cos phi (sect. 8.5); for a radial follower phi = atan(s' / (R_p + s)), R_p = R_b + R_r
// (eq. 8.31 with no offset). Rebuilt here from the CSV's motion columns alone.
TEST(CamMargins, AxialForceIsNormalForceTimesCosPressureAngleByHand) {
  const auto model = write_model("axial.yaml", kRadialRoller + R"(dynamics:
  mass: 1.5 kg
  spring_rate: 2 N/mm
  preload: 40 N
)");
  const fs::path csv = scratch_dir() / "axial.csv", plot = scratch_dir() / "axial_dyn.svg";
  const auto j = run_json(quoted(model) + " --csv " + quoted(csv) + " --dynamics-plot " + quoted(plot));
  const double M = 1.5, k = 2000, F0 = 40, omega = 300 * pi / 30, Rp = 50;
  const auto c = read_csv(csv);
  ASSERT_TRUE(c.count("axial_force_N") && c.count("contact_force_N"));
  double largest = -INFINITY;
  for (std::size_t i = 0; i < c.at("s_mm").size(); ++i) {
    const double s = c.at("s_mm")[i], ds = c.at("ds_dtheta_mm")[i], d2s = c.at("d2s_dtheta2_mm")[i];
    const double Fc = M * d2s * 1e-3 * omega * omega + k * s * 1e-3 + F0;
    const double phi = std::atan(ds / (Rp + s));
    EXPECT_NEAR(c.at("axial_force_N")[i], Fc, 1e-6 * std::abs(Fc) + 1e-9) << i;
    EXPECT_NEAR(c.at("contact_force_N")[i], Fc / std::cos(phi), 1e-6 * std::abs(Fc / std::cos(phi)) + 1e-9) << i;
    largest = std::max(largest, Fc);
  }
  // The report's rows over the dynamics' own (finer) samples: at least the CSV's largest.
  EXPECT_GE(j["dynamics"]["axial_force_max_N"].get<double>(), largest - 1e-6);
  EXPECT_LE(j["dynamics"]["axial_force_max_N"].get<double>(), j["dynamics"]["contact_force_max_N"].get<double>() + 1e-9);
  const std::string svg = slurp(plot);
  EXPECT_NE(svg.find("axial force F_c"), std::string::npos);
  EXPECT_NE(svg.find("F_c = F_n cos phi"), std::string::npos);
  EXPECT_NE(svg.find("contact force F_n"), std::string::npos);
}

// Every plot states its speed: the s-v-a-j plot at cam.speed, the dynamics plot at the design
// speed, which may differ (issue 32).
TEST(CamMargins, EveryPlotStatesItsSpeed) {
  const auto model = write_model("speeds.yaml", kRadialRoller + "dynamics: {mass: 1 kg, design_speed: 600 rpm}\n");
  const fs::path motion = scratch_dir() / "speeds_motion.svg", dyn = scratch_dir() / "speeds_dyn.svg";
  run_json(quoted(model) + " --plot " + quoted(motion) + " --dynamics-plot " + quoted(dyn));
  EXPECT_NE(slurp(motion).find("Follower motion at cam speed 300 rpm"), std::string::npos);
  EXPECT_NE(slurp(dyn).find("Cam dynamics at the design speed 600 rpm (the s-v-a-j plot: cam speed 300 rpm)"), std::string::npos);
  std::string untimed = kRadialRoller;
  untimed.replace(untimed.find(", speed: 300 rpm"), std::string(", speed: 300 rpm").size(), "");
  const auto bare = write_model("untimed.yaml", untimed);
  run_json(quoted(bare) + " --plot " + quoted(motion));
  EXPECT_NE(slurp(motion).find("Follower motion per radian of cam angle (no cam speed given)"), std::string::npos);
}

}  // namespace
