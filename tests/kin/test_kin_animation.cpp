// CLI tests of `gearkit kin --animate` (cli/kin_animation_elements.hpp): slider blocks and guides,
// link and point names, the output point's trace through the sweep's positions, and the loop time
// from --speed.
#include "run_gearkit.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;

namespace {

std::string animate(const std::string& example, const std::string& options) {
  const fs::path dir = gearkit::testing::scratch_dir("kin-animation");
  const fs::path svg = dir / "a.svg";
  const auto r = run_gearkit("kin " + shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/" + example) + " " +
                             options + " --animate " + shell_quote(svg.string()));
  EXPECT_EQ(r.status, 0) << r.err;
  return gearkit::testing::slurp(svg);
}

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(KinAnimation, SliderBlockOnItsGuideAndNames) {
  const std::string svg = animate("slider_crank.yaml", "--sweep 0:360:10");
  EXPECT_EQ(count(svg, "<title>slider</title>"), 1u);  // one prismatic joint in the model
  EXPECT_EQ(count(svg, "<title>guide</title>"), 1u);
  for (const char* name : {">crank<", ">rod<", ">piston<", ">A<", ">B<"}) EXPECT_NE(svg.find(name), std::string::npos) << name;
  // No --speed: the stated default, 25 frames per second (37 frames) and at least 2 s.
  EXPECT_NE(svg.find("no --speed: 25 frames per second"), std::string::npos);
  EXPECT_NE(svg.find("dur=\"2.000s\""), std::string::npos);
}

TEST(KinAnimation, LoopTimeFollowsTheInputSpeed) {
  // A full turn at 60 rpm (1 turn/s) takes 1 s; at 30 rpm 2 s; half a turn at 60 rpm 0.5 s.
  EXPECT_NE(animate("four_bar.yaml", "--sweep 0:360:10 --speed 60rpm").find("dur=\"1.000s\""), std::string::npos);
  EXPECT_NE(animate("four_bar.yaml", "--sweep 0:360:10 --speed '30 rpm'").find("dur=\"2.000s\""), std::string::npos);
  EXPECT_NE(animate("four_bar.yaml", "--sweep 0:180:10 --speed 60rpm").find("dur=\"0.500s\""), std::string::npos);
  const auto bad = run_gearkit("kin " + shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/four_bar.yaml") +
                               " --sweep 0:360:10 --speed 3kg --animate x.svg");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("option '--speed'"), std::string::npos) << bad.err;
}

TEST(KinAnimation, CouplerPointTraceRunsThroughEveryPosition) {
  // four_bar.yaml has the outputs Cx, Cy of coupler.C: one trace, one vertex per position (37).
  const std::string svg = animate("four_bar.yaml", "--sweep 0:360:10");
  const std::size_t at = svg.find("<title>trace of Cx</title>");
  ASSERT_NE(at, std::string::npos);
  const std::size_t start = svg.rfind("<path d=\"", at);
  const std::string d = svg.substr(start, at - start);
  EXPECT_EQ(count(d, " L") + 1, 37u);
  EXPECT_EQ(count(svg, "<title>trace of"), 1u);  // Cy is the same point
}
