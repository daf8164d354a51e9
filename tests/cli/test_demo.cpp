// `gearkit demo` (the README's first command runs it): every step runs, every file is written,
// the DXF passes ezdxf's audit, and the printed results are the seeds' answers.
#include <run_gearkit.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;
using gearkit::testing::slurp;

namespace fs = std::filesystem;

TEST(Demo, WritesGearTableTrainAndCamFiles) {
  fs::path dir = gearkit::testing::scratch_dir("demo") / "out";
  auto r = run_gearkit("demo --output " + shell_quote(dir.string()));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  for (const char* f : {"gear-table.txt", "train.txt", "cam.txt", "cam.dxf", "cam.svg", "cam-motion.svg",
                        "cam-profile.csv", "seed_two_epicyclic_stages.yaml", "translating_roller_cycloidal.yaml"})
    EXPECT_TRUE(fs::is_regular_file(dir / f)) << f;

  // Seed 004 (exam 2020-21, exercise 1): w7/w1 = 7/5 with the arm fixed, 9/7 with ring 45
  // fixed, 1 with the arm and ring locked together.
  std::string train = slurp(dir / "train.txt");
  EXPECT_NE(train.find("7/5"), std::string::npos) << train;
  EXPECT_NE(train.find("9/7"), std::string::npos) << train;
  // OTM 2015 problem 3: at the V-0 mounting the centre distance stays a = m (z1 + z2) / 2 = 225 mm,
  // and the tip clearance is 0.25 m = 2.25 mm.
  std::string gear = slurp(dir / "gear-table.txt");
  EXPECT_NE(gear.find("225.000"), std::string::npos) << gear;
  EXPECT_NE(gear.find("2.250"), std::string::npos) << gear;

  std::string svg = slurp(dir / "cam.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  std::string check = "/usr/bin/python3 " + shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/tests/io/ezdxf_check.py") +
                      " " + shell_quote((dir / "cam.dxf").string()) + " > /dev/null";
  EXPECT_EQ(std::system(check.c_str()), 0) << "ezdxf audit failed for the demo's cam.dxf";
}

TEST(Demo, UnwritableFolderIsBadInput) {
  fs::path dir = gearkit::testing::scratch_dir("demo_bad");
  std::ofstream(dir / "file") << "x";
  auto r = run_gearkit("demo --output " + shell_quote((dir / "file" / "sub").string()));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("option '--output': cannot create folder"), std::string::npos) << r.err;
}

TEST(Demo, AllOrNothingAndTheOptionTheUserGave) {
  // Issue 11 item B: a folder in the way of cam.svg made the demo exit 2 after writing four
  // files, blaming '--svg', an option the user never typed.
  fs::path dir = gearkit::testing::scratch_dir("demo_all_or_nothing");
  fs::create_directories(dir / "cam.svg");
  std::ofstream(dir / "gear-table.txt") << "old\n";
  auto r = run_gearkit("demo --output " + shell_quote(dir.string()));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind("gearkit: option '--output': cannot write '", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("': it is a folder"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("--svg"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(dir / "gear-table.txt"), "old\n");
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir)) left.push_back(e.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"cam.svg", "gear-table.txt"}));
}
