// CLI tests of `gearkit cam` with a dynamics: section: the textbook problems through the model
// file, spring sizing, the flywheel handed over to `gearkit dyn`, groove and conjugate cams, the
// dynamics plot, and bad input.
#include "cam_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

namespace {

namespace fs = std::filesystem;
using gearkit::cam::testing::ezdxf_check;
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
  try {
    return nlohmann::json::parse(r.output);
  } catch (const nlohmann::json::exception&) {
    ADD_FAILURE() << r.output;
    return {};
  }
}

bool has_warning(const nlohmann::json& j, const std::string& fragment) {
  for (const auto& w : j["warnings"])
    if (w.get<std::string>().find(fragment) != std::string::npos) return true;
  return false;
}

// A Norton-style double-dwell problem: rise 10 mm in 90 deg, dwell 45 deg, fall 10 mm in 180 deg,
// dwell; 3-4-5; roller 12.5 mm, base 63.7 mm; m = 7.5 kg, c = 2.74 N s/m; 10 rad/s.
const std::string kDoubleDwell = R"(cam: {base_radius: 63.7 mm, speed: 10 rad/s}
follower: {type: translating, contact: roller, roller_radius: 12.5 mm}
motion:
  - {type: rise, from: 0 deg, to: 90 deg, law: 3-4-5, lift: 10 mm}
  - {type: dwell, from: 90 deg, to: 135 deg}
  - {type: return, from: 135 deg, to: 315 deg, law: 3-4-5}
  - {type: dwell, from: 315 deg, to: 360 deg}
)";

TEST(CamDynamicsCommand, DoubleDwellSpringOf100NPerMIsNotSatisfactory) {
  // Is a spring of 100 N/m with 10 N preload satisfactory? By hand (test_follower_dynamics.cpp)
  // the kinetostatic force Q falls to -6.47 N in the rise: no. The contact force is Q / cos(phi).
  const auto model = write_model("dd.yaml", kDoubleDwell + R"(dynamics:
  mass: 7.5 kg
  spring_rate: 100 N/m
  preload: 10 N
  damping: 2.74 N*s/m
)");
  const auto j = run_json(quoted(model));
  const auto& d = j["dynamics"];
  EXPECT_NEAR(d["contact_force_min_N"].get<double>(), -6.48, 0.02);
  EXPECT_LT(d["jump_speed_rpm"].get<double>(), 10 * 30 / pi);
  EXPECT_TRUE(has_warning(j, "the follower leaves the cam"));
  EXPECT_NEAR(d["spring_rate_N_per_mm"].get<double>(), 0.1, 1e-12);
  EXPECT_FALSE(d["spring_rate_sized"].get<bool>());
  EXPECT_GT(d["preload_needed_N"].get<double>(), 16.47);  // 10 N + 6.47 N at least
}

TEST(CamDynamicsCommand, SpringIsSizedWhenNotGivenAndHolds) {
  // Norton problem 15-12's eccentric (s = e (1 - cos theta), e = 20 mm, m = 1 kg, 200 rpm): with
  // no spring given the least-mean-force spring is k = m W^2 / 2, F_pl = F_min (hand derivation,
  // test_follower_dynamics.cpp); with zeta = 0.1 the damping follows the rate.
  const auto model = write_model("ecc.yaml", R"(cam: {base_radius: 30 mm, speed: 200 rpm}
follower: {type: translating, contact: flat_face}
motion:
  - {type: rise, from: 0 deg, to: 180 deg, law: simple_harmonic, lift: 40 mm}
  - {type: return, from: 180 deg, to: 360 deg, law: simple_harmonic}
dynamics:
  mass: 1 kg
  min_contact_force: 2 N
)");
  const auto j = run_json(quoted(model));
  const auto& d = j["dynamics"];
  const double W = 200 * pi / 30;
  EXPECT_NEAR(d["spring_rate_N_per_mm"].get<double>(), W * W / 2 / 1000, 1e-3 * W * W / 2 / 1000);
  EXPECT_NEAR(d["preload_N"].get<double>(), 2, 2e-3);
  EXPECT_TRUE(d["spring_rate_sized"].get<bool>() && d["preload_sized"].get<bool>());
  EXPECT_GE(d["contact_force_min_N"].get<double>(), 2 - 1e-6);
  EXPECT_FALSE(has_warning(j, "leaves the cam"));
  // Jump above the design speed: the sized spring holds up to 200 rpm exactly at the limit... and a
  // little beyond, since F_min = 2 N is the margin.
  EXPECT_GT(d["jump_speed_rpm"].get<double>(), 200);
}

TEST(CamDynamicsCommand, FlywheelHandedOverToGearkitDynMatchesTheTorqueCurve) {
  // --dyn writes the camshaft as a `gearkit dyn` model; its energy excursion must be the one of
  // the camshaft torque in the CSV (E = integral of (T_mean - T) dtheta, trapezoids at the same
  // 3600 angles), and its mean driving torque the report's mean torque.
  const auto model = write_model("fly.yaml", kDoubleDwell + R"(dynamics:
  mass: 7.5 kg
  damping: 2.74 N*s/m
  min_contact_force: 5 N
  fluctuation: 0.05
output: {samples: 3600}
)");
  const fs::path dyn = scratch_dir() / "fly_dyn.yaml", csv = scratch_dir() / "fly.csv";
  const auto cam = run_json(quoted(model) + " --dyn " + quoted(dyn) + " --csv " + quoted(csv));
  const auto r = run("'" + std::string(GEARKIT_EXE) + "' dyn " + quoted(dyn) + " --format json");
  ASSERT_EQ(r.status, 0) << r.errors;
  const auto flywheel = nlohmann::json::parse(r.output);
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::stringstream h(line); std::getline(h, line, ',');) names.push_back(line);
  const auto col = std::find(names.begin(), names.end(), "camshaft_torque_N_m") - names.begin();
  std::vector<double> torque;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string cell;
    for (long k = 0; k <= col; ++k) std::getline(row, cell, ',');
    torque.push_back(std::stod(cell));
  }
  ASSERT_EQ(torque.size(), 3600u);
  torque.push_back(torque.front());
  const double h = 2 * pi / 3600;
  double work = 0;
  for (std::size_t i = 0; i + 1 < torque.size(); ++i) work += 0.5 * (torque[i] + torque[i + 1]) * h;
  const double mean = work / (2 * pi);
  double E = 0, lo = 0, hi = 0;
  for (std::size_t i = 0; i + 1 < torque.size(); ++i) {
    E += (mean - 0.5 * (torque[i] + torque[i + 1])) * h;
    lo = std::min(lo, E), hi = std::max(hi, E);
  }
  EXPECT_NEAR(flywheel["energy_excursion_J"].get<double>(), hi - lo, 1e-3 * (hi - lo));
  EXPECT_NEAR(flywheel["mean_drive_torque_Nm"].get<double>(), cam["dynamics"]["camshaft_torque_mean_N_m"].get<double>(),
              1e-3 * std::abs(mean) + 1e-9);
  // I = dE / (delta w^2) with delta = 0.05 at 10 rad/s.
  EXPECT_NEAR(flywheel["inertia_total_kgm2"].get<double>(), (hi - lo) / (0.05 * 100), 1e-3 * (hi - lo) / 5);
}

TEST(CamDynamicsCommand, OscillatingFollowerWithTorsionSpringFlexibilityAndHertz) {
  const auto model = write_model("osc.yaml", R"(cam: {base_radius: 40 mm, speed: 300 rpm}
follower: {type: oscillating, contact: roller, roller_radius: 10 mm, pivot_distance: 130 mm, arm_length: 100 mm}
motion:
  - {type: dwell, from: 0 deg, to: 60 deg}
  - {type: rise, from: 60 deg, to: 150 deg, law: cycloidal, lift: 15 deg}
  - {type: dwell, from: 150 deg, to: 210 deg}
  - {type: return, from: 210 deg, to: 300 deg, law: simple_harmonic}
  - {type: dwell, from: 300 deg, to: 360 deg}
dynamics:
  inertia: 0.004 kg*m^2
  damping_ratio: 0.05
  min_contact_force: 20 N
  follower_stiffness: 5000 N*m/rad
  speed_sweep: {to: 1200 rpm, steps: 24}
contact: {width: 12 mm, allowable: 1500 MPa}
)");
  const fs::path plot = scratch_dir() / "osc_dyn.svg";
  const auto j = run_json(quoted(model) + " --dynamics-plot " + quoted(plot));
  const auto& d = j["dynamics"];
  for (const char* key : {"inertia_kg_m2", "spring_rate_N_m_per_rad", "preload_N_m", "damping_N_m_s_per_rad",
                          "hertz_stress_max_MPa", "roller_speed_max_rpm", "camshaft_torque_max_N_m", "speed_sweep"})
    EXPECT_TRUE(d.contains(key)) << key;
  EXPECT_GE(d["contact_force_min_N"].get<double>(), 20 - 1e-6);
  // The sweep's jump (bisection on the least margin) agrees with the closed-form jump speed.
  ASSERT_FALSE(d["speed_sweep_jump_rpm"].is_null());
  EXPECT_NEAR(d["speed_sweep_jump_rpm"].get<double>(), d["jump_speed_rpm"].get<double>(), 1e-6 * d["jump_speed_rpm"].get<double>());
  // The harmonic return's acceleration steps leave more residual vibration than the cycloidal rise.
  const auto& res = d["flexible"]["residual_vibration"];
  ASSERT_EQ(res.size(), 2u);
  EXPECT_GT(res[1]["amplitude_deg"].get<double>(), res[0]["amplitude_deg"].get<double>());
  std::ifstream svg(plot);
  const std::string text((std::istreambuf_iterator<char>(svg)), {});
  for (const char* s : {"contact force", "camshaft torque", "Hertz", "flexible follower"})
    EXPECT_NE(text.find(s), std::string::npos) << s;
}

TEST(CamDynamicsCommand, GrooveAndConjugateCamsReportBothSurfacesAndDrawBoth) {
  for (const std::string& type : {std::string("groove"), std::string("conjugate")}) {
    SCOPED_TRACE(type);
    const std::string second = type == "conjugate" ? ", second_roller: {distance: 130 mm}" : "";
    const auto model = write_model(type + ".yaml", "cam: {base_radius: 40 mm, speed: 600 rpm, type: " + type + "}\n" +
                                                       "follower: {type: translating, contact: roller, roller_radius: 10 mm" +
                                                       second + "}\n" + R"(motion:
  - {type: rise, from: 0 deg, to: 120 deg, law: cycloidal, lift: 20 mm}
  - {type: dwell, from: 120 deg, to: 180 deg}
  - {type: return, from: 180 deg, to: 300 deg}
  - {type: dwell, from: 300 deg, to: 360 deg}
dynamics: {mass: 2 kg, damping: 5 N*s/m}
)");
    const fs::path dxf = scratch_dir() / (type + ".dxf");
    const auto j = run_json(quoted(model) + " --dxf " + quoted(dxf) + " --cutter-radius 6");
    const std::string other = type == "groove" ? "outer_wall" : "conjugate_cam";
    ASSERT_TRUE(j.contains(other));
    EXPECT_LE(j[other]["profile_deviation_mm"].get<double>(), 1e-3);
    EXPECT_FALSE(j["dynamics"].contains("jump_speed_rpm"));  // form closure: no jump
    EXPECT_GT(j["dynamics"]["contact_force_other_max_N"].get<double>(), 0);
    EXPECT_FALSE(j["dynamics"]["wall_changes_deg"].empty());
    const auto check = ezdxf_check(dxf);
    ASSERT_FALSE(check.contains("read_error")) << check.dump();
    EXPECT_TRUE(check["audit_errors"].empty());
    for (const std::string& layer : type == "groove" ? std::vector<std::string>{"profile", "outer_wall", "tool_path", "outer_tool_path"}
                                                    : std::vector<std::string>{"profile", "conjugate_profile", "conjugate_pitch_curve"})
      EXPECT_TRUE(check["entities"].contains(layer)) << layer;
  }
}

void expect_error(const std::string& name, const std::string& text, const std::string& fragment, const std::string& extra = "") {
  const auto model = write_model(name, text);
  const auto r = run(gearkit() + quoted(model) + extra);
  EXPECT_EQ(r.status, 2) << name << ": " << r.errors;
  EXPECT_NE(r.errors.find(fragment), std::string::npos) << name << ": " << r.errors;
  EXPECT_TRUE(r.output.empty());
}

TEST(CamDynamicsCommand, BadDynamicsInputIsOneLineWithUnits) {
  const std::string head = kDoubleDwell;
  expect_error("samples.yaml", head + "dynamics: {mass: 1 kg, samples: 10}\n", "expected from 36 to 36000 samples, found 10");
  expect_error("steps.yaml", head + "dynamics: {mass: 1 kg, speed_sweep: {to: 100 rpm, steps: 5000}}\n",
               "expected from 1 to 1000 steps, found 5000");
  expect_error("mass.yaml", head + "dynamics: {mass: -1 kg}\n", "expected mass > 0 kg, found -1 kg");
  expect_error("both.yaml", head + "dynamics: {mass: 1 kg, damping: 1 N*s/m, damping_ratio: 0.1}\n",
               "expected damping or damping_ratio, not both");
  expect_error("nospeed.yaml", R"(cam: {base_radius: 40 mm}
follower: {type: translating, contact: roller, roller_radius: 10 mm}
motion:
  - {type: rise, from: 0 deg, to: 180 deg, lift: 10 mm}
  - {type: return, from: 180 deg, to: 360 deg}
dynamics: {mass: 1 kg}
)", "the dynamics needs a cam speed");
  expect_error("speed.yaml", head + "dynamics: {mass: 1 kg, design_speed: 2e7 rpm}\n", "up to 1e+06 rpm, found 2e+07 rpm");
  expect_error("knife.yaml", R"(cam: {base_radius: 40 mm, speed: 100 rpm}
follower: {type: translating, contact: knife_edge}
motion:
  - {type: rise, from: 0 deg, to: 180 deg, lift: 10 mm}
  - {type: return, from: 180 deg, to: 360 deg}
dynamics: {mass: 1 kg}
contact: {width: 10 mm}
)", "a knife edge has no Hertz contact");
  expect_error("nodyn.yaml", head + "contact: {width: 10 mm}\n", "add a dynamics: section");
  expect_error("dynopt.yaml", head, "expected a dynamics: section", " --dyn x.yaml");
  // On the base circle (a dwell: no inertia, pressure angle 0) the follower needs exactly the
  // least contact force, 5 N: both with their units.
  expect_error("preload.yaml", head + "dynamics: {mass: 7.5 kg, preload: 1 N, min_contact_force: 5 N}\n",
               "the preload 1 N is too small");
  expect_error("preload_need.yaml", head + "dynamics: {mass: 7.5 kg, preload: 1 N, min_contact_force: 5 N}\n",
               "the follower needs 5 N");
  expect_error("spring_torsion.yaml", R"(cam: {base_radius: 40 mm, speed: 100 rpm}
follower: {type: oscillating, contact: roller, roller_radius: 10 mm, pivot_distance: 130 mm, arm_length: 100 mm}
motion:
  - {type: rise, from: 0 deg, to: 180 deg, lift: 10 deg}
  - {type: return, from: 180 deg, to: 360 deg}
dynamics: {inertia: 0.01 kg*m^2, spring_rate: 20 N/mm}
)", "expected a torsional stiffness");
  expect_error("conj.yaml", R"(cam: {base_radius: 40 mm, type: conjugate}
follower: {type: translating, contact: roller, roller_radius: 10 mm}
motion:
  - {type: rise, from: 0 deg, to: 180 deg, lift: 10 mm}
  - {type: return, from: 180 deg, to: 360 deg}
)", "a conjugate cam needs follower.second_roller");
}

/// The conjugate example's cams and arm without damping: a loss-free follower train.
const std::string kLossFreeConjugate = R"(cam: {base_radius: 45 mm, type: conjugate, speed: 300 rpm}
follower:
  type: oscillating
  contact: roller
  roller_radius: 10 mm
  pivot_distance: 140 mm
  arm_length: 105 mm
  second_roller: {arm_length: 120 mm, arm_angle: -55 deg}
motion:
  - {type: rise, from: 0 deg, to: 120 deg, law: cycloidal, lift: 18 deg}
  - {type: dwell, from: 120 deg, to: 180 deg}
  - {type: return, from: 180 deg, to: 300 deg, law: cycloidal}
  - {type: dwell, from: 300 deg, to: 360 deg}
)";

TEST(CamDynamicsCommand, LossFreeCamHasNoMeanTorqueNotRoundOff) {
  // Issue 18: with no damping and no friction the camshaft returns every joule it gives (the
  // inertia torque I q'' q' omega^2 integrates to [I q'^2 omega^2 / 2] = 0 over the turn), but
  // the report printed -1.3652e-17 N*m and -4.2889e-16 W: round-off, now 0.
  const auto model = write_model("lossfree.yaml", kLossFreeConjugate + "dynamics: {inertia: 0.006 kg*m^2}\n");
  const auto j = run_json(quoted(model));
  EXPECT_EQ(j["dynamics"]["camshaft_torque_mean_N_m"].get<double>(), 0.0);
  EXPECT_EQ(j["dynamics"]["power_mean_W"].get<double>(), 0.0);
  EXPECT_EQ(j["dynamics"]["work_per_cycle_J"].get<double>(), 0.0);
  const std::string text = run(gearkit() + quoted(model)).output;
  const auto row = text.find("mean camshaft torque [N*m]");
  ASSERT_NE(row, std::string::npos) << text;
  std::istringstream cells(text.substr(row + 26, text.find('\n', row) - row - 26));
  std::string value;
  cells >> value;
  EXPECT_EQ(value, "0") << text;
}

TEST(CamDynamicsCommand, DampingRatioNeedsAStiffness) {
  // Issue 18: damping_ratio without a spring and without follower_stiffness gave zero damping
  // silently (c = 2 zeta sqrt(k M) with k = 0).
  expect_error("ratio.yaml", kLossFreeConjugate + "dynamics: {inertia: 0.006 kg*m^2, damping_ratio: 0.05}\n",
               "expected follower_stiffness (or a spring_rate > 0) with damping_ratio");
  // With the train's stiffness the ratio refers to it: c = 2 x 0.05 x sqrt(20000 x 0.006) = 1.0954 N*m*s/rad.
  const auto model = write_model("ratio_ok.yaml", kLossFreeConjugate +
                                                      "dynamics: {inertia: 0.006 kg*m^2, damping_ratio: 0.05, "
                                                      "follower_stiffness: 20000 N*m/rad}\n");
  const auto j = run_json(quoted(model));
  EXPECT_NEAR(j["dynamics"]["damping_N_m_s_per_rad"].get<double>(), 2 * 0.05 * std::sqrt(20000 * 0.006), 1e-9);
}

// Issue 25: a sized preload was printed as 3.2e-14 N where none is needed. The double-dwell cam
// undamped with no wanted contact force and 3000 N/m: by hand the follower asks the spring for
// -m q'' w^2 only where q'' < 0 (decelerating rise, accelerating return), and there q > 0 with
// sup(-m w^2 q''/q) = m w^2 max(-y''/y)/beta^2 = 7.5 * 100 * 6.2775 / (pi/2)^2 = 1908 N/m in the
// rise (max of -y''/y = 6.2775 at u = 0.79 for 3-4-5, by dense evaluation; the return, beta = pi,
// needs a quarter). 3000 N/m > 1908 N/m: k q exceeds the need wherever q > 0, and on the base
// circle the need is 0, so the least preload is exactly 0 (and the follower stays on the cam).
TEST(CamDynamicsCommand, NoPreloadNeededIsZeroNotRounding) {
  const auto model = write_model("nopreload.yaml", kDoubleDwell + "dynamics: {mass: 7.5 kg, min_contact_force: 0 N, "
                                                                  "spring_rate: 3000 N/m}\n");
  const auto j = run_json(quoted(model));
  EXPECT_EQ(j["dynamics"]["preload_N"].get<double>(), 0.0) << j["dynamics"];
  EXPECT_TRUE(j["dynamics"]["preload_sized"].get<bool>());
  EXPECT_FALSE(has_warning(j, "leaves the cam"));
  const auto text = run(gearkit() + quoted(model));
  ASSERT_EQ(text.status, 0) << text.errors;
  const auto row = text.output.find("preload [N]");
  ASSERT_NE(row, std::string::npos) << text.output;
  std::istringstream cells(text.output.substr(row + 11, text.output.find('\n', row) - row - 11));
  std::string value;
  cells >> value;
  EXPECT_EQ(value, "0") << text.output.substr(row, 80);
  // On the dwells the spring is unloaded, without preload, and nothing accelerates: the least
  // contact force is exactly 0 N by hand, shown as 0 rather than its rounding residue.
  EXPECT_EQ(j["dynamics"]["contact_force_min_N"].get<double>(), 0.0) << j["dynamics"];
  const auto least = text.output.find("least contact force [N]");
  ASSERT_NE(least, std::string::npos);
  const std::string least_row = text.output.substr(least, text.output.find('\n', least) - least);
  EXPECT_EQ(least_row.find("e-"), std::string::npos) << least_row;  // no 3.2e-14
  // Below the hand limit the rate alone does not hold, and a preload is needed.
  const auto soft = write_model("softpreload.yaml", kDoubleDwell + "dynamics: {mass: 7.5 kg, min_contact_force: 0 N, "
                                                                   "spring_rate: 1500 N/m}\n");
  EXPECT_GT(run_json(quoted(soft))["dynamics"]["preload_N"].get<double>(), 1.0);
}

// Issue 25: gearkit writes its models through yaml-cpp's emitter. A cam named with quotes, a
// colon, a hash, a backslash and non-ASCII letters (Nocke "A": 3-4-5 # \ Ü) hands over a
// `gearkit dyn` model that reads back, with the title as written.
TEST(CamDynamicsCommand, DynModelOfAnyCamNameReadsBack) {
  const auto model = write_model("named.yaml", "name: \"Nocke \\\"A\\\": 3-4-5 # \\\\ \xC3\x9C\"\n" + kDoubleDwell +
                                                   "dynamics: {mass: 7.5 kg, min_contact_force: 5 N}\n");
  const fs::path dyn = scratch_dir() / "named_dyn.yaml";
  const auto cam = run(gearkit() + quoted(model) + " --dyn " + quoted(dyn));
  ASSERT_EQ(cam.status, 0) << cam.errors;
  const auto r = run("'" + std::string(GEARKIT_EXE) + "' dyn " + quoted(dyn) + " --format json");
  ASSERT_EQ(r.status, 0) << r.errors;
  EXPECT_EQ(nlohmann::json::parse(r.output)["title"], "camshaft of Nocke \"A\": 3-4-5 # \\ \xC3\x9C") << r.output.substr(0, 300);
}

}  // namespace
