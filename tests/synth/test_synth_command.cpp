// `gearkit synth` through the executable (plugins/synth): every example task, the mechanism file
// it writes analysed by `gearkit kin` at the precision positions (closing the loop through the
// real executable), the drawing and chart files, reproducibility and bad input.
#include <run_gearkit.hpp>

#include <gearkit/mechanism/reader.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

using gearkit::testing::count_lines;
using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;
namespace fs = std::filesystem;

namespace {

std::string example(const std::string& name) {
  return shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/examples/synthesis/" + name);
}

const fs::path& scratch() {
  static const fs::path dir = gearkit::testing::scratch_dir("synth");
  return dir;
}

nlohmann::json synth_json(const std::string& args) {
  const auto r = run_gearkit("synth " + args + " --format json");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  return nlohmann::json::parse(r.out);
}

// `gearkit kin FILE --at DEG` and the value of one output.
double kin_output(const fs::path& file, double at_deg, const std::string& key) {
  const auto r = run_gearkit("kin " + shell_quote(file.string()) + " --at " + std::to_string(at_deg) + "deg --format json");
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(r.out)["positions"][0]["outputs"][key].get<double>();
}

void expect_bad_input(const gearkit::testing::RunResult& r, const std::string& part) {
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("gearkit: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

fs::path write_task(const std::string& name, const std::string& text) {
  const fs::path p = scratch() / name;
  std::ofstream(p) << text;
  return p;
}


// `gearkit kin FILE ARGS --format json`, parsed.
nlohmann::json kin_json(const fs::path& file, const std::string& args) {
  const auto r = run_gearkit("kin " + shell_quote(file.string()) + " " + args + " --format json");
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

std::string exact_deg(double deg) {
  std::ostringstream o;
  o << std::setprecision(17) << deg << "deg";
  return o.str();
}

// Every output of `gearkit kin FILE --at DEG` (full precision).
nlohmann::json kin_at(const fs::path& file, double deg) {
  return kin_json(file, "--at " + exact_deg(deg))["positions"][0]["outputs"];
}

// The driver's sweep [start, end] in deg as the synthesis wrote it ("theta2 sweeps from pose 1 to
// the last"): it says which way the crank turns through the positions.
std::pair<double, double> driver_range(const fs::path& file) {
  // Plain text search: GCC 12's <regex> warns (maybe-uninitialized) under the sanitizers.
  const std::string text = gearkit::testing::slurp(file);
  const std::string key = "range: [";
  const auto at = text.find(key);
  EXPECT_NE(at, std::string::npos) << text;
  if (at == std::string::npos) return {0.0, 0.0};
  std::size_t used = 0;
  const double start = std::stod(text.substr(at + key.size()), &used);
  const auto comma = text.find(',', at + key.size() + used);
  return {start, std::stod(text.substr(comma + 1))};
}

// The crank angle t reached from `from`, turning the way the file's sweep goes.
double turning(const std::pair<double, double>& range, double t) {
  const double dir = range.second >= range.first ? 1 : -1;
  return range.first + dir * std::fmod(std::fmod(dir * (t - range.first), 360.0) + 360.0, 360.0);
}

double angle_between(double a_deg, double b_deg) { return std::remainder(a_deg - b_deg, 360.0); }

// Motion generation closed through kin: at each position's crank angle the coupler point P is the
// pose's point and the coupler has turned by the pose's change of angle from pose 1.
void expect_kin_reaches_poses(const fs::path& mech, const nlohmann::json& synth, const std::vector<std::array<double, 3>>& poses) {
  const auto range = driver_range(mech);
  const auto& pos = synth["positions"];
  ASSERT_EQ(pos.size(), poses.size());
  double theta3_first = 0;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const auto o = kin_at(mech, turning(range, pos[i]["theta2_deg"].get<double>()));
    EXPECT_NEAR(o["Px_mm"].get<double>(), poses[i][0], 1e-5) << i;
    EXPECT_NEAR(o["Py_mm"].get<double>(), poses[i][1], 1e-5) << i;
    if (i == 0) theta3_first = o["theta3_deg"].get<double>();
    EXPECT_NEAR(angle_between(o["theta3_deg"].get<double>() - theta3_first, poses[i][2] - poses[0][2]), 0, 1e-6) << i;
  }
}
}  // namespace

TEST(SynthCommand, ThreePositionMechanismIsAnalysedByKinAtEveryPosition) {
  const fs::path out = scratch() / "three.yaml";
  const auto j = synth_json("motion " + example("three_positions.yaml") + " --mechanism " + shell_quote(out.string()));
  EXPECT_EQ(j["defects"].size(), 0u);
  EXPECT_LT(j["solver_check_max_miss_mm"].get<double>(), 1e-5);
  // The task's poses: C at (0, 0), (50, 60), (110, 80) mm; the driver sweeps from pose 1.
  const double t1 = j["positions"][0]["theta2_deg"], t2 = j["positions"][1]["theta2_deg"], t3 = j["positions"][2]["theta2_deg"];
  const double dir = std::remainder(t2 - t1, 360.0) > 0 ? 1 : -1;
  const auto reach = [&](double t) { return t1 + dir * std::fmod(std::fmod(dir * (t - t1), 360.0) + 360.0, 360.0); };
  EXPECT_NEAR(kin_output(out, t1, "Px_mm"), 0, 1e-5);
  EXPECT_NEAR(kin_output(out, reach(t2), "Px_mm"), 50, 1e-5);
  EXPECT_NEAR(kin_output(out, reach(t2), "Py_mm"), 60, 1e-5);
  EXPECT_NEAR(kin_output(out, reach(t3), "Px_mm"), 110, 1e-5);
  EXPECT_NEAR(kin_output(out, reach(t3), "Py_mm"), 80, 1e-5);
}

TEST(SynthCommand, EveryExampleRunsAndChecksItselfWithTheSolver) {
  for (const char* task : {"function function_log10.yaml", "function function_slider.yaml", "motion two_positions.yaml",
                           "motion four_positions.yaml", "motion five_positions.yaml", "crank-rocker crank_rocker.yaml",
                           "dwell dwell.yaml"}) {
    const std::string s(task);
    const auto space = s.find(' ');
    const auto j = synth_json(s.substr(0, space) + " " + example(s.substr(space + 1)));
    ASSERT_TRUE(j.contains("solver_check_max_miss_mm")) << task;
    EXPECT_LT(j["solver_check_max_miss_mm"].get<double>(), 1e-5) << task;
    EXPECT_LT(j["solver_check_max_miss_deg"].get<double>(), 1e-6) << task;
  }
}

TEST(SynthCommand, FilesAreWrittenAndTheChartShowsTheStructuralError) {
  const fs::path mech = scratch() / "log.yaml", svg = scratch() / "log.svg", dxf = scratch() / "log.dxf", plot = scratch() / "log-plot.svg";
  const auto r = run_gearkit("synth function " + example("function_log10.yaml") + " -m " + shell_quote(mech.string()) +
                             " --drawing " + shell_quote(svg.string()) + " --plot " + shell_quote(plot.string()));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(gearkit::testing::slurp(mech).find("type: revolute"), std::string::npos);
  EXPECT_NE(gearkit::testing::slurp(svg).find("<svg"), std::string::npos);
  EXPECT_NE(gearkit::testing::slurp(plot).find("structural error"), std::string::npos);
  EXPECT_EQ(run_gearkit("synth function " + example("function_log10.yaml") + " --drawing " + shell_quote(dxf.string())).status, 0);
  EXPECT_NE(gearkit::testing::slurp(dxf).find("AC1015"), std::string::npos);
  EXPECT_NE(r.out.find("Largest structural error"), std::string::npos);
}

TEST(SynthCommand, PathIsReproducibleWithItsSeed) {
  const std::string args = "path " + example("path_ellipse.yaml") + " --evaluations 20000 --restarts 4 --seed 7";
  const auto a = synth_json(args), b = synth_json(args);
  EXPECT_EQ(a["linkage"], b["linkage"]);
  EXPECT_EQ(a["seed"], 7);
  EXPECT_GT(a["tracking_error_mm2"].get<double>(), 0);
  EXPECT_EQ(a["targets"].size(), 10u);
}

TEST(SynthCommand, BadInputIsOneLine) {
  expect_bad_input(run_gearkit("synth teleport " + example("dwell.yaml")), "expected a synthesis task");
  expect_bad_input(run_gearkit("synth path " + example("path_ellipse.yaml") + " --evaluations 5"), "--evaluations");
  expect_bad_input(run_gearkit("synth path " + example("path_ellipse.yaml") + " --restarts 0"), "--restarts");
  expect_bad_input(run_gearkit("synth path " + example("path_ellipse.yaml") + " --seed -3"), "--seed");
  const fs::path typo = write_task("typo.yaml", "swing: 45 deg\ntime_ratio: 1.25\nrockr: 100 mm\n");
  expect_bad_input(run_gearkit("synth crank-rocker " + shell_quote(typo.string())), "typo.yaml:3:1");
  const fs::path formula = write_task("formula.yaml", "function: log10(x\nx: [1, 2]\ninput: [90, 60]\noutput: [225, 60]\n");
  expect_bad_input(run_gearkit("synth function " + shell_quote(formula.string())), "expected a formula in x");
  const fs::path one = write_task("one.yaml", "positions:\n  - {point: [0, 0], angle: 0}\n");
  expect_bad_input(run_gearkit("synth motion " + shell_quote(one.string())), "expected 2 to 5 positions");
  const fs::path toggle = write_task("toggle.yaml", "function: log10(x)\nx: [1, 10]\ninput: [45 deg, 60 deg]\noutput: [135 deg, 60 deg]\n");
  expect_bad_input(run_gearkit("synth function " + shell_quote(toggle.string())), "cannot run over the whole x range");
  const fs::path far = write_task("far.yaml", "swing: 45 deg\ntime_ratio: 1.25\nrocker: 100 mm\nground: 1 mm\n");
  expect_bad_input(run_gearkit("synth crank-rocker " + shell_quote(far.string())), "no Grashof crank-rocker");
  expect_bad_input(run_gearkit("synth dwell " + example("dwell.yaml") + " --mechanism /nonexistent-dir/x.yaml"), "--mechanism");
}

// Issue 26, section 3: a task value out of the synthesis's range named only the file. Each is now
// refused at its value's line and column (docs/synthesis.md gives the ranges: 1 <= Q < 10, a swing
// under 180 deg, a dwell of 5 to 180 deg, 72 to 7200 samples).
TEST(SynthCommand, TaskValuesOutOfRangeSayWhere) {
  const fs::path q = write_task("q12.yaml", "swing: 45 deg\ntime_ratio: 12\nrocker: 100 mm\n");
  expect_bad_input(run_gearkit("synth crank-rocker " + shell_quote(q.string())),
                   "q12.yaml:2:13: 'time_ratio': expected a time ratio Q with 1 <= Q < 10, found 12");
  const fs::path slow = write_task("q09.yaml", "swing: 45 deg\ntime_ratio: 0.9\nrocker: 100 mm\n");
  expect_bad_input(run_gearkit("synth crank-rocker " + shell_quote(slow.string())), "q09.yaml:2:13: 'time_ratio'");
  const fs::path swing = write_task("swing.yaml", "rocker: 100 mm\nswing: 200 deg\n");
  expect_bad_input(run_gearkit("synth crank-rocker " + shell_quote(swing.string())),
                   "swing.yaml:2:8: 'swing': expected a rocker swing between 0 and 180 deg, found 200.000 deg");
  const fs::path dwell = write_task("dwell4.yaml", "four_bar: {ground: 100 mm, crank: 30 mm, coupler: 100 mm, rocker: 90 mm, "
                                                   "coupler_point: [60 mm, 45 mm]}\ndwell: 4 deg\n");
  expect_bad_input(run_gearkit("synth dwell " + shell_quote(dwell.string())), "dwell4.yaml:2:8: 'dwell': expected a dwell");
  const fs::path samples = write_task("samples.yaml", "four_bar: {ground: 100 mm, crank: 30 mm, coupler: 100 mm, rocker: 90 mm, "
                                                      "coupler_point: [60 mm, 45 mm]}\nsamples: 10\n");
  expect_bad_input(run_gearkit("synth dwell " + shell_quote(samples.string())),
                   "samples.yaml:2:10: 'samples': expected 72 to 7200 samples, found 10");
}

TEST(SynthCommand, JsonNumbersCarryNoConversionNoise) {
  // Issue 19: the target 17.66 mm came back as 17.660000000000004 after mm -> m -> mm; values are
  // written to 12 significant digits, as the cam command writes them.
  const auto r = run_gearkit("synth path " + example("path_ellipse.yaml") + " --evaluations 20000 --restarts 2 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.find("17.660000000000004"), std::string::npos);
  EXPECT_EQ(r.out.find("000000000"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("999999999"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["targets"][1]["target_mm"][0].dump(), "17.66");
}

TEST(SynthCommand, GrashofLineIsInMillimetres) {
  // Issue 19: the Grashof line said "s + l = 0.153677 m" in a report in mm. Here s + l is the
  // shortest plus the longest link and p + q the other two (Norton, Design of Machinery, eq. 2.8),
  // from the report's own link lengths in mm.
  const auto j = synth_json("function " + example("function_log10.yaml"));
  const auto& k = j["linkage"];
  std::vector<double> links{k["ground_mm"].get<double>(), k["crank_mm"].get<double>(), k["coupler_mm"].get<double>(),
                            k["rocker_mm"].get<double>()};
  std::sort(links.begin(), links.end());
  const std::string text = j["grashof"].get<std::string>();
  const auto sl = text.find("s + l = "), pq = text.find("p + q = ");
  ASSERT_NE(sl, std::string::npos) << text;
  ASSERT_NE(pq, std::string::npos) << text;
  EXPECT_NEAR(std::stod(text.substr(sl + 8)), links[0] + links[3], 1e-3) << text;
  EXPECT_NEAR(std::stod(text.substr(pq + 8)), links[1] + links[2], 1e-3) << text;
  EXPECT_EQ(text.substr(text.find(' ', sl + 8), 4), " mm ") << text;
  EXPECT_EQ(text.substr(text.find(' ', pq + 8), 3), " mm") << text;
}

// ---- Every synthesis mode closed through the executables: synth writes the mechanism, `gearkit
// kin` analyses that file, and the task is checked from kin's own output (issue 19, acceptance 2).

constexpr double kPi = std::numbers::pi;

// Chebyshev spacing of n precision points over [xs, xf] (Hartenberg & Denavit, Kinematic Synthesis
// of Linkages, 1964; docs/synthesis.md): x_j = (xs + xf)/2 - (xf - xs)/2 cos((2j - 1) pi / (2n)).
double chebyshev(double xs, double xf, int j, int n) {
  return (xs + xf) / 2 - (xf - xs) / 2 * std::cos((2 * j - 1) * kPi / (2 * n));
}

TEST(SynthCommand, Log10GeneratorPassesThePrecisionPointsInKin) {
  // The task: theta2 = 90 + 60 (x - 1) deg, theta4 = 225 + 60 log10(x) / log10(2) deg, x in [1, 2]
  // (the rocker may point the other way, +180 deg, docs/synthesis.md). kin's theta4 must give
  // y = log10(x) exactly at the three Chebyshev points, and its largest departure from log10 over
  // the range (201 positions, the synthesis's own error samples) must be the reported one.
  const fs::path mech = scratch() / "log10_loop.yaml";
  const auto j = synth_json("function " + example("function_log10.yaml") + " -m " + shell_quote(mech.string()));
  const double lg2 = std::log10(2.0);
  const auto y_of = [&](double theta4) { return std::remainder(theta4 - 225, 180.0) / 60 * lg2; };
  for (int k = 1; k <= 3; ++k) {
    const double x = chebyshev(1, 2, k, 3);
    EXPECT_NEAR(y_of(kin_at(mech, 90 + 60 * (x - 1))["theta4_deg"].get<double>()), std::log10(x), 1e-9) << x;
  }
  const auto sweep = kin_json(mech, "--sweep 90:150:0.3")["positions"];
  ASSERT_EQ(sweep.size(), 201u);
  double worst = 0;
  for (const auto& p : sweep) {
    const double x = 1 + (p["input_deg"].get<double>() - 90) / 60;
    worst = std::max(worst, std::abs(y_of(p["outputs"]["theta4_deg"].get<double>()) - std::log10(x)));
  }
  EXPECT_NEAR(worst, j["structural_error"]["max_abs"].get<double>(), 1e-8);
  EXPECT_LT(worst, 0.0011);  // 0.34 % of the range: the three-point generator's known accuracy
}

TEST(SynthCommand, SliderCrankGeneratorsPassTheirPointsInKin) {
  // y = x^2 over [0, 1] on theta2 = 30 + 120 x deg, s = 80 - 60 y mm. With three precision points
  // kin's slider must be there exactly; the least-squares example's largest error over the range
  // (201 kin positions) must be the one the synthesis reports.
  const fs::path task = write_task("slider3.yaml",
                                   "generator: slider-crank\nfunction: x^2\nx: [0, 1]\ninput: [30 deg, 120 deg]\n"
                                   "output: [80 mm, -60 mm]\n");
  const fs::path three = scratch() / "slider3_mech.yaml", lsq = scratch() / "slider_lsq_mech.yaml";
  synth_json("function " + shell_quote(task.string()) + " -m " + shell_quote(three.string()));
  for (int k = 1; k <= 3; ++k) {
    const double x = chebyshev(0, 1, k, 3);
    EXPECT_NEAR(kin_at(three, 30 + 120 * x)["s_mm"].get<double>(), 80 - 60 * x * x, 1e-6) << x;
  }
  const auto j = synth_json("function " + example("function_slider.yaml") + " -m " + shell_quote(lsq.string()));
  const auto sweep = kin_json(lsq, "--sweep 30:150:0.6")["positions"];
  ASSERT_EQ(sweep.size(), 201u);
  double worst = 0;
  for (const auto& p : sweep) {
    const double x = (p["input_deg"].get<double>() - 30) / 120;
    worst = std::max(worst, std::abs((80 - p["outputs"]["s_mm"].get<double>()) / 60 - x * x));
  }
  EXPECT_NEAR(worst, j["structural_error"]["max_abs"].get<double>(), 1e-8);
}

TEST(SynthCommand, TwoThreeFourAndFivePoseMechanismsReachTheirPosesInKin) {
  // The poses of the example tasks, as written there: point P and the coupler's angle (two and
  // three positions give C and D: P = C, the angle that of C D).
  const auto cd = [](double cx, double cy, double dx, double dy) {
    return std::array<double, 3>{cx, cy, std::atan2(dy - cy, dx - cx) * 180 / kPi};
  };
  const std::vector<std::array<double, 3>> burmester{{78.673705, 70.607532, 22.409015},
                                                     {67.482928, 82.026368, 18.376018},
                                                     {47.057694, 87.807671, 18.887903},
                                                     {24.424175, 84.905245, 21.964284},
                                                     {4.959355, 74.146196, 27.254698}};
  const std::vector<std::pair<std::string, std::vector<std::array<double, 3>>>> cases{
      {"two_positions.yaml", {cd(0, 0, 80, 0), cd(60, 40, 110, 102)}},
      {"three_positions.yaml", {cd(0, 0, 60, 20), cd(50, 60, 110, 62), cd(110, 80, 160, 50)}},
      {"four_positions.yaml", {burmester.begin(), burmester.begin() + 4}},
      {"five_positions.yaml", burmester}};
  for (const auto& [file, poses] : cases) {
    SCOPED_TRACE(file);
    const fs::path mech = scratch() / ("loop_" + file);
    const auto j = synth_json("motion " + example(file) + " -m " + shell_quote(mech.string()));
    EXPECT_EQ(j["defects"].size(), 0u);
    expect_kin_reaches_poses(mech, j, poses);
  }
}

TEST(SynthCommand, PathLinkageMeetsItsReportedPointsInKin) {
  // At each target's crank angle kin's coupler point is the reported reached point; its distances
  // to the targets are the reported ones, their largest the reported maximum and the sum of their
  // squares the tracking error E = sum |C_j - T_j|^2 (docs/synthesis.md).
  const fs::path mech = scratch() / "path_loop.yaml";
  const auto j = synth_json("path " + example("path_ellipse.yaml") + " --evaluations 20000 --restarts 4 -m " +
                            shell_quote(mech.string()));
  const auto range = driver_range(mech);
  double sum = 0, worst = 0;
  for (const auto& t : j["targets"]) {
    const auto o = kin_at(mech, turning(range, t["theta2_deg"].get<double>()));
    const double d = std::hypot(o["Px_mm"].get<double>() - t["target_mm"][0].get<double>(),
                                o["Py_mm"].get<double>() - t["target_mm"][1].get<double>());
    EXPECT_NEAR(o["Px_mm"].get<double>(), t["reached_mm"][0].get<double>(), 1e-6);
    EXPECT_NEAR(o["Py_mm"].get<double>(), t["reached_mm"][1].get<double>(), 1e-6);
    EXPECT_NEAR(d, t["distance_mm"].get<double>(), 1e-6);
    sum += d * d, worst = std::max(worst, d);
  }
  EXPECT_NEAR(worst, j["max_distance_mm"].get<double>(), 1e-6);
  EXPECT_NEAR(sum, j["tracking_error_mm2"].get<double>(), 1e-6 * std::max(1.0, sum));
}

TEST(SynthCommand, QuickReturnSwingAndTimeRatioFromKinsLimitPositions) {
  // Norton's quick return (45 deg swing, time ratio 1:1.25): kin finds the rocker's limit
  // positions itself; between them the crank turns 200 and 160 deg, 1.25 : 1.
  const fs::path mech = scratch() / "quick_loop.yaml";
  synth_json("crank-rocker " + example("crank_rocker.yaml") + " -m " + shell_quote(mech.string()));
  const auto lim = kin_json(mech, "--sweep 0:360:1")["limit_positions"];
  std::vector<std::pair<double, double>> rocker;  // (crank deg, rocker deg)
  for (const auto& l : lim)
    if (l["output"] == "theta4") rocker.emplace_back(l["input_deg"].get<double>(), l["value_deg"].get<double>());
  ASSERT_EQ(rocker.size(), 2u) << lim.dump();
  EXPECT_NEAR(std::abs(rocker[0].second - rocker[1].second), 45, 1e-6);
  const double stroke = std::fmod(std::abs(rocker[1].first - rocker[0].first), 360.0);
  EXPECT_NEAR(std::max(stroke, 360 - stroke) / std::min(stroke, 360 - stroke), 1.25, 1e-6);
}

TEST(SynthCommand, DwellOutputRestsInKinWhileTheCouplerPointRunsOnTheArc) {
  // Over the dwell window the coupler point stays on the arc about D (within the reported arc
  // deviation) and the output rocker theta6 moves by no more than the reported dwell motion; over
  // the whole turn it swings by the reported swing.
  const fs::path mech = scratch() / "dwell_loop.yaml";
  const auto j = synth_json("dwell " + example("dwell.yaml") + " -m " + shell_quote(mech.string()));
  const auto& w = j["dwell"];
  const double start = w["window_start_deg"], width = w["window_deg"], R = w["radius_mm"];
  const double Dx = w["D_mm"][0], Dy = w["D_mm"][1];
  const auto in = kin_json(mech, "--sweep " + std::to_string(start) + ":" + std::to_string(start + width) + ":0.5")["positions"];
  ASSERT_EQ(in.size(), 121u);
  double lo = 1e9, hi = -1e9, off = 0;
  for (const auto& p : in) {
    const auto& o = p["outputs"];
    lo = std::min(lo, o["theta6_deg"].get<double>()), hi = std::max(hi, o["theta6_deg"].get<double>());
    off = std::max(off, std::abs(std::hypot(o["Px_mm"].get<double>() - Dx, o["Py_mm"].get<double>() - Dy) - R));
  }
  EXPECT_LE(off, w["arc_deviation_mm"].get<double>() + 1e-6);
  EXPECT_LE(hi - lo, w["dwell_motion_deg"].get<double>() + 1e-6);
  EXPECT_LT(hi - lo, 0.05);  // at rest: under 0.15 % of the swing
  double all_lo = 1e9, all_hi = -1e9;
  const auto turn = kin_json(mech, "--sweep 0:360:0.25");  // kept: a range-for would not extend its life
  for (const auto& p : turn["positions"]) {
    all_lo = std::min(all_lo, p["outputs"]["theta6_deg"].get<double>());
    all_hi = std::max(all_hi, p["outputs"]["theta6_deg"].get<double>());
  }
  EXPECT_NEAR(all_hi - all_lo, w["swing_deg"].get<double>(), 0.01);
}

namespace {

// The file without its `mechanism:` (title) line.
std::string without_title(const std::string& text) {
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line))
    if (line.rfind("mechanism: ", 0) != 0) out += line + "\n";
  return out;
}

}  // namespace

// Issue 25: the title went into the mechanism file unquoted, and the crank-rocker's own default
// "Crank-rocker: 45.000 deg swing, time ratio 1.25" made the file gearkit wrote unreadable. Every
// task kind, given a title with ':', '#', both quotes, a line break and non-ASCII letters, writes
// a file the mechanism reader reads back with that title and otherwise the same text as the
// example's own run (the same linkage, number for number).
TEST(SynthCommand, EveryTaskWritesAMechanismThatReadsBackWhateverItsTitle) {
  const std::string title = "Kurbelschwinge \xE2\x80\x93 \xC3\x9C: 45\xC2\xB0 \"quick\" 'return' # no comment\nline 2";
  const std::string yaml_title =
      "\"Kurbelschwinge \xE2\x80\x93 \xC3\x9C: 45\xC2\xB0 \\\"quick\\\" 'return' # no comment\\nline 2\"";
  const char* const tasks[][3] = {{"function", "function_log10.yaml", ""},
                                  {"function", "function_slider.yaml", ""},
                                  {"motion", "three_positions.yaml", ""},
                                  {"motion", "five_positions.yaml", ""},
                                  {"path", "path_ellipse.yaml", " --evaluations 20000 --restarts 2 --seed 3"},
                                  {"crank-rocker", "crank_rocker.yaml", ""},
                                  {"dwell", "dwell.yaml", ""}};
  for (const auto& [task, name, extra] : tasks) {
    std::istringstream in(gearkit::testing::slurp(std::string(GEARKIT_SOURCE_DIR) + "/examples/synthesis/" + name));
    std::string line, text;
    while (std::getline(in, line)) text += (line.rfind("synthesis:", 0) == 0 ? "synthesis: " + yaml_title : line) + "\n";
    const fs::path task_file = write_task(std::string("hostile_") + name, text);
    const fs::path plain = scratch() / (std::string("plain_") + name), hostile = scratch() / (std::string("titled_") + name);
    const auto a = run_gearkit(std::string("synth ") + task + " " + example(name) + extra + " -m " + shell_quote(plain.string()));
    const auto b = run_gearkit(std::string("synth ") + task + " " + shell_quote(task_file.string()) + extra + " -m " +
                               shell_quote(hostile.string()));
    ASSERT_EQ(a.status, 0) << name << a.err;
    ASSERT_EQ(b.status, 0) << name << b.err;
    const auto mech = gearkit::mechanism::load_mechanism(hostile.string(), [](std::string_view) { return nullptr; });
    EXPECT_EQ(mech.title, title) << name;
    EXPECT_EQ(without_title(gearkit::testing::slurp(hostile)), without_title(gearkit::testing::slurp(plain))) << name;
  }
  // The crank-rocker's default title (Norton's example: 45 deg swing, Q = 1.25) reads back too.
  const fs::path untitled = write_task("untitled.yaml", "swing: 45 deg\ntime_ratio: 1.25\nrocker: 100 mm\n");
  const fs::path out = scratch() / "untitled_mechanism.yaml";
  const auto r = run_gearkit("synth crank-rocker " + shell_quote(untitled.string()) + " -m " + shell_quote(out.string()));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(gearkit::mechanism::load_mechanism(out.string(), [](std::string_view) { return nullptr; }).title,
            "Crank-rocker: 45.000 deg swing, time ratio 1.25");
}

// Issue 25: the solver check counted checkpoints, two per pose (point and angle), and said "6
// precision positions" for the 3 poses of examples/synthesis/three_positions.yaml.
TEST(SynthCommand, SolverCheckCountsPosesNotCheckpoints) {
  for (const auto& [name, poses] : {std::pair{"two_positions.yaml", 2}, {"three_positions.yaml", 3}, {"four_positions.yaml", 4},
                                    {"five_positions.yaml", 5}}) {
    const auto r = run_gearkit(std::string("synth motion ") + example(name));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("driven through the " + std::to_string(poses) + " precision positions"), std::string::npos) << r.out;
  }
  // A function generator checks one value per precision point: three for the log10 example.
  const auto f = run_gearkit("synth function " + example("function_log10.yaml"));
  ASSERT_EQ(f.status, 0) << f.err;
  EXPECT_NE(f.out.find("driven through the 3 precision positions"), std::string::npos) << f.out;
}
