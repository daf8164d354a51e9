// CLI tests of the coupler curves (cli/kin_coupler.hpp): the curve's points equal the sweep's,
// as the JSON report of the same run gives the point's x and y outputs; the DXF polyline read
// back by ezdxf holds the same points; a bad point names the option and the link points.
#include "run_gearkit.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;

namespace {

std::vector<std::vector<double>> csv_rows(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

TEST(KinCoupler, CurvePointsEqualTheSweepsOutputs) {
  const fs::path dir = gearkit::testing::scratch_dir("kin-coupler");
  const std::string model = std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/four_bar.yaml";
  const auto r = run_gearkit("kin " + shell_quote(model) + " --sweep 0:360:15 --format json --coupler coupler.C --coupler-csv " +
                             shell_quote((dir / "c.csv").string()) + " --coupler-dxf " + shell_quote((dir / "c.dxf").string()) +
                             " --coupler-svg " + shell_quote((dir / "c.svg").string()));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const std::string csv = gearkit::testing::slurp(dir / "c.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "input_deg,coupler.C_x_mm,coupler.C_y_mm");
  const auto rows = csv_rows(csv);
  ASSERT_EQ(rows.size(), j["positions"].size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& p = j["positions"][i];
    EXPECT_NEAR(rows[i][0], p["input_deg"].get<double>(), 1e-6);
    // The model's outputs Cx, Cy are the same point C of the coupler (examples/mechanisms/four_bar.yaml).
    EXPECT_NEAR(rows[i][1], p["outputs"]["Cx_mm"].get<double>(), 1e-6) << i;
    EXPECT_NEAR(rows[i][2], p["outputs"]["Cy_mm"].get<double>(), 1e-6) << i;
  }
  EXPECT_NE(gearkit::testing::slurp(dir / "c.svg").find("layer-coupler_1"), std::string::npos);
  if (std::system("/usr/bin/python3 -c 'import ezdxf' >/dev/null 2>&1") != 0) GTEST_SKIP() << "python3-ezdxf not installed";
  const std::string cmd = "/usr/bin/python3 " + shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/tests/gear/dxf_dump.py") + " " +
                          shell_quote((dir / "c.dxf").string()) + " > " + shell_quote((dir / "c.json").string());
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const auto d = nlohmann::json::parse(gearkit::testing::slurp(dir / "c.json"));
  EXPECT_EQ(d["audit_errors"], 0);
  std::size_t curves = 0;
  for (const auto& shape : d["polyline_shapes"]["coupler_1"]) {
    if (shape["points"].size() != rows.size()) continue;  // the arrow head is a 3-point polyline
    ++curves;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      EXPECT_NEAR(shape["points"][i][0].get<double>(), rows[i][1], 1e-6);
      EXPECT_NEAR(shape["points"][i][1].get<double>(), rows[i][2], 1e-6);
    }
  }
  EXPECT_EQ(curves, 1u);
}

TEST(KinCoupler, BadPointNamesTheOptionAndTheLinkPoints) {
  const std::string model = std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/four_bar.yaml";
  auto r = run_gearkit("kin " + shell_quote(model) + " --sweep 0:360:15 --coupler coupler.X");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("option '--coupler': expected LINK.POINT of a moving link ("), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("coupler.C"), std::string::npos);
  r = run_gearkit("kin " + shell_quote(model) + " --sweep 0:360:15 --coupler-csv x.csv");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--coupler"), std::string::npos) << r.err;
}
