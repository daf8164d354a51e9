// CLI tests of the gear drawing (plugins/gear/gear_drawing.hpp): the DXF read back by ezdxf, an
// independent reader; the data block's numbers are compared with the JSON report of the same run.
#include "dxf_drawing.hpp"
#include "run_gearkit.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;

namespace {

bool have_ezdxf() { return std::system("/usr/bin/python3 -c 'import ezdxf' >/dev/null 2>&1") == 0; }

nlohmann::json dump(const fs::path& dxf) {
  const fs::path out = dxf.string() + ".json";
  const std::string cmd = "/usr/bin/python3 " + shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/tests/gear/dxf_dump.py") + " " +
                          shell_quote(dxf.string()) + " > " + shell_quote(out.string());
  EXPECT_EQ(std::system(cmd.c_str()), 0);
  return nlohmann::json::parse(gearkit::testing::slurp(out));
}

std::string f3(const nlohmann::json& v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.3f", v.get<double>());
  return b;
}

bool has_text(const nlohmann::json& texts, const std::string& s) {
  return std::any_of(texts.begin(), texts.end(), [&](const nlohmann::json& t) { return t.get<std::string>() == s; });
}

}  // namespace

TEST(GearDrawing, DataBlockNumbersEqualTheReport) {
  if (!have_ezdxf()) GTEST_SKIP() << "python3-ezdxf not installed";
  const fs::path dir = gearkit::testing::scratch_dir("gear-drawing");
  const fs::path dxf = dir / "pair.dxf";
  const auto r = run_gearkit("gear --z1 20 --z2 40 --module 3 --x1 0.2 --x2 0.1 --helix-angle 12 --quality 7 --format json --dxf " +
                             shell_quote(dxf.string()));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto d = dump(dxf);
  EXPECT_EQ(d["audit_errors"], 0);
  const auto& block = d["texts"]["data_block"];
  ASSERT_FALSE(block.empty());
  for (int i = 0; i < 2; ++i) {
    const auto& g = j["gears"][i];
    EXPECT_TRUE(has_text(block, std::to_string(g["z"].get<int>()))) << i;
    for (const char* key : {"d_mm", "d_b_mm", "d_a_mm", "d_f_mm", "m_n_mm"}) EXPECT_TRUE(has_text(block, f3(g[key]))) << key << i;
    const std::string span = "k = " + std::to_string(g["k_span"].get<int>()) + ": " + f3(g["W_k_max_mm"]) + " / " + f3(g["W_k_min_mm"]);
    EXPECT_TRUE(has_text(block, span)) << span;
    const std::string pins = "D_M " + f3(g["pin_diameter_mm"]) + ": " + f3(g["M_d_max_mm"]) + " / " + f3(g["M_d_min_mm"]);
    EXPECT_TRUE(has_text(block, pins)) << pins;
    EXPECT_TRUE(has_text(block, "ISO 1328-1:2013 class 7"));
    EXPECT_TRUE(has_text(block, "12.000° " + std::string(i == 0 ? "right" : "left"))) << i;  // external pair: opposite hands
    // The circles: on their layers, with the report's diameters, around each gear's centre.
    for (const auto& [layer, key] : {std::pair{"reference_circle", "d_mm"}, {"base_circle", "d_b_mm"}, {"tip_circle", "d_a_mm"},
                                     {"root_circle", "d_f_mm"}}) {
      const auto& c = d["circles"][layer];
      ASSERT_EQ(c.size(), 2u) << layer;
      EXPECT_NEAR(c[i][2].get<double>(), 0.5 * g[key].get<double>(), 1e-9) << layer;
    }
    // Every circle is labelled with its diameter.
    const auto& labels = d["texts"]["labels"];
    EXPECT_TRUE(has_text(labels, "d = " + f3(g["d_mm"]) + " (reference)"));
  }
  const auto& a = j["pair"];
  const std::string centre = f3(a["centre_distance_mm"]) + " " + a["centre_distance_allowances"]["field"].get<std::string>() + " (+" +
                             f3(a["centre_distance_allowances"]["A_ae_mm"]) + " / " + f3(a["centre_distance_allowances"]["A_ai_mm"]) + ")";
  EXPECT_TRUE(has_text(block, centre)) << centre;
  EXPECT_EQ(d["polylines"]["gear1"], 1);
  EXPECT_EQ(d["polylines"]["gear2"], 1);
  EXPECT_TRUE(has_text(d["texts"]["title_block"], "lengths mm, angles deg"));
}

TEST(GearDrawing, RingCutByAShaperCutter) {
  const fs::path dir = gearkit::testing::scratch_dir("gear-drawing-ring");
  const fs::path dxf = dir / "ring.dxf", svg = dir / "ring.svg";
  const auto r = run_gearkit("gear --z1 20 --z2 60 --internal --module 2 --cutter-teeth 25 --draw gear2 --format json --dxf " +
                             shell_quote(dxf.string()) + " --svg " + shell_quote(svg.string()));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["gears"][1]["k_span"].is_null());  // no span measurement on a ring (docs/gear.md)
  EXPECT_TRUE(j["gears"][0]["k_span"].is_number());
  EXPECT_EQ(j["ring_cutter"]["z_0"], 25);
  // Generating mesh with x = x_0 = 0: on the reference circles, a_0 = (60 - 25) m / 2.
  EXPECT_NEAR(j["ring_cutter"]["a_0_mm"].get<double>(), 35.0, 1e-9);
  EXPECT_EQ(j["ring_cutter"]["tip_interference_mm"].get<double>(), 0.0);
  EXPECT_NE(gearkit::testing::slurp(svg).find("<text"), std::string::npos);
  if (have_ezdxf()) {
    EXPECT_EQ(dump(dxf)["audit_errors"], 0);
  }
  // A cutter nearly as large as the ring: tip interference is a warning, not an error.
  const auto w = run_gearkit("gear --z1 20 --z2 60 --internal --module 2 --cutter-teeth 55 --format json");
  ASSERT_EQ(w.status, 0) << w.err;
  EXPECT_NE(w.out.find("tip interference"), std::string::npos);
}

// Issue 25: the default cutter of a ring m = 2, z2 = 57, x2 = 0.2 was refused with a message that
// blamed --cutter-tip-radius, which nobody gave. The default now cuts it cleanly (a cutter of
// at most |z2| - 10 = 47 teeth, no interference warning); an explicit cutter that cannot cut it
// is refused naming --cutter-teeth and the cutter's own reason.
TEST(GearDrawing, DefaultCutterCutsARingWithPositiveShift) {
  const fs::path dir = gearkit::testing::scratch_dir("gear-drawing-ring57");
  const std::string svg = shell_quote((dir / "ring57.svg").string());
  const std::string pair = "gear --z1 20 --z2 57 --internal --module 2 --x2 0.2 --draw gear2 --format json --svg " + svg;
  const auto r = run_gearkit(pair);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_LE(j["ring_cutter"]["z_0"].get<int>(), 47);
  EXPECT_EQ(j["ring_cutter"]["tip_interference_mm"].get<double>(), 0.0);
  EXPECT_EQ(j["ring_cutter"]["involute_interference_mm"].get<double>(), 0.0);
  for (const auto& w : j["warnings"]) EXPECT_EQ(w.get<std::string>().find("cutter"), std::string::npos) << w;
  const auto thick = run_gearkit(pair + " --cutter-teeth 48");
  EXPECT_EQ(thick.status, 2);
  EXPECT_NE(thick.err.find("option '--cutter-teeth'"), std::string::npos) << thick.err;
  EXPECT_NE(thick.err.find("too thick for the ring's spaces"), std::string::npos) << thick.err;
  EXPECT_EQ(thick.err.find("--cutter-tip-radius"), std::string::npos) << thick.err;
  // z_0 = 47 cuts, trimming the ring's tips: a warning, as at x2 = 0.15.
  const auto trims = run_gearkit(pair + " --cutter-teeth 47");
  ASSERT_EQ(trims.status, 0) << trims.err;
  EXPECT_NE(trims.out.find("tip interference"), std::string::npos);
}

// Issue 25: the data block labelled single nominal values "max / min". Without inspection options
// a cell holds one value, W_k = m cos(alpha) [(k - 0.5) pi + z inv(alpha)] (ISO 21771, x = 0),
// and the row is "span"; with --quality the cells hold the limits and the row says "max / min".
TEST(GearDrawing, DataBlockSaysMaxMinOnlyForLimits) {
  const fs::path dir = gearkit::testing::scratch_dir("gear-drawing-labels");
  const fs::path svg = dir / "pair.svg";
  const auto r = run_gearkit("gear --z1 20 --z2 40 --module 3 --format json --svg " + shell_quote(svg.string()));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const std::string text = gearkit::testing::slurp(svg);
  EXPECT_EQ(text.find("max / min"), std::string::npos);
  EXPECT_NE(text.find(">span<"), std::string::npos);
  EXPECT_NE(text.find(">over (ring: between) pins<"), std::string::npos);
  const double alpha = 20.0 * std::numbers::pi / 180.0, inv = std::tan(alpha) - alpha;
  for (int i = 0; i < 2; ++i) {
    const int z = i == 0 ? 20 : 40, k = j["gears"][i]["k_span"].get<int>();
    const double W = 3.0 * std::cos(alpha) * ((k - 0.5) * std::numbers::pi + z * inv);
    char cell[64];
    std::snprintf(cell, sizeof cell, ">k = %d: %.3f<", k, W);
    EXPECT_NE(text.find(cell), std::string::npos) << cell;
  }
  const auto q = run_gearkit("gear --z1 20 --z2 40 --module 3 --quality 7 --svg " + shell_quote(svg.string()));
  ASSERT_EQ(q.status, 0) << q.err;
  const std::string limits = gearkit::testing::slurp(svg);
  EXPECT_NE(limits.find(">span max / min<"), std::string::npos);
  EXPECT_NE(limits.find(">over (ring: between) pins max / min<"), std::string::npos);
}

TEST(GearDrawing, BadDrawingOptions) {
  const fs::path dir = gearkit::testing::scratch_dir("gear-drawing-bad");
  const std::string svg = shell_quote((dir / "x.svg").string());
  for (const auto& [args, option] : {std::pair{"--tolerance 0", "--tolerance"}, {"--tolerance 2mm", "--tolerance"},
                                     {"--internal --cutter-teeth 60", "--cutter-teeth"},
                                     {"--internal --cutter-tip-radius 5", "--cutter-tip-radius"}}) {
    const auto r = run_gearkit(std::string("gear --z1 20 --z2 60 --module 2 ") + args + " --svg " + svg);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(r.err.rfind("gearkit: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "x.svg"));
  }
  // The tolerance takes units: 0.5 um is 0.0005 mm.
  const auto ok = run_gearkit("gear --z1 20 --z2 60 --module 2 --tolerance 0.5um --svg " + svg);
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_NE(gearkit::testing::slurp(dir / "x.svg").find("within 0.0005 mm"), std::string::npos);
}

TEST(GearDrawing, LabelsClearOfEachOtherAndOfCurvesInsideTheFrame) {
  if (!have_ezdxf()) GTEST_SKIP() << "python3-ezdxf not installed";
  // The pair the audit printed with LibreCAD ("d = 60.000 (reference)" cut at the page edge), a
  // ring pair and one gear: no text box overlaps another or is crossed by a curve, and every text
  // lies inside the frame, which "fit to page" fits.
  const fs::path dir = gearkit::testing::scratch_dir("gear-layout");
  for (const std::string args : {"--z1 20 --z2 40 --module 3 --x1 0.2 --x2 0.1 --quality 7",
                                 "--z1 20 --z2 60 --module 2 --internal --quality 7", "--z1 17 --z2 40 --module 2 --draw gear1"}) {
    const fs::path dxf = dir / "g.dxf";
    const auto r = run_gearkit("gear " + args + " --dxf " + shell_quote(dxf.string()));
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = dump(dxf);
    const gearkit::io::Drawing d = gearkit::testing::drawing_from_dump(j);
    EXPECT_EQ(gearkit::testing::layout_faults(d), "") << args;
    const auto& frames = j["polyline_shapes"]["frame"];
    ASSERT_EQ(frames.size(), 1u) << args;
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    for (const auto& p : frames[0]["points"]) {
      xmin = std::min(xmin, p[0].get<double>()), xmax = std::max(xmax, p[0].get<double>());
      ymin = std::min(ymin, p[1].get<double>()), ymax = std::max(ymax, p[1].get<double>());
    }
    for (const auto& t : d.texts) {
      const gearkit::io::Box b = gearkit::io::text_box(t);
      EXPECT_TRUE(b.xmin > xmin && b.xmax < xmax && b.ymin > ymin && b.ymax < ymax) << t.text << " " << args;
    }
  }
}
