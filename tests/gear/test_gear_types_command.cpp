// CLI tests of `gearkit gear rack`, `gearkit gear worm` and `gearkit gear crossed`
// (plugins/gear/gear_*_command.cpp), run through GEARKIT_EXE.
#include "dxf_drawing.hpp"
#include "run_gearkit.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

using gearkit::testing::run_gearkit;

namespace {

nlohmann::json json_of(const std::string& args) {
  const auto r = run_gearkit("gear " + args + " --format json");
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

double num(const nlohmann::json& j) { return j.get<double>(); }

}  // namespace

TEST(GearRackCommand, KhkMountingDistanceAndDocumentedKeys) {
  // KHK: a = z m / 2 + H + x m = 18 + 32 + 1.8 = 51.8 mm for z = 12, m = 3, x = 0.6, H = 32.
  const auto j = json_of("rack --z1 12 --module 3 --x1 0.6 --rack-height 32 --travel 200 --face-width 30");
  EXPECT_NEAR(num(j["mesh"]["a_back_mm"]), 51.8, 1e-9);
  EXPECT_NEAR(num(j["mesh"]["H_0_mm"]), 19.8, 1e-9);
  EXPECT_NEAR(num(j["mesh"]["travel_per_turn_mm"]), 113.097335529, 1e-8);  // pi 36
  for (const char* key : {"z", "x", "d_mm", "d_a_mm", "W_k_mm", "k_span", "M_d_mm", "x_min"}) EXPECT_TRUE(j["pinion"].contains(key)) << key;
  for (const char* key : {"M_r_mm", "M_r_back_mm", "length_mm", "teeth", "pin_diameter_mm"}) EXPECT_TRUE(j["rack"].contains(key)) << key;
  for (const char* key : {"eps_alpha", "eps_beta", "g_alpha_mm", "c_mm"}) EXPECT_TRUE(j["mesh"].contains(key)) << key;
  // The mounting distance from the back sets the same shift.
  const auto k = json_of("rack --z1 12 --module 3 --mounting-distance 51.8 --rack-height 32");
  EXPECT_NEAR(num(k["pinion"]["x"]), 0.6, 1e-9);
}

TEST(GearRackCommand, ForcesFollowTheSenseOfTheSpeed) {
  // T = 18 N m on d = 36 mm: F_t = 1000 N, F_r = 1000 tan 20 = 363.970 N (spur).
  const auto j = json_of("rack --z1 12 --module 3 --x1 0.6 --torque1 18N*m --speed1=-100rpm");
  EXPECT_NEAR(num(j["forces"]["F_t_N"]), 1000.0, 1e-9);
  EXPECT_NEAR(num(j["forces"]["F_r_N"]), 363.970234266, 1e-6);
  EXPECT_LT(num(j["forces"]["F_rack_N"][0]), 0.0);  // turning about -z, the pinion pushes the rack towards -x
  EXPECT_LT(num(j["forces"]["v_rack_m_s"]), 0.0);
}

TEST(GearWormCommand, WorksheetPairAndKeys) {
  // "Worm Gear Formula-Master" worksheet (Niemann/DIN): gamma = 7.7651660184 deg, d_a1 = 50,
  // d_a2 = 96, a = 67, r_k = 19 (tests/gear/test_worm.cpp).
  const auto j = json_of("worm --z1 2 --z2 30 --module 3 --worm-diameter 44 --flank ZA --friction 0.05");
  EXPECT_NEAR(num(j["worm"]["gamma_deg"]), 7.7651660184, 1e-9);
  EXPECT_NEAR(num(j["worm"]["p_x_mm"]), 9.42477796077, 1e-9);
  EXPECT_NEAR(num(j["worm"]["d_a1_mm"]), 50.0, 1e-9);
  EXPECT_NEAR(num(j["wheel"]["d_a2_mm"]), 96.0, 1e-9);
  EXPECT_NEAR(num(j["wheel"]["r_k_mm"]), 19.0, 1e-9);
  EXPECT_NEAR(num(j["pair"]["a_mm"]), 67.0, 1e-9);
  for (const char* key : {"eta_worm_driving", "eta_wheel_driving", "self_locking", "self_locking_static", "self_locking_dynamic", "v_g_m_s"})
    EXPECT_TRUE(j["pair"].contains(key)) << key;
  EXPECT_EQ(j["worm"]["flank"], "ZA");
}

TEST(GearWormCommand, SelfLockingIsAWarningAndTheWheelCannotDrive) {
  const std::string pair = "worm --z1 1 --z2 40 --module 3 --q 14 --friction 0.08 --speed1 100rpm --torque2 100N*m --driver wheel";
  const auto r = run_gearkit("gear " + pair);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("self-locking (dynamic)"), std::string::npos) << r.out;
  EXPECT_EQ(run_gearkit("gear " + pair + " --strict").status, 3);
  const auto j = json_of(pair);
  EXPECT_TRUE(j["pair"]["self_locking"].get<bool>());
  EXPECT_FALSE(j.contains("forces"));
}

TEST(GearWormCommand, PowerBalanceOfTheForces) {
  const auto j = json_of("worm --z1 2 --z2 30 --module 3 --q 12 --speed1 1450rpm --torque1 20N*m");
  const auto& f = j["forces"];
  EXPECT_NEAR(num(f["P_in_W"]) - num(f["P_out_W"]), num(f["P_loss_W"]), 1e-6 * num(f["P_in_W"]));
  // P_in = T1 omega1 = 20 * 1450 pi / 30 W.
  EXPECT_NEAR(num(f["P_in_W"]), 20.0 * 1450.0 * 3.14159265358979 / 30.0, 1e-6);
  EXPECT_EQ(j["pair"]["mu_source"], "agma6034");
}

TEST(GearCrossedCommand, KhkScrewGearLayout) {
  // d1 = 45 / cos 20 = 47.888000, d2 = 72 / cos 30 = 83.138439, a = 65.513219, Sigma = 50 deg.
  const auto j = json_of("crossed --z1 15 --z2 24 --module 3 --helix-angle1 20 --helix-angle2 30");
  EXPECT_NEAR(num(j["pair"]["a_mm"]), 65.5132193, 1e-6);
  EXPECT_NEAR(num(j["pair"]["Sigma_deg"]), 50.0, 1e-9);
  EXPECT_NEAR(num(j["gears"][0]["d_mm"]), 47.8880, 5e-5);
  EXPECT_EQ(j["gears"][1]["hand"], "right");
}

TEST(GearTypesCommand, EveryFormatRenders) {
  for (const char* cmd : {"rack --z1 20 --module 2 --torque1 10N*m", "worm --z1 2 --z2 30 --module 3 --q 12 --torque1 10N*m --speed1 1000rpm",
                          "crossed --z1 15 --z2 24 --module 3 --helix-angle1 45 --helix-angle2 45 --torque1 10N*m --speed1 1000rpm"})
    for (const char* format : {"text", "json", "csv", "md", "html"}) {
      const auto r = run_gearkit(std::string("gear ") + cmd + " --format " + format + (std::string(format) == "csv" ? " --table all" : ""));
      EXPECT_EQ(r.status, 0) << cmd << " " << format << ": " << r.err;
      EXPECT_FALSE(r.out.empty());
    }
}

TEST(GearTypesCommand, BadInputExitsWithStatus2AndNamesTheOption) {
  struct Case {
    const char* args;
    const char* option;
  };
  for (const Case& c : {Case{"worm --z1 2 --z2 30 --module 3", "--q"}, Case{"worm --z1 2 --z2 30 --module 3 --q 12 --torque1 20", "--torque1"},
                        Case{"worm --z1 2 --z2 30 --module 3 --q 1", "--q"}, Case{"worm --z1 2 --z2 30 --module 3 --q 12 --flank ZX", "--flank"},
                        Case{"rack --z1 12 --module 3 --x1 0.6 --datum-distance 20", "--datum-distance"},
                        Case{"rack --z1 2 --module 3", "--z1"}, Case{"rack --z1 12 --module 3 --mounting-distance 50", "--mounting-distance"},
                        Case{"crossed --z1 15 --z2 24 --module 3 --helix-angle1 20 --helix-angle2=-20", "--helix-angle2"},
                        Case{"crossed --z1 15 --z2 24 --module 3 --helix-angle1 20", "--helix-angle2"}}) {
    const auto r = run_gearkit(std::string("gear ") + c.args);
    EXPECT_EQ(r.status, 2) << c.args << ": " << r.out;
    EXPECT_NE(r.err.find(c.option), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << c.args << ": one line expected: " << r.err;
  }
}

// The drawings read back by ezdxf (an independent DXF reader): no audit errors, the data block's
// numbers equal the JSON report of the same run, and no text overlaps another or is crossed by a curve.
namespace {

bool have_ezdxf() { return std::system("/usr/bin/python3 -c 'import ezdxf' >/dev/null 2>&1") == 0; }

nlohmann::json dump(const std::filesystem::path& dxf) {
  using gearkit::testing::shell_quote;
  const std::filesystem::path out = dxf.string() + ".json";
  const std::string cmd = "/usr/bin/python3 " + shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/tests/gear/dxf_dump.py") + " " +
                          shell_quote(dxf.string()) + " > " + shell_quote(out.string());
  EXPECT_EQ(std::system(cmd.c_str()), 0);
  return nlohmann::json::parse(gearkit::testing::slurp(out));
}

bool block_has(const nlohmann::json& d, const nlohmann::json& value) {
  char b[64];
  std::snprintf(b, sizeof b, "%.3f", value.get<double>());
  for (const auto& t : d["texts"]["data_block"])
    if (t.get<std::string>().find(b) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(GearTypesDrawing, RackAndWormDrawingsReadBack) {
  if (!have_ezdxf()) GTEST_SKIP() << "python3-ezdxf not installed";
  const auto dir = gearkit::testing::scratch_dir("gear-types-drawing");
  const std::string rack = (dir / "rack.dxf").string(), worm = (dir / "worm.dxf").string(), svg = (dir / "worm.svg").string();
  auto r = run_gearkit("gear rack --z1 18 --module 2 --x1 0.3 --rack-height 20 --travel 60 --format json --dxf " + rack);
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  auto d = dump(rack);
  EXPECT_EQ(d["audit_errors"], 0);
  for (const auto& v : {j["pinion"]["d_a_mm"], j["pinion"]["d_f_mm"], j["mesh"]["H_0_mm"], j["mesh"]["a_back_mm"], j["rack"]["length_mm"]})
    EXPECT_TRUE(block_has(d, v)) << v;
  EXPECT_EQ(gearkit::testing::layout_faults(gearkit::testing::drawing_from_dump(d)), "");
  r = run_gearkit("gear worm --z1 2 --z2 30 --module 3 --worm-diameter 44 --format json --dxf " + worm + " --svg " + svg);
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  d = dump(worm);
  EXPECT_EQ(d["audit_errors"], 0);
  for (const auto& v : {j["wheel"]["d_a2_mm"], j["wheel"]["d_e2_mm"], j["wheel"]["r_k_mm"], j["worm"]["d_a1_mm"], j["pair"]["a_mm"]})
    EXPECT_TRUE(block_has(d, v)) << v;
  EXPECT_EQ(gearkit::testing::layout_faults(gearkit::testing::drawing_from_dump(d)), "");
  EXPECT_TRUE(std::filesystem::exists(svg));
}
