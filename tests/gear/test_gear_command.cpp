// CLI tests of `gearkit gear` (plugins/gear/gear_command.cpp), run through GEARKIT_EXE.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
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
  const fs::path dir = fs::temp_directory_path() / ("gearkit-gear-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path out = dir / "out.txt", err = dir / "err.txt";
  const std::string cmd = std::string("'") + GEARKIT_EXE + "' gear " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
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

std::string last_line(const std::string& text) {
  std::string line, last;
  std::istringstream is(text);
  while (std::getline(is, line))
    if (!line.empty()) last = line;
  return last;
}

}  // namespace

TEST(GearCommand, JsonHasTheDocumentedKeys) {
  const CliRun r = run("--z1 12 --z2 24 --module 3 --x1 0.6 --x2 0.36 --face-width 20 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"alpha_wt_deg", "centre_distance_mm", "y", "k", "sum_x", "mounting", "contact_ratio_alpha",
                          "contact_ratio_beta", "tip_clearance_mm", "backlash_circumferential_mm", "backlash_normal_mm"}) {
    EXPECT_TRUE(j["pair"].contains(key)) << key;
  }
  EXPECT_EQ(j["pair"]["tip_clearance_mm"].size(), 2u);
  ASSERT_EQ(j["gears"].size(), 2u);
  for (const auto& g : j["gears"]) {
    for (const char* key : {"z", "x", "m_n_mm", "d_mm", "d_b_mm", "d_w_mm", "d_a_mm", "d_f_mm", "p_mm", "s_mm", "e_mm",
                            "s_a_mm", "W_k_mm", "k_span", "M_d_mm", "x_min"}) {
      EXPECT_TRUE(g.contains(key)) << key;
    }
  }
  EXPECT_TRUE(j.contains("warnings"));
  // Values of the KHK example (bolsover.com reproduction): a = 56.500, d_a1 = 44.840.
  EXPECT_NEAR(j["pair"]["centre_distance_mm"].template get<double>(), 56.5, 5e-4);
  EXPECT_NEAR(j["gears"][0]["d_a_mm"].template get<double>(), 44.840, 5e-4);
  EXPECT_EQ(j["pair"]["mounting"], "V");
}

// The 0.1 spellings stay accepted for one release: --center-distance is --centre-distance, and
// the JSON carries the old keys with the same values.
TEST(GearCommand, AmericanSpellingIsAnAlias) {
  const CliRun r = run("--z1 12 --z2 24 --module 3 --center-distance=56.5 --x1 0.6 --center-distance-deviation 0.02 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["pair"]["centre_distance_mm"].get<double>(), 56.5, 5e-4);
  EXPECT_EQ(j["pair"]["center_distance_mm"], j["pair"]["centre_distance_mm"]);
  EXPECT_EQ(j["pair"]["reference_center_distance_mm"], j["pair"]["reference_centre_distance_mm"]);
  EXPECT_NEAR(j["pair"]["center_distance_deviation_mm"].get<double>(), 0.02, 1e-12);
  EXPECT_EQ(j["pair"]["center_distance_deviation_mm"], j["pair"]["centre_distance_deviation_mm"]);
}

TEST(GearCommand, UnitsInValuesAndTextTable) {
  // OTM 2015 problem 3 (seed 000_bc94d104a9983772.txt), modified first stage, units written out.
  const CliRun r = run("--z1 10 --z2 40 --module '9 mm' --pressure-angle '20 deg' --centre-distance '225 mm' --x1 0.23529411764705882");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("V-0"), std::string::npos);
  EXPECT_NE(r.out.find("225.0000"), std::string::npos);
  EXPECT_NE(r.out.find("2.2500"), std::string::npos);  // bottom clearance 0.25 m
  EXPECT_NE(r.out.find("-0.2353"), std::string::npos);
  const CliRun md = run("--z1 10 --z2 40 --module 9 --format md");
  EXPECT_EQ(md.status, 0);
  EXPECT_NE(md.out.find("|"), std::string::npos);
  const CliRun csv = run("--z1 10 --z2 40 --module 9 --format csv --table all");
  EXPECT_EQ(csv.status, 0);
  EXPECT_NE(csv.out.find(","), std::string::npos);
}

TEST(GearCommand, TheCourseWayOtm2015Problem3) {
  // a) the teeth from the ratio 1/4 (u = 4): z1 = 15 -> z2 = 60 at m = 6; the second stage at the
  // same centre distance 225 mm with m = 5: z1 + z2 = 90, z = 18/72.
  CliRun r = run("--z1 15 --ratio 4 --module 6 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["gears"][1]["z"], 60);
  EXPECT_NEAR(j["pair"]["centre_distance_mm"].get<double>(), 225.0, 1e-9);
  r = run("--ratio 4 --module 5 --centre-distance 225 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["gears"][0]["z"], 18);
  EXPECT_EQ(j["gears"][1]["z"], 72);
  EXPECT_EQ(j["pair"]["mounting"], "zero");
  // b) V-0 with the least shift by the course's undercut limit, c) the table in radii.
  r = run("--z1 10 --z2 40 --module 9 --centre-distance 225 --split min-shift --undercut-limit practical --radii --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["pair"]["mounting"], "V-0");
  EXPECT_EQ(j["pair"]["shift_split"], "min-shift");
  EXPECT_EQ(j["pair"]["undercut_limit"], "practical");
  EXPECT_NEAR(j["gears"][0]["x"].get<double>(), 4.0 / 17.0, 1e-12);
  EXPECT_NEAR(j["gears"][0]["x_min_practical"].get<double>(), 4.0 / 17.0, 1e-12);
  EXPECT_NEAR(j["gears"][0]["r_b_mm"].get<double>(), 0.5 * j["gears"][0]["d_b_mm"].get<double>(), 1e-12);
  EXPECT_NEAR(j["gears"][1]["r_a_mm"].get<double>(), 186.88, 0.005);  // the seed's r_c of the wheel
  const CliRun text = run("--z1 10 --z2 40 --module 9 --centre-distance 225 --split min-shift --undercut-limit practical --radii");
  EXPECT_NE(text.out.find("tip radius r_a [mm]"), std::string::npos);
  EXPECT_EQ(text.out.find("tip diameter"), std::string::npos);
  EXPECT_NE(text.out.find("the course's answer is \"no undercut\""), std::string::npos) << text.out;
  // Bad combinations name the option.
  EXPECT_NE(run("--ratio 4 --module 5 --centre-distance 226").err.find("--ratio"), std::string::npos);
  EXPECT_NE(run("--ratio 4.5 --z1 15 --module 5").err.find("whole number"), std::string::npos);
  EXPECT_NE(run("--ratio 4 --z1 15 --z2 60 --module 5").err.find("--ratio"), std::string::npos);
  EXPECT_NE(run("--z1 10 --z2 40 --module 9 --undercut-limit iso").err.find("--undercut-limit"), std::string::npos);
  EXPECT_NE(run("--z1 10 --z2 40 --module 9 --centre-distance 225 --split min-shift --undercut-limit din").err.find("iso or practical"),
            std::string::npos);
  EXPECT_EQ(run("--ratio 4 --module 5 --centre-distance 226").status, 2);
}

TEST(GearCommand, BadInputExitsWithStatus2AndNamesTheOption) {
  struct Case {
    const char* args;
    const char* option;
  };
  const Case cases[] = {
      {"--z1 0 --z2 24 --module 3", "--z1"},
      {"--z1 12.5 --z2 24 --module 3", "--z1"},
      {"--z1 12 --z2 -4 --module 3", "--z2"},
      {"--z1 12 --z2 24 --module 0", "--module"},
      {"--z1 12 --z2 24 --module -3", "--module"},
      {"--z1 12 --z2 24 --module '3 deg'", "--module"},
      {"--z1 12 --z2 24 --module 3 --pressure-angle 45", "--pressure-angle"},
      {"--z1 12 --z2 24 --module 3 --pressure-angle 0", "--pressure-angle"},
      {"--z1 12 --z2 24 --module 3 --centre-distance 40", "--centre-distance"},
      {"--z1 12 --z2 24 --module 3 --centre-distance 200", "--centre-distance"},
      {"--z1 12 --z2 24 --module 3 --centre-distance '5 deg'", "--centre-distance"},
      {"--z1 30 --z2 20 --module 3 --internal", "--z2"},
      {"--z1 12 --z2 24 --module 3 --centre-distance 56.5 --x2 0.3", "--x2"},
      {"--z1 12 --z2 24 --module 3 --backlash 0.1 --allowance1 -0.05", "--backlash"},
      {"--z1 12 --z2 24 --module 3 --split balanced", "--split"},
      {"--z1 12 --z2 24 --module 3 --pin-diameter 0", "--pin-diameter"},
  };
  for (const auto& c : cases) {
    const CliRun r = run(c.args);
    EXPECT_EQ(r.status, 2) << c.args;
    const std::string line = last_line(r.err);
    EXPECT_NE(line.find(std::string("'") + c.option + "'"), std::string::npos) << c.args << " -> " << line;
    EXPECT_EQ(r.err.find("terminate"), std::string::npos);
  }
  EXPECT_EQ(run("--z2 24 --module 3").status, 2);  // missing --z1
}

TEST(GearCommand, DrawingsAreWrittenAtomically) {
  const fs::path dir = fs::temp_directory_path() / ("gearkit-gear-draw-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path svg = dir / "pair.svg", dxf = dir / "pair.dxf";
  const CliRun r = run("--z1 17 --z2 40 --module 2 --internal --svg '" + svg.string() + "' --dxf '" + dxf.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_TRUE(fs::exists(svg));
  ASSERT_TRUE(fs::exists(dxf));
  std::ifstream d(dxf);
  std::stringstream ds;
  ds << d.rdbuf();
  EXPECT_NE(ds.str().find("LWPOLYLINE"), std::string::npos);
  // A strict reader accepts it (Debian's python3-ezdxf, audit without errors), when installed;
  // one outline per gear (the sheet's frame is a polyline too, on its own layer).
  if (fs::exists("/usr/bin/python3") &&
      std::system("/usr/bin/python3 -c 'import ezdxf' >/dev/null 2>&1") == 0) {
    const std::string check = "/usr/bin/python3 -c \"import ezdxf,sys; d=ezdxf.readfile(sys.argv[1]); a=d.audit(); "
                              "n=sum(1 for e in d.modelspace().query('LWPOLYLINE') if e.dxf.layer in ('gear1', 'gear2')); "
                              "sys.exit(0 if not a.errors and n==2 else 1)\" '" +
                              dxf.string() + "'";
    EXPECT_EQ(std::system(check.c_str()), 0);
  }
  // One gear alone, helical, given in the transverse system.
  const fs::path one = dir / "gear1.dxf";
  const CliRun g = run("--z1 17 --z2 40 --module 2.2 --pressure-angle 21 --helix-angle 15 --transverse --dxf '" + one.string() +
                       "' --draw gear1 --format json");
  ASSERT_EQ(g.status, 0) << g.err;
  EXPECT_TRUE(fs::exists(one));
  const auto j = nlohmann::json::parse(g.out);
  EXPECT_NEAR(j["gears"][0]["m_t_mm"].template get<double>(), 2.2, 1e-12);
  EXPECT_NEAR(j["gears"][0]["alpha_t_deg"].template get<double>(), 21.0, 1e-12);
  // A folder that does not exist: exit 2, nothing written.
  const fs::path bad = dir / "missing" / "x.svg";
  const CliRun b = run("--z1 17 --z2 40 --module 2 --svg '" + bad.string() + "'");
  EXPECT_EQ(b.status, 2);
  EXPECT_FALSE(fs::exists(bad));
  fs::remove_all(dir);
}

TEST(GearCommand, WarningsDoNotChangeTheStatusUnlessStrict) {
  EXPECT_EQ(run("--z1 8 --z2 30 --module 2").status, 0);
  EXPECT_EQ(run("--z1 8 --z2 30 --module 2 --strict").status, 3);
}

// The hand of each gear in every format: --helix-angle is gear 1's, > 0 right hand; an external
// mate has the other hand, a ring the same (the drawing's convention, gear_drawing.cpp).
TEST(GearCommand, HelixHandOfEachGearInEveryReport) {
  const std::string pair = "--z1 20 --z2 40 --module 3 --helix-angle ";
  const CliRun text = run(pair + "15");
  ASSERT_EQ(text.status, 0) << text.err;
  const auto row = text.out.find("helix hand");
  ASSERT_NE(row, std::string::npos);
  const std::string line = text.out.substr(row, text.out.find('\n', row) - row);
  EXPECT_LT(line.find("right"), line.find("left")) << line;
  for (const char* format : {"csv --table all", "md", "html"}) {
    const CliRun r = run(pair + "15 --format " + format);
    EXPECT_NE(r.out.find("helix hand"), std::string::npos) << format;
  }
  const auto j = nlohmann::json::parse(run(pair + "-15 --format json").out);
  EXPECT_EQ(j["gears"][0]["helix_hand"], "left");
  EXPECT_EQ(j["gears"][1]["helix_hand"], "right");
  const auto ring = nlohmann::json::parse(run("--z1 20 --z2 60 --module 3 --internal --helix-angle 15 --format json").out);
  EXPECT_EQ(ring["gears"][1]["helix_hand"], "right");
  const auto spur = nlohmann::json::parse(run("--z1 20 --z2 40 --module 3 --format json").out);
  EXPECT_EQ(spur["gears"][0]["helix_hand"], "spur");
}
