// CLI tests of `gearkit cam` (the cam plugin): reports, exports checked by ezdxf against the
// computed profile, and bad input.
#include "cam_test_support.hpp"

#include <gtest/gtest.h>
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

namespace {

namespace fs = std::filesystem;
using gearkit::cam::testing::ezdxf_check;
using gearkit::cam::testing::gearkit;
using gearkit::cam::testing::quoted;
using gearkit::cam::testing::run;
using gearkit::cam::testing::scratch_dir;

fs::path example(const std::string& name) { return fs::path(GEARKIT_SOURCE_DIR) / "examples" / "cams" / name; }

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

fs::path write_model(const std::string& name, const std::string& text) {
  const fs::path p = scratch_dir() / name;
  std::ofstream(p) << text;
  return p;
}

TEST(CamCommand, Otm2015Problem2Report) {
  const auto j = run_json(quoted(example("otm2015_p2_oscillating_cycloidal.yaml")));
  for (const char* key : {"pressure_angle_max_deg", "pressure_angle_max_at_deg", "rho_min_mm", "rho_min_at_deg",
                          "undercut", "profile_points", "warnings"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_FALSE(j["undercut"].get<bool>());
  EXPECT_EQ(j["profile_points"].size(), 360u);
  // The exam's motion climbs 57.3 deg in 60 deg of cam: with any reasonable arm the pressure
  // angle exceeds the 45 deg limit, and the report says so.
  EXPECT_GT(std::abs(j["pressure_angle_max_deg"].get<double>()), 45);  // signed: the largest is on the return
  ASSERT_FALSE(j["warnings"].empty());
  EXPECT_NE(j["warnings"][0].get<std::string>().find("pressure angle"), std::string::npos);
}

TEST(CamCommand, Otm2015Problem2TableInTheCsv) {
  // Seed 000_bc94d104a9983772.txt, problem 2 b: psi = 1.65, 11.20, 28.65, 46.09, 55.64 deg at
  // theta = 130 ... 170 deg (every 10 deg), and the same values descending from 260 deg by 20 deg.
  const fs::path csv = scratch_dir() / "otm.csv";
  const auto r = run(gearkit() + quoted(example("otm2015_p2_oscillating_cycloidal.yaml")) + " --csv " + quoted(csv));
  ASSERT_EQ(r.status, 0) << r.errors;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("theta_deg,psi_deg,", 0), 0u) << line;
  std::map<int, double> psi;
  while (std::getline(in, line)) {
    const double theta = std::stod(line.substr(0, line.find(',')));
    const auto second = line.find(',') + 1;
    psi[static_cast<int>(std::lround(theta))] = std::stod(line.substr(second, line.find(',', second) - second));
  }
  const std::map<int, double> expected{{120, 0},     {130, 1.65},  {140, 11.20}, {150, 28.65}, {160, 46.09},
                                       {170, 55.64}, {180, 57.30}, {240, 57.30}, {260, 55.64}, {280, 46.09},
                                       {300, 28.65}, {320, 11.20}, {340, 1.65}};
  for (auto [theta, value] : expected) EXPECT_NEAR(psi.at(theta), value, 0.005) << theta;
}

TEST(CamCommand, EveryExampleExportsADxfThatEzdxfAcceptsWithTheComputedProfile) {
  for (const auto& entry : fs::directory_iterator(fs::path(GEARKIT_SOURCE_DIR) / "examples" / "cams")) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().filename().string());
    for (bool lines_arcs : {false, true}) {
      const std::string stem = entry.path().stem().string() + (lines_arcs ? "_la" : "");
      const fs::path dxf = scratch_dir() / (stem + ".dxf"), csv = scratch_dir() / (stem + ".csv");
      const auto r = run(gearkit() + quoted(entry.path()) + " --dxf " + quoted(dxf) + " --csv " + quoted(csv) +
                         " --cutter-radius 5" + (lines_arcs ? " --dxf-lines-arcs" : "") + " --format json");
      ASSERT_EQ(r.status, 0) << r.errors;
      const auto report = nlohmann::json::parse(r.output);
      // Where the profile is arcs, ezdxf must read back every analytic profile point (CSV, 360
      // per turn) within the fit tolerance, which is a bound (issue 18), not an estimate; a cusped
      // flat-face envelope is a polyline through 3600 points, whose chords leave the in-between
      // CSV points by up to their sag.
      const double tol = report["fit_tolerance_mm"].get<double>() + 1e-12;
      EXPECT_LE(report["profile_deviation_mm"].get<double>(), report["fit_tolerance_mm"].get<double>());
      const auto check = ezdxf_check(dxf, "--points " + quoted(csv) +
                                              " --x-column profile_x_mm --y-column profile_y_mm --layer profile"
                                              " --tol " + std::to_string(report["profile_arcs"].get<int>() >= 3600 ? 0.05 : tol));
      ASSERT_FALSE(check.contains("read_error")) << check.dump();
      EXPECT_TRUE(check["audit_errors"].empty()) << check.dump();
      EXPECT_EQ(check["dxfversion"], "AC1015");
      EXPECT_EQ(check["insunits"], 4);
      EXPECT_TRUE(check["ok"].get<bool>()) << check.dump();
      const auto& layers = check["entities"];
      EXPECT_TRUE(layers.contains("profile"));
      EXPECT_TRUE(layers.contains("base_circle"));
      if (lines_arcs) {
        for (const auto& [layer, counts] : layers.items()) EXPECT_FALSE(counts.contains("LWPOLYLINE")) << layer;
      } else {
        EXPECT_EQ(check["closed_polylines"]["profile"], 1);
        if (!report["undercut"].get<bool>()) {
          EXPECT_EQ(check["closed_polylines"]["tool_path"], 1);
        }
      }
    }
  }
}

TEST(CamCommand, SvgDrawingAndPlotAreWritten) {
  const fs::path svg = scratch_dir() / "cam.svg", plot = scratch_dir() / "plot.svg";
  fs::remove(svg);
  fs::remove(plot);
  const auto r = run(gearkit() + quoted(example("translating_roller_cycloidal.yaml")) + " --svg " + quoted(svg) +
                     " --plot " + quoted(plot) + " --follower-at 90");
  ASSERT_EQ(r.status, 0) << r.errors;
  std::ifstream a(svg), b(plot);
  const std::string drawing((std::istreambuf_iterator<char>(a)), {}), chart((std::istreambuf_iterator<char>(b)), {});
  for (const char* layer : {"layer-profile", "layer-pitch_curve", "layer-base_circle", "layer-follower"})
    EXPECT_NE(drawing.find(layer), std::string::npos) << layer;
  EXPECT_NE(chart.find("<svg"), std::string::npos);
  EXPECT_NE(chart.find("acceleration"), std::string::npos);
}

/// The error line of a run: the last line on stderr (the plugin host may warn before it about
/// unrelated plugins).
std::string last_line(const std::string& text) {
  std::string t = text;
  while (!t.empty() && t.back() == '\n') t.pop_back();
  const auto nl = t.rfind('\n');
  return nl == std::string::npos ? t : t.substr(nl + 1);
}

void expect_input_error(const std::string& args, const std::string& fragment) {
  const auto r = run(gearkit() + args);
  EXPECT_EQ(r.status, 2) << r.errors;
  EXPECT_NE(last_line(r.errors).find(fragment), std::string::npos) << r.errors;
  EXPECT_EQ(r.errors.find("terminate"), std::string::npos) << r.errors;
  EXPECT_TRUE(r.output.empty()) << r.output;
}

const std::string kHead = R"(cam: {base_radius: 40 mm}
follower: {type: translating, contact: roller, roller_radius: 10 mm}
)";

TEST(CamCommand, BadInputIsOneLineAndExitTwo) {
  const auto gap = write_model("gap.yaml", kHead + R"(motion:
  - {type: rise, from: 0 deg, to: 100 deg, lift: 10 mm}
  - {type: return, from: 110 deg, to: 360 deg}
)");
  expect_input_error(quoted(gap), "gap.yaml:5:5: segment starts at 110 deg but the previous one ends at 100 deg (a gap)");
  const auto overlap = write_model("overlap.yaml", kHead + R"(motion:
  - {type: rise, from: 0 deg, to: 100 deg, lift: 10 mm}
  - {type: return, from: 90 deg, to: 360 deg}
)");
  expect_input_error(quoted(overlap), "an overlap");
  const auto short_turn = write_model("short.yaml", kHead + R"(motion:
  - {type: rise, from: 0 deg, to: 100 deg, lift: 10 mm}
  - {type: return, from: 100 deg, to: 300 deg}
)");
  expect_input_error(quoted(short_turn), "must cover 360 deg, they cover 300 deg");
  const auto zero = write_model("zero.yaml", kHead + R"(motion:
  - {type: dwell, from: 0 deg, to: 100 deg}
  - {type: rise, from: 100 deg, to: 100 deg, lift: 10 mm}
  - {type: return, from: 100 deg, to: 360 deg}
)");
  expect_input_error(quoted(zero), "zero.yaml:5:5: expected a segment of positive duration");
  const auto negative = write_model("negative.yaml", R"(cam: {base_radius: 40 mm}
follower: {type: translating, contact: roller, roller_radius: -10 mm}
motion:
  - {type: rise, from: 0 deg, to: 180 deg, lift: 10 mm}
  - {type: return, from: 180 deg, to: 360 deg}
)");
  expect_input_error(quoted(negative), "negative.yaml:2:");
  const auto small_base = write_model("small_base.yaml", R"(cam: {base_radius: 8 mm}
follower: {type: translating, contact: roller, roller_radius: 10 mm}
motion:
  - {type: rise, from: 0 deg, to: 180 deg, lift: 10 mm}
  - {type: return, from: 180 deg, to: 360 deg}
)");
  expect_input_error(quoted(small_base), "small_base.yaml:1:20: 'base_radius': expected a base circle radius >= the roller radius");
  const auto reach = write_model("reach.yaml", R"(cam: {base_radius: 40 mm}
follower: {type: oscillating, contact: roller, roller_radius: 10 mm, pivot_distance: 300 mm, arm_length: 100 mm}
motion:
  - {type: rise, from: 0 deg, to: 180 deg, lift: 20 deg}
  - {type: return, from: 180 deg, to: 360 deg}
)");
  expect_input_error(quoted(reach), "the follower cannot reach the cam");
  const auto unknown = write_model("unknown.yaml", kHead + R"(motion:
  - {type: rise, from: 0 deg, to: 180 deg, lift: 10 mm, law: cycloid}
  - {type: return, from: 180 deg, to: 360 deg}
)");
  expect_input_error(quoted(unknown), "unknown.yaml:4:");
  const auto negative_lift = write_model("negative_lift.yaml", kHead + R"(motion:
  - {type: rise, from: 0 deg, to: 180 deg, lift: 10 mm}
  - {type: return, from: 180 deg, to: 360 deg, lift: -10 mm}
)");
  expect_input_error(quoted(negative_lift), "negative_lift.yaml:5:5: expected a lift > 0, found -10");
  expect_input_error(quoted(example("translating_roller_cycloidal.yaml")) + " --cutter-radius -3", "option '--cutter-radius'");
  expect_input_error(quoted(example("translating_roller_cycloidal.yaml")) + " --cutter-radius 3kg", "option '--cutter-radius'");
  expect_input_error(quoted(scratch_dir() / "missing.yaml"), "missing.yaml");
}

TEST(CamCommand, FailedExportLeavesNoFile) {
  const fs::path target = scratch_dir() / "no-such-dir" / "cam.dxf";
  const auto r = run(gearkit() + quoted(example("translating_roller_cycloidal.yaml")) + " --dxf " + quoted(target));
  EXPECT_EQ(r.status, 2) << r.errors;
  EXPECT_NE(last_line(r.errors).find("--dxf"), std::string::npos) << r.errors;
  EXPECT_FALSE(fs::exists(target));
}

}  // namespace

namespace {

TEST(CamCommand, MotionPeaksPerSecondMatchTheCycloidalFormulas) {
  // Cycloidal rise L = 20 mm over beta = 120 deg at 300 rpm (omega = 10 pi rad/s):
  // v_max = 2 L / beta * omega = 600 mm/s, a_max = 2 pi L / beta^2 * omega^2,
  // j_max = 4 pi^2 L / beta^3 * omega^3 (Norton table 8-3 factors 2, 2 pi, 4 pi^2).
  const auto j = run_json(gearkit::cam::testing::quoted(example("translating_roller_cycloidal.yaml")));
  const double pi = std::numbers::pi, L = 20, beta = 2 * pi / 3, w = 10 * pi;
  EXPECT_NEAR(j["v_max_mm_s"].get<double>(), 2 * L / beta * w, 1e-6);
  EXPECT_NEAR(j["a_max_mm_s2"].get<double>(), 2 * pi * L / (beta * beta) * w * w, 1e-3);
  EXPECT_NEAR(j["j_max_mm_s3"].get<double>(), 4 * pi * pi * L / (beta * beta * beta) * w * w * w, 1e-1);
  EXPECT_NEAR(j["velocity_max_per_rad"].get<double>(), 2 * L / beta, 1e-9);
}

TEST(CamCommand, StrictTurnsWarningsIntoExitThree) {
  const auto r = run(gearkit() + gearkit::cam::testing::quoted(example("otm2015_p2_oscillating_cycloidal.yaml")) +
                     " --strict");
  EXPECT_EQ(r.status, 3) << r.errors;
}

}  // namespace

namespace {

TEST(CamCommand, DxfReadBackMeetsTheToleranceAtTwentyThousandAngles) {
  // Issue 18: read back from the DXF, the translating flat-face cam (base 30) missed 1e-3 mm at
  // 1.026e-3 and the roller cam at 4e-5 mm gave 4.17e-5. ezdxf reads the file; every analytic
  // profile point (the CSV at 20000 cam angles) must lie within the stated tolerance.
  struct Case {
    std::string name, model;
    double tol;
  };
  const std::vector<Case> cases{
      {"flat30", R"(cam: {base_radius: 30 mm, rotation: cw}
follower: {type: translating, contact: flat_face}
motion:
  - {type: rise, from: 0 deg, to: 90 deg, law: 3-4-5, lift: 15 mm}
  - {type: dwell, from: 90 deg, to: 180 deg}
  - {type: return, from: 180 deg, to: 270 deg, law: 3-4-5}
  - {type: dwell, from: 270 deg, to: 360 deg}
output: {tolerance: 0.001 mm, samples: 20000}
)", 1e-3},
      {"roller4e-5", R"(cam: {base_radius: 40 mm}
follower: {type: translating, contact: roller, roller_radius: 10 mm}
motion:
  - {type: rise, from: 0 deg, to: 120 deg, law: cycloidal, lift: 20 mm}
  - {type: dwell, from: 120 deg, to: 180 deg}
  - {type: return, from: 180 deg, to: 300 deg, law: cycloidal}
  - {type: dwell, from: 300 deg, to: 360 deg}
output: {tolerance: 4e-5 mm, samples: 20000}
)", 4e-5}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const fs::path model = write_model(c.name + ".yaml", c.model);
    const fs::path dxf = scratch_dir() / (c.name + ".dxf"), csv = scratch_dir() / (c.name + ".csv");
    const auto r = run(gearkit() + quoted(model) + " --dxf " + quoted(dxf) + " --csv " + quoted(csv));
    ASSERT_EQ(r.status, 0) << r.errors;
    const auto check = ezdxf_check(dxf, "--points " + quoted(csv) +
                                            " --x-column profile_x_mm --y-column profile_y_mm --layer profile --tol " +
                                            fmt::format("{:.17g}", c.tol));
    ASSERT_FALSE(check.contains("read_error")) << check.dump();
    EXPECT_LE(check["max_deviation_mm"].get<double>(), c.tol) << check.dump();
  }
}

}  // namespace

namespace {

TEST(CamCommand, BadValuesOfIssue18AreRefusedWithUnits) {
  const std::string motion = R"(motion:
  - {type: rise, from: 0 deg, to: 180 deg, lift: 10 mm}
  - {type: return, from: 180 deg, to: 360 deg}
)";
  const auto speed = write_model("speed.yaml", "cam: {base_radius: 40 mm, speed: -60 rpm}\n"
                                               "follower: {type: translating, contact: roller, roller_radius: 10 mm}\n" + motion);
  expect_input_error(quoted(speed), "speed.yaml:1:34: expected a cam speed > 0 rpm (the sense of rotation is cam.rotation), found -60 rpm");
  const auto limit = write_model("limit.yaml", "cam: {base_radius: 40 mm, pressure_angle_limit: 95 deg}\n"
                                               "follower: {type: translating, contact: roller, roller_radius: 10 mm}\n" + motion);
  expect_input_error(quoted(limit), "expected a pressure angle limit between 0 and 90 deg, found 95 deg");
  const auto huge = write_model("huge.yaml", "cam: {base_radius: 1e6 mm}\n"
                                             "follower: {type: translating, contact: roller, roller_radius: 10 mm}\n" + motion);
  expect_input_error(quoted(huge), "huge.yaml:1:20: expected a length of at most 10000 mm, found 1e+06 mm");
  // Beyond the range of every length (docs/units.md) the quantity reader refuses it first.
  const auto absurd = write_model("absurd.yaml", "cam: {base_radius: 1e300 mm}\n"
                                                 "follower: {type: translating, contact: roller, roller_radius: 10 mm}\n" + motion);
  expect_input_error(quoted(absurd), "absurd.yaml:1:20: 'base_radius': expected a length of size 0 or between");
  const auto tol = write_model("tol.yaml", kHead + motion + "output: {tolerance: 1e-7 mm}\n");
  expect_input_error(quoted(tol), "expected a fit tolerance from 1e-6 mm to 1 mm, found 1e-07 mm");
  const auto below = write_model("below.yaml", kHead + R"(motion:
  - {type: rise, from: 0 deg, to: 180 deg, lift: 5 mm}
  - {type: return, from: 180 deg, to: 360 deg, lift: 10 mm}
)");
  expect_input_error(quoted(below), "the return goes 5 mm below the base circle");
  const auto dip = write_model("dip.yaml", kHead + R"(motion:
  - type: table
    from: 0 deg
    to: 120 deg
    interpolation: cubic
    points: [[0 deg, 0 mm], [20 deg, 0 mm], [40 deg, 0 mm], [50 deg, 20 mm], [120 deg, 20 mm]]
  - {type: return, from: 120 deg, to: 360 deg}
)");
  expect_input_error(quoted(dip), "the cubic spline through the table dips to s = -4.6");
}

TEST(CamCommand, JsonNumbersCarryNoConversionNoise) {
  const auto j = run_json(quoted(example("translating_flat_345.yaml")));
  // 30 deg read in radians and written back in degrees stays 30.
  EXPECT_EQ(j["pressure_angle_limit_deg"].dump(), "30.0");
  EXPECT_EQ(j["base_radius_mm"].dump(), "30.0");
}

TEST(CamCommand, PivotInsideTheCamsSweepIsAWarning) {
  // Issue 18: the OTM example's first dimensions (pivot 120, arm 100, base 40 mm) made a cam that
  // reaches 134.3 mm and sweeps through its own pivot at 120 mm: a warning.
  std::string yaml;
  {
    std::ifstream in(example("otm2015_p2_oscillating_cycloidal.yaml"));
    yaml.assign(std::istreambuf_iterator<char>(in), {});
  }
  for (auto [from, to] : {std::pair{"base_radius: 75 mm", "base_radius: 40 mm"}, {"pivot_distance: 170 mm", "pivot_distance: 120 mm"},
                          {"arm_length: 90 mm", "arm_length: 100 mm"}, {"  pivot_radius: 10 mm\n", ""}}) {
    ASSERT_NE(yaml.find(from), std::string::npos) << from;
    yaml.replace(yaml.find(from), std::string(from).size(), to);
  }
  const auto j = run_json(quoted(write_model("otm_clash.yaml", yaml)));
  EXPECT_NEAR(j["radius_max_mm"].get<double>(), 134.3, 0.05);
  EXPECT_LT(j["pivot_clearance_mm"].get<double>(), 0);
  bool warned = false;
  for (const auto& w : j["warnings"]) warned = warned || w.get<std::string>().find("strike the pivot") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(CamCommand, ShippedOtmExampleClearsItsPivot) {
  // Issue 18: a shipped example must not clash. Its dimensions (chosen, not in the seed): pivot
  // a = 170, arm L = 90, roller 10, base 75 mm (prime radius 85), boss 10 mm. Law of cosines:
  // cos(gamma_0) = (a^2 + L^2 - 85^2) / (2 a L); at the top dwell (psi = 1 rad) the roller centre
  // is at R^2 = a^2 + L^2 - 2 a L cos(gamma_0 + 1) from the cam centre, and the cam's largest
  // radius is R - 10 mm there (the dwell's profile is a circle about the centre).
  const double a = 170, L = 90, gamma0 = std::acos((a * a + L * L - 85.0 * 85) / (2 * a * L));
  const double reach = std::sqrt(a * a + L * L - 2 * a * L * std::cos(gamma0 + 1)) - 10;
  const auto j = run_json(quoted(example("otm2015_p2_oscillating_cycloidal.yaml")));
  EXPECT_NEAR(j["radius_max_mm"].get<double>(), reach, 1e-6);
  EXPECT_NEAR(j["pivot_clearance_mm"].get<double>(), a - 10 - reach, 1e-6);
  EXPECT_GT(j["pivot_clearance_mm"].get<double>(), 5);
  for (const auto& w : j["warnings"]) EXPECT_EQ(w.get<std::string>().find("pivot"), std::string::npos) << w;
}

TEST(CamCommand, PolynomialAndBsplineSegmentsFromTheModelFile) {
  // The 3-4-5 rise written as a polynomial from its boundary conditions: the same peaks as the
  // named law (a_max = 5.7735 L / beta^2, Norton table 8-3), and a B-spline table is smooth.
  const auto poly = write_model("poly.yaml", kHead + R"(motion:
  - {type: polynomial, from: 0 deg, to: 90 deg, start: {s: 0 mm, v: 0, a: 0}, end: {s: 15 mm, v: 0, a: 0}}
  - {type: dwell, from: 90 deg, to: 180 deg}
  - type: table
    from: 180 deg
    to: 300 deg
    interpolation: bspline
    points: [[180 deg, 15 mm], [220 deg, 12 mm], [260 deg, 3 mm], [300 deg, 0 mm]]
  - {type: dwell, from: 300 deg, to: 360 deg}
)");
  const fs::path csv = scratch_dir() / "poly.csv";
  const auto j = run_json(quoted(poly) + " --csv " + quoted(csv));
  for (const auto& w : j["warnings"]) EXPECT_EQ(w.get<std::string>().find("jumps"), std::string::npos) << w;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  double a_max = 0;
  while (std::getline(in, line)) {
    std::vector<double> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(std::stod(cell));
    if (cells[0] <= 90) a_max = std::max(a_max, cells[3]);  // d2s_dtheta2_mm
  }
  const double beta = std::numbers::pi / 2;
  EXPECT_NEAR(a_max, 5.773502691896 * 15 / (beta * beta), 2e-3);  // sampled at 1 deg: the peak within 2e-3
}

}  // namespace

namespace {

/// The benchmark cam (examples/cams/translating_roller_cycloidal.yaml) with a uniform-velocity
/// rise: ds/dtheta jumps from 0 to 20 mm / (120 deg) = 9.5493 mm/rad at 0 deg and back at 120 deg.
const std::string kUniformRise = R"(cam: {base_radius: 40 mm, speed: 300 rpm}
follower: {type: translating, contact: roller, roller_radius: 10 mm}
motion:
  - {type: rise, from: 0 deg, to: 120 deg, law: uniform_velocity, lift: 20 mm}
  - {type: dwell, from: 120 deg, to: 180 deg}
  - {type: return, from: 180 deg, to: 300 deg, law: cycloidal, lift: 20 mm}
  - {type: dwell, from: 300 deg, to: 360 deg}
output: {tolerance: 0.001 mm, cutter_radius: 8 mm}
)";

bool has_warning(const nlohmann::json& j, const std::string& fragment) {
  for (const auto& w : j["warnings"])
    if (w.get<std::string>().find(fragment) != std::string::npos) return true;
  return false;
}

TEST(CamCommand, RollerWithAVelocityJumpIsAReportWithItsCorners) {
  // Issue 18: the roller version exited 2 ("cannot fit arcs ... near cam angle 180 deg") while the
  // knife-edge and flat-face versions warn. The pitch curve has corners: on the prime circle
  // (50 mm) the tangent turns by atan(9.5493 / 50) = 10.81 deg away from the cam at 0 deg, at
  // the top (70 mm) by atan(9.5493 / 70) = 7.77 deg towards it at 120 deg (hand derivation).
  const fs::path model = write_model("uniform_rise.yaml", kUniformRise);
  const fs::path dxf = scratch_dir() / "uniform_rise.dxf", csv = scratch_dir() / "uniform_rise.csv";
  const auto j = run_json(quoted(model) + " --dxf " + quoted(dxf) + " --csv " + quoted(csv));
  EXPECT_TRUE(has_warning(j, "velocity jumps at cam angle 0.00 deg: 0 before, 9.5493 after (mm/rad); the pitch curve "
                             "turns 10.81 deg away from the cam"))
      << j["warnings"].dump();
  EXPECT_TRUE(has_warning(j, "velocity jumps at cam angle 120.00 deg: 9.5493 before, 0 after (mm/rad); the pitch curve "
                             "turns 7.77 deg towards the cam"))
      << j["warnings"].dump();
  EXPECT_LE(j["profile_deviation_mm"].get<double>(), 1e-3);
  // Read back, the profile passes through every analytic contact point within the tolerance,
  // except those the roller cannot reach at the convex corner: there the two sides' offsets
  // cross R_r tan(7.77 / 2 deg) = 0.68 mm before their ends, 0.56 deg of cam on the 70 mm circle.
  std::ifstream in(csv);
  const fs::path kept = scratch_dir() / "uniform_rise_kept.csv";
  std::ofstream out(kept);
  std::string line;
  std::getline(in, line);
  out << line << "\n";
  while (std::getline(in, line))
    if (std::abs(std::stod(line.substr(0, line.find(','))) - 120) > 0.6) out << line << "\n";
  out.close();
  const auto check = ezdxf_check(dxf, "--points " + quoted(kept) +
                                          " --x-column profile_x_mm --y-column profile_y_mm --layer profile --tol 0.001");
  ASSERT_FALSE(check.contains("read_error")) << check.dump();
  EXPECT_LE(check["max_deviation_mm"].get<double>(), 1e-3) << check.dump();
  EXPECT_EQ(check["closed_polylines"]["profile"], 1);
}

TEST(CamCommand, CuspedFlatFaceReportsTheDeviationOfWhatItExports) {
  // Issue 18: with cusps the flat-face envelope is exported as straight segments; the report said
  // profile_deviation_mm 0 while the DXF read back missed the envelope by 3.39e-5 mm (chord sag).
  const fs::path model = write_model("cusped.yaml", R"(cam: {base_radius: 10.7 mm, rotation: cw}
follower: {type: translating, contact: flat_face}
motion:
  - {type: rise, from: 0 deg, to: 90 deg, law: 3-4-5, lift: 15 mm}
  - {type: dwell, from: 90 deg, to: 180 deg}
  - {type: return, from: 180 deg, to: 270 deg, law: 3-4-5}
  - {type: dwell, from: 270 deg, to: 360 deg}
output: {tolerance: 0.0001 mm, samples: 20000}
)");
  const fs::path dxf = scratch_dir() / "cusped.dxf", csv = scratch_dir() / "cusped.csv";
  const auto j = run_json(quoted(model) + " --dxf " + quoted(dxf) + " --csv " + quoted(csv));
  EXPECT_TRUE(has_warning(j, "exported as straight segments"));
  const double reported = j["profile_deviation_mm"].get<double>();
  EXPECT_GT(reported, 0);
  EXPECT_LE(reported, 1e-4);
  const auto check = ezdxf_check(dxf, "--points " + quoted(csv) +
                                          " --x-column profile_x_mm --y-column profile_y_mm --layer profile --tol 0.0001");
  ASSERT_FALSE(check.contains("read_error")) << check.dump();
  EXPECT_LE(check["max_deviation_mm"].get<double>(), reported + 1e-9) << check.dump();
}

TEST(CamCommand, JerkJumpsAreInTheJson) {
  // Issue 18: the jerk-jump notes were in the text only. The 3-4-5 law's jerk at its ends is
  // 60 L / beta^3 = 60 x 15 / (pi/2)^3 = 232.211 mm/rad^3 (Norton, Design of Machinery, eq. 8.24).
  const auto j = run_json(quoted(example("translating_flat_345.yaml")));
  ASSERT_TRUE(j["jerk_jumps"].is_array());
  ASSERT_EQ(j["jerk_jumps"].size(), 4u);
  const double jump = 60 * 15 / std::pow(std::numbers::pi / 2, 3);
  std::map<int, std::pair<double, double>> at;
  for (const auto& k : j["jerk_jumps"])
    at[static_cast<int>(std::lround(k["at_deg"].get<double>()))] = {k["before_mm_per_rad3"].get<double>(),
                                                                     k["after_mm_per_rad3"].get<double>()};
  EXPECT_NEAR(at.at(0).second, jump, 1e-6);
  EXPECT_NEAR(at.at(90).first, jump, 1e-6);
  EXPECT_NEAR(at.at(180).second, -jump, 1e-6);
  EXPECT_NEAR(at.at(270).first, -jump, 1e-6);
}

TEST(CamCommand, JumpMessagesCarryTheirUnits) {
  // Issue 18: "(per rad^2)" said neither mm nor deg.
  const auto j = run_json(quoted(example("offset_knife_table.yaml")));
  bool acceleration = false;
  for (const auto& w : j["warnings"]) {
    const std::string text = w.get<std::string>();
    if (text.rfind("acceleration jumps at cam angle", 0) == 0) acceleration = text.find(" after (mm/rad^2)") != std::string::npos;
  }
  EXPECT_TRUE(acceleration) << j["warnings"].dump();
  EXPECT_TRUE(has_warning(j, "mm/rad^2): use interpolation: bspline")) << j["warnings"].dump();
}

}  // namespace
