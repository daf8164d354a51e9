// CLI tests of `gearkit gear bevel` (plugins/gear/gear_bevel_command.cpp), run through GEARKIT_EXE.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

struct CliRun {
  int status = -1;
  std::string out, err;
};

CliRun run(const std::string& args) {
  const fs::path dir = fs::temp_directory_path() / ("gearkit-bevel-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path out = dir / "out.txt", err = dir / "err.txt";
  const std::string cmd = std::string("'") + GEARKIT_EXE + "' gear bevel " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int raw = std::system(cmd.c_str());
  CliRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream o(out), e(err);
  std::stringstream so, se;
  so << o.rdbuf();
  se << e.rdbuf();
  r.out = so.str();
  r.err = se.str();
  return r;
}

double num(const nlohmann::json& j, const char* key) { return j.at(key).get<double>(); }

}  // namespace

// The KHK Gleason straight bevel example (values: tests/gear/test_bevel.cpp, KHK's formulas by
// hand): every documented per-gear key is there, with the table's values.
TEST(GearBevelCommand, KhkExampleAsJson) {
  const CliRun r = run("--z1 20 --z2 40 --module 3 --face-width 22 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& b = j.at("bevel");
  for (const char* key : {"u", "u_v", "Sigma_deg", "alpha_n_deg", "beta_m_deg", "b_mm", "m_et_mm", "m_mt_mm", "m_mn_mm", "m_it_mm",
                          "p_et_mm", "R_e_mm", "R_m_mm", "R_i_mm", "c_mm", "h_mw_mm", "alpha_vt_deg", "a_v_mm", "eps_va"})
    EXPECT_TRUE(b.contains(key)) << key;
  for (const char* stem : {"delta%_deg", "d_e%_mm", "d_m%_mm", "d_i%_mm", "x_he%", "x_hm%", "h_ae%_mm", "h_fe%_mm", "h_am%_mm",
                           "h_fm%_mm", "h_ai%_mm", "h_fi%_mm", "theta_a%_deg", "theta_f%_deg", "delta_a%_deg", "delta_f%_deg",
                           "d_ae%_mm", "d_fe%_mm", "d_ai%_mm", "t_xo%_mm", "t_xi%_mm", "b_x%_mm", "t_zm%_mm", "z_v%", "d_v%_mm",
                           "d_va%_mm", "d_vb%_mm", "x_min%"}) {
    for (const char* i : {"1", "2"}) {
      std::string key = stem;
      key.replace(key.find('%'), 1, i);
      EXPECT_TRUE(b.contains(key)) << key;
    }
  }
  EXPECT_NEAR(num(b, "delta1_deg"), 26.56505, 5e-6);
  EXPECT_NEAR(num(b, "R_e_mm"), 67.08204, 5e-6);
  EXPECT_NEAR(num(b, "d_ae1_mm"), 67.2180, 5e-5);
  EXPECT_NEAR(num(b, "d_ae2_mm"), 121.7575, 5e-5);
  EXPECT_NEAR(num(b, "theta_f1_deg"), 2.15903, 5e-6);
  EXPECT_NEAR(num(b, "t_xo1_mm"), 58.1955, 5e-5);
  EXPECT_NEAR(num(b, "z_v1"), 20.0 * std::sqrt(5.0) / 2.0, 1e-9);
  EXPECT_TRUE(j.at("warnings").empty());
  EXPECT_FALSE(j.contains("forces"));
}

// Bhandari Example 27-1 (8 kW at 400 rpm, i = 2, r = 200 mm, b = 0.2 R): 1061 N, 345.41 N,
// 172.71 N on the pinion; T1 = 8000 W / (400 * 2 pi / 60) = 190.986 N m.
TEST(GearBevelCommand, StraightBevelForces) {
  const CliRun r = run("--z1 40 --z2 80 --module 10 --face-width 89.4427191 --torque1 190.98593N*m --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto f = nlohmann::json::parse(r.out).at("forces");
  EXPECT_NEAR(num(f, "F_t1_N"), 1061.0, 0.5);
  EXPECT_NEAR(num(f, "F_r1_N"), 345.41, 0.01);
  EXPECT_NEAR(num(f, "F_a1_N"), 172.71, 0.01);
  EXPECT_NEAR(num(f, "F_r2_N"), 172.71, 0.01);
  EXPECT_EQ(f.at("driver"), 1);
  EXPECT_EQ(f.at("rotation1"), "ccw");
  EXPECT_EQ(f.at("rotation2"), "cw");
}

// A spiral bevel's axial force on the driving pinion reverses with the sense of rotation
// (hand derivation in tests/gear/test_bevel.cpp): left hand, cw -> out of mesh.
TEST(GearBevelCommand, SpiralThrustFollowsTheSense) {
  const std::string base = "--z1 13 --z2 39 --module 4 --face-width 18 --type spiral --spiral-angle 35 --hand1 left --torque1 100N*m --format json";
  const CliRun cw = run(base + " --rotation1 cw"), ccw = run(base + " --rotation1 ccw");
  ASSERT_EQ(cw.status, 0) << cw.err;
  ASSERT_EQ(ccw.status, 0) << ccw.err;
  const auto j = nlohmann::json::parse(cw.out);
  EXPECT_GT(num(j.at("forces"), "F_a1_N"), 0.0);
  EXPECT_LT(num(nlohmann::json::parse(ccw.out).at("forces"), "F_a1_N"), 0.0);
  EXPECT_EQ(j.at("bevel").at("hand1"), "left");
  EXPECT_EQ(j.at("bevel").at("hand2"), "right");
  EXPECT_TRUE(j.at("bevel").contains("z_vn1"));
  EXPECT_TRUE(j.at("bevel").contains("eps_vg"));
}

TEST(GearBevelCommand, TextAndOtherFormats) {
  const CliRun t = run("--z1 20 --z2 40 --module 3 --face-width 22");
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_NE(t.out.find("outer tip diameter d_ae [mm]"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("67.2180"), std::string::npos);
  for (const char* format : {"csv --table gears", "md", "html"}) {
    const CliRun r = run(std::string("--z1 20 --z2 40 --module 3 --face-width 22 --format ") + format);
    EXPECT_EQ(r.status, 0) << format << ": " << r.err;
    EXPECT_NE(r.out.find("121.7575"), std::string::npos) << format;
  }
}

// Engineering problems are warnings (exit 0, 3 with --strict); bad input exits 2 naming the option.
TEST(GearBevelCommand, WarningsAndBadInput) {
  const CliRun wide = run("--z1 20 --z2 40 --module 3 --face-width 25");
  EXPECT_EQ(wide.status, 0) << wide.err;
  EXPECT_NE(wide.out.find("R_e/3"), std::string::npos);
  EXPECT_EQ(run("--z1 20 --z2 40 --module 3 --face-width 25 --strict").status, 3);
  struct Case {
    const char* args;
    const char* option;
  };
  for (const Case& c : {Case{"--z2 40 --module 3 --face-width 22", "--z1"},
                        Case{"--z1 20 --z2 40 --face-width 22", "--module"},
                        Case{"--z1 20 --z2 40 --module 3 --face-width 80", "--face-width"},
                        Case{"--z1 20 --z2 40 --module 3 --face-width 22 --shaft-angle 150", "--shaft-angle"},
                        Case{"--z1 20 --z2 40 --module 3 --face-width 22 --type helical", "--type"},
                        Case{"--z1 20 --z2 40 --module 3 --face-width 22 --spiral-angle 30", "--spiral-angle"},
                        Case{"--z1 20 --z2 40 --module 3 --face-width 22 --type spiral --spiral-angle 35", "--hand1"},
                        Case{"--z1 20 --z2 40 --module 3 --face-width 22 --type spiral --spiral-angle 35 --hand1 left --torque1 5N*m", "--rotation1"},
                        Case{"--z1 20 --z2 40 --module 3 --face-width 22 --torque1 5", "--torque1"},
                        Case{"--z1 20 --z2 40 --module 3 --face-width 22 --torque1 5N*m --torque2 5N*m", "--torque2"},
                        Case{"--z1 20 --z2 40 --module 3 --face-width 22 --x1 1.5", "--x1"}}) {
    const CliRun r = run(c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.out;
    EXPECT_NE(r.err.find(c.option), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  }
}

// The drawing: both files written with the report, on the documented layers, with the data block
// carrying the table's values (KHK example: d_ae2 = 121.758, delta_a1 = 30.4870).
TEST(GearBevelCommand, DrawingFiles) {
  const fs::path dir = fs::temp_directory_path() / ("gearkit-bevel-draw-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path svg = dir / "pair.svg", dxf = dir / "pair.dxf";
  const CliRun r = run("--z1 20 --z2 40 --module 3 --face-width 22 --svg '" + svg.string() + "' --dxf '" + dxf.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  auto read = [](const fs::path& p) {
    std::ifstream f(p);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
  };
  const std::string s = read(svg), d = read(dxf);
  for (const char* layer : {"gear1", "gear2", "axes", "pitch_cone", "back_cone", "data_block"}) {
    EXPECT_NE(s.find(std::string("layer-") + layer), std::string::npos) << layer;
    EXPECT_NE(d.find(layer), std::string::npos) << layer;
  }
  for (const char* value : {"121.758", "30.4870", "58.195"}) {
    EXPECT_NE(s.find(value), std::string::npos) << value;
    EXPECT_NE(d.find(value), std::string::npos) << value;
  }
  // A refused option leaves no file behind.
  fs::remove(svg);
  EXPECT_EQ(run("--z1 20 --z2 40 --module 3 --face-width 80 --svg '" + svg.string() + "'").status, 2);
  EXPECT_FALSE(fs::exists(svg));
  fs::remove_all(dir);
}
