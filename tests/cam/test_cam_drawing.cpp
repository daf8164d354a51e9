// CLI tests of the annotated cam drawing (plugins/cam/cam_sheet.hpp), read back from the DXF by
// ezdxf: the motion program as the model file states it, the checks equal to the JSON report of
// the same run, the key radii dimensioned with the model's values, the legend, the zero-angle
// mark and the segment angles, the follower at cam angle 0.
#include "dxf_drawing.hpp"
#include "run_gearkit.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;

namespace {

bool have_ezdxf() { return std::system("/usr/bin/python3 -c 'import ezdxf' >/dev/null 2>&1") == 0; }

std::string f(const nlohmann::json& v, int digits) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", digits, v.get<double>());
  return b;
}

bool has(const nlohmann::json& texts, const std::string& s) {
  return std::any_of(texts.begin(), texts.end(), [&](const nlohmann::json& t) { return t.get<std::string>() == s; });
}

struct CamRun {
  nlohmann::json report, dxf;
  std::string svg;
};

CamRun run(const std::string& example) {
  const fs::path dir = gearkit::testing::scratch_dir("cam-drawing");
  const fs::path dxf = dir / "cam.dxf", svg = dir / "cam.svg", dump = dir / "cam.json";
  const auto r = run_gearkit("cam " + shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/examples/cams/" + example) +
                             " --format json --dxf " + shell_quote(dxf.string()) + " --svg " + shell_quote(svg.string()));
  EXPECT_EQ(r.status, 0) << r.err;
  const std::string cmd = "/usr/bin/python3 " + shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/tests/gear/dxf_dump.py") + " " +
                          shell_quote(dxf.string()) + " > " + shell_quote(dump.string());
  EXPECT_EQ(std::system(cmd.c_str()), 0);
  return {nlohmann::json::parse(r.out), nlohmann::json::parse(gearkit::testing::slurp(dump)), gearkit::testing::slurp(svg)};
}

}  // namespace

TEST(CamDrawing, TablesLegendAndDimensionsCarryTheModelAndTheReport) {
  if (!have_ezdxf()) GTEST_SKIP() << "python3-ezdxf not installed";
  const CamRun r = run("translating_roller_cycloidal.yaml");
  const auto& d = r.dxf;
  EXPECT_EQ(d["audit_errors"], 0);
  // The motion program as examples/cams/translating_roller_cycloidal.yaml writes it.
  const auto& tables = d["texts"]["tables"];
  for (const char* cell : {"Motion program", "rise", "0.00", "120.00", "cycloidal", "20.0000", "dwell", "180.00", "return",
                           "300.00", "360.00"})
    EXPECT_TRUE(has(tables, cell)) << cell;
  // The checks, as the JSON report of the same run gives them.
  EXPECT_TRUE(has(tables, "max pressure angle [deg]"));
  EXPECT_TRUE(has(tables, f(r.report["pressure_angle_max_deg"], 3)));
  EXPECT_TRUE(has(tables, f(r.report["pressure_angle_max_at_deg"], 2)));
  EXPECT_TRUE(has(tables, f(r.report["rho_min_mm"], 3)));
  EXPECT_TRUE(has(tables, f(r.report["radius_max_mm"], 3)));
  // Radii: base 40 mm, roller 10 mm, prime circle 40 + 10 = 50 mm (the model file).
  const auto& dims = d["texts"]["dimensions"];
  EXPECT_TRUE(has(dims, "R_b = 40.000 (base)"));
  EXPECT_TRUE(has(dims, "R_p = 50.000 (prime)"));
  EXPECT_TRUE(has(dims, "r_r = 10.000"));
  EXPECT_TRUE(has(dims, "R_max = " + f(r.report["radius_max_mm"], 3)));
  EXPECT_TRUE(has(dims, "rotation:"));
  EXPECT_TRUE(has(dims, "counter-clockwise"));
  ASSERT_EQ(d["circles"]["prime_circle"].size(), 1u);
  EXPECT_NEAR(d["circles"]["prime_circle"][0][2].get<double>(), 50.0, 1e-9);
  // The legend names each curve drawn; the DXF's follower is at cam angle 0.
  const auto& legend = d["texts"]["legend"];
  for (const char* entry : {"cam profile", "pitch curve (roller centre)", "tool path (cutter centre, R 8.000)", "base circle",
                            "prime circle", "follower at cam angle 0.0°"})
    EXPECT_TRUE(has(legend, entry)) << entry;
  // The follower at 0: a roller of 10 mm whose centre is on the prime circle, on the follower's
  // axis x = offset = 0 (s = 0 at cam angle 0).
  const auto& roller = d["circles"]["follower"];
  ASSERT_EQ(roller.size(), 1u);
  EXPECT_NEAR(roller[0][0].get<double>(), 0.0, 1e-9);
  EXPECT_NEAR(roller[0][1].get<double>(), 50.0, 1e-9);
  EXPECT_NEAR(roller[0][2].get<double>(), 10.0, 1e-9);
  // Angle marks: zero and each segment start.
  const auto& marks = d["texts"]["angle_marks"];
  for (const char* m : {"cam angle 0°", "120.0°", "180.0°", "300.0°"}) EXPECT_TRUE(has(marks, m)) << m;
  EXPECT_TRUE(has(d["texts"]["title_block"], "lengths mm, angles deg"));
  // The SVG has the same annotation, the follower at the file's follower_at (60 deg).
  EXPECT_NE(r.svg.find("follower at cam angle 60.0°"), std::string::npos);
  EXPECT_NE(r.svg.find("R_b = 40.000 (base)"), std::string::npos);
}

TEST(CamDrawing, TitleBlockStatesTheCamAngleDrawn) {
  if (!have_ezdxf()) GTEST_SKIP() << "python3-ezdxf not installed";
  // The DXF is at cam angle 0 (profile as cut); the SVG at the file's follower_at: 60 deg
  // (examples/cams/translating_roller_cycloidal.yaml), the cam turned with it.
  const CamRun r = run("translating_roller_cycloidal.yaml");
  EXPECT_TRUE(has(r.dxf["texts"]["title_block"], "cam angle 0.0° (profile layers as cut)"));
  EXPECT_NE(r.svg.find("cam angle 60.0° (cam turned 60.0° from the cutting position)"), std::string::npos);
  EXPECT_EQ(r.svg.find("cam angle 0.0° (profile layers as cut)"), std::string::npos);
}

TEST(CamDrawing, ZeroMarkPointsAtTheFollowerAtCamAngleZero) {
  if (!have_ezdxf()) GTEST_SKIP() << "python3-ezdxf not installed";
  // Translating follower on the axis x = 0, above the cam: the zero mark runs from the centre
  // straight up (x = 0), through the roller centre's direction.
  const CamRun r = run("translating_roller_cycloidal.yaml");
  const auto& lines = r.dxf["lines"]["angle_marks"];
  bool found = false;
  for (const auto& l : lines) {
    if (l[0].get<double>() != 0.0 || l[1].get<double>() != 0.0) continue;  // the one from the centre
    found = true;
    EXPECT_NEAR(l[2].get<double>(), 0.0, 1e-9);
    EXPECT_GT(l[3].get<double>(), 50.0);
  }
  EXPECT_TRUE(found);
}

TEST(CamDrawing, NoLabelOverlapsAnotherOrIsCrossedByACurve) {
  if (!have_ezdxf()) GTEST_SKIP() << "python3-ezdxf not installed";
  // Every shipped cam: texts (labels, dimensions, angle marks, tables) clear of each other and of
  // every curve (profile, pitch curve, tool path, circles, dimension lines), as read back from
  // the DXF. The audit saw the profile through R_b and R_p and R_max's line through the rotation
  // text of translating_roller_cycloidal.yaml.
  for (const char* example : {"translating_roller_cycloidal.yaml", "translating_flat_345.yaml", "groove_cam.yaml",
                              "conjugate_oscillating.yaml", "offset_knife_table.yaml", "oscillating_flat_modified_trapezoid.yaml",
                              "otm2015_p2_oscillating_cycloidal.yaml", "double_dwell_dynamics.yaml"}) {
    const CamRun r = run(example);
    const gearkit::io::Drawing d = gearkit::testing::drawing_from_dump(r.dxf);
    ASSERT_GT(d.texts.size(), 20u) << example;
    EXPECT_EQ(gearkit::testing::layout_faults(d), "") << example;
  }
}
