// `gearkit synth` through the executable (plugins/synth): every example task, the mechanism file
// it writes analysed by `gearkit kin` at the precision positions (closing the loop through the
// real executable), the drawing and chart files, reproducibility and bad input.
#include <run_gearkit.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

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
