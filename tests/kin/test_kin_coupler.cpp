// CLI tests of the coupler curves (cli/kin_coupler.hpp): the curve's points equal the sweep's,
// as the JSON report of the same run gives the point's x and y outputs; the DXF polyline read
// back by ezdxf holds the same points; a bad point names the option and the link points.
#include "run_gearkit.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
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

TEST(KinCoupler, DrawingHasRulersInMillimetres) {
  if (std::system("/usr/bin/python3 -c 'import ezdxf' >/dev/null 2>&1") != 0) GTEST_SKIP() << "python3-ezdxf not installed";
  // Every number on the rulers (layer "scale") stands at the tick for that many mm: a vertical
  // tick at x = value on the bottom ruler, a horizontal one at y = value on the left; the ticks
  // span the curve as the CSV gives it. The ground pivots O2 (0, 0) and O4 (100, 0) of
  // examples/mechanisms/four_bar.yaml are inside the x ruler's range.
  const fs::path dir = gearkit::testing::scratch_dir("kin-coupler-scale");
  const std::string model = std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/four_bar.yaml";
  const auto r = run_gearkit("kin " + shell_quote(model) + " --sweep 0:360:5 --coupler coupler.C --coupler-csv " +
                             shell_quote((dir / "c.csv").string()) + " --coupler-dxf " + shell_quote((dir / "c.dxf").string()));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string cmd = "/usr/bin/python3 " + shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/tests/gear/dxf_dump.py") + " " +
                          shell_quote((dir / "c.dxf").string()) + " > " + shell_quote((dir / "c.json").string());
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const auto d = nlohmann::json::parse(gearkit::testing::slurp(dir / "c.json"));
  const auto& lines = d["lines"]["scale"];
  auto tick_at = [&](double v, bool vertical) {
    for (const auto& l : lines) {
      const double x1 = l[0], y1 = l[1], x2 = l[2], y2 = l[3];
      if (vertical && x1 == x2 && std::abs(x1 - v) < 1e-9) return true;
      if (!vertical && y1 == y2 && std::abs(y1 - v) < 1e-9 && std::abs(x2 - x1) < 5.0) return true;
    }
    return false;
  };
  double xlo = 1e300, xhi = -1e300, ylo = 1e300, yhi = -1e300;
  int numbers = 0;
  for (const auto& t : d["text_at"]["scale"]) {
    const std::string text = t[0];
    if (text.find("mm") != std::string::npos) continue;
    const double v = std::stod(text), x = t[1], y = t[2];
    ++numbers;
    const bool below = y < 0.0 && std::abs(x + 0.62 * 0.5 * text.size() * d["text_height"]["scale"][0].get<double>() - v) < 1e-6;
    if (below) xlo = std::min(xlo, v), xhi = std::max(xhi, v);
    else ylo = std::min(ylo, v), yhi = std::max(yhi, v);
    EXPECT_TRUE(tick_at(v, below)) << text;
  }
  EXPECT_GE(numbers, 8);
  const auto rows = csv_rows(gearkit::testing::slurp(dir / "c.csv"));
  for (const auto& row : rows) {
    EXPECT_LE(xlo, row[1]);
    EXPECT_GE(xhi, row[1]);
    EXPECT_LE(ylo, row[2]);
    EXPECT_GE(yhi, row[2]);
  }
  EXPECT_LE(xlo, 0.0);
  EXPECT_GE(xhi, 100.0);
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
