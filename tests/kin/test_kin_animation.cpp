// CLI tests of `gearkit kin --animate` (cli/kin_animation_elements.hpp): slider blocks and guides,
// link and point names, the output point's trace through the sweep's positions, and the loop time
// from --speed.
#include "run_gearkit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>
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
  // No --speed: the file's 3000 rpm (examples/mechanisms/slider_crank.yaml) turns the crank in
  // 60/3000 = 0.02 s, shown 100 times slower: 2 s.
  EXPECT_NE(svg.find("one loop 2 s: the speed in the file, 100x slower (real 0.02 s)"), std::string::npos);
  EXPECT_NE(svg.find("dur=\"2.000s\""), std::string::npos);
}

TEST(KinAnimation, LoopTimeFromTheFilesSpeedWithoutSpeedOption) {
  // four_bar.yaml: 25 rad/s, a turn in 2 pi / 25 = 0.2513 s, shown 10 times slower: 2.513 s.
  const std::string four_bar = animate("four_bar.yaml", "--sweep 0:360:10");
  EXPECT_NE(four_bar.find("dur=\"2.513s\""), std::string::npos);
  EXPECT_NE(four_bar.find("one loop 2.51 s: the speed in the file, 10x slower (real 0.251 s)"), std::string::npos);
  // --speed wins over the file: 60 rpm, 1 s a turn.
  const std::string given = animate("four_bar.yaml", "--sweep 0:360:10 --speed 60rpm");
  EXPECT_NE(given.find("dur=\"1.000s\""), std::string::npos);
  EXPECT_NE(given.find("one loop 1 s: the sweep at --speed"), std::string::npos);
  // lifting_platform.yaml is quasi-static (speed 0): the stated default, 25 frames per second
  // (51 positions from 50 to 100 deg by 1 deg: 2.04 s).
  const std::string platform = animate("lifting_platform.yaml", "");
  EXPECT_NE(platform.find("one loop 2.04 s: no speed given, 25 frames per second"), std::string::npos);
  EXPECT_NE(platform.find("dur=\"2.040s\""), std::string::npos);
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

namespace {

std::vector<std::pair<double, double>> points_of(const std::string& list) {
  std::vector<std::pair<double, double>> out;
  std::istringstream in(list);
  for (std::string xy; in >> xy;) {
    const std::size_t comma = xy.find(',');
    out.emplace_back(std::stod(xy.substr(0, comma)), std::stod(xy.substr(comma + 1)));
  }
  return out;
}

}  // namespace

TEST(KinAnimation, SpringStretchesBetweenItsPoints) {
  // four_bar.yaml with a spring from the rocker's B to a ground point S = (150, 100) mm. In every
  // frame the spring's first point is B, 80 mm (the rocker) from the pivot O4 = (100, 0), and its
  // last S, hypot(50, 100) = 111.803 mm from O4 (the SVG's units are mm).
  const fs::path dir = gearkit::testing::scratch_dir("kin-animation-spring");
  std::string text = gearkit::testing::slurp(std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/four_bar.yaml");
  text.replace(text.find("  O4: [100, 0]\n"), 14, "  O4: [100, 0]\n  S: [150, 100]\n");
  text.replace(text.find("  gravity: 9.81 m/s^2\n"), 22,
               "  gravity: 9.81 m/s^2\n  springs: [{name: k, between: [rocker.B, ground.S], stiffness: 500 N/m, free_length: 50}]\n");
  std::ofstream(dir / "spring.yaml") << text;
  const fs::path svg = dir / "a.svg";
  const auto r = run_gearkit("kin " + shell_quote((dir / "spring.yaml").string()) + " --sweep 0:360:30 --animate " +
                             shell_quote(svg.string()));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string a = gearkit::testing::slurp(svg);
  const std::size_t title = a.find("<title>spring k</title>");
  ASSERT_NE(title, std::string::npos);
  const std::size_t o4 = a.find("<title>ground.O4</title>");
  ASSERT_NE(o4, std::string::npos);
  const std::size_t pivot = a.rfind("points=\"", o4) + 8;
  const auto p = points_of(a.substr(pivot, a.find('"', pivot) - pivot)).front();
  const std::size_t values = a.find("values=\"", title) + 8;
  std::istringstream frames(a.substr(values, a.find('"', values) - values));
  int n = 0;
  for (std::string frame; std::getline(frames, frame, ';'); ++n) {
    const auto pts = points_of(frame);
    ASSERT_EQ(pts.size(), 20u);  // B, the ends of the straight parts and 16 corners between, S
    EXPECT_NEAR(std::hypot(pts.front().first - p.first, pts.front().second - p.second), 80.0, 1e-2) << n;
    EXPECT_NEAR(std::hypot(pts.back().first - p.first, pts.back().second - p.second), std::hypot(50.0, 100.0), 1e-2) << n;
  }
  EXPECT_EQ(n, 13);  // 0, 30, ..., 360 deg
}

namespace {

// The direction (rad, y up) of each frame's tooth mark "Mx,y Lx,y" of the gear named `name`.
std::vector<double> mark_angles(const std::string& svg, const std::string& name) {
  const std::size_t title = svg.find("<title>tooth mark " + name + "</title>");
  EXPECT_NE(title, std::string::npos) << name;
  std::vector<double> out;
  if (title == std::string::npos) return out;
  const std::size_t values = svg.find("values=\"", title) + 8;
  std::istringstream frames(svg.substr(values, svg.find('"', values) - values));
  for (std::string f; std::getline(frames, f, ';');) {
    double mx = 0, my = 0, lx = 0, ly = 0;
    EXPECT_EQ(std::sscanf(f.c_str(), "M%lf,%lf L%lf,%lf", &mx, &my, &lx, &ly), 4) << f;
    out.push_back(std::atan2(-(ly - my), lx - mx));
  }
  return out;
}

}  // namespace

TEST(KinAnimation, GearsArePitchCirclesTurningAtTheRatio) {
  // geared_five_bar.yaml: module 5 mm, z1 = 20, z2 = 40 (the file), so pitch radii m z / 2 = 50 and
  // 100 mm (the SVG's units are mm); the tooth marks turn with the gears, gear 2 at -z1/z2 = -1/2
  // of gear 1 (external mesh: opposite senses).
  const std::string svg = animate("geared_five_bar.yaml", "");
  EXPECT_NE(svg.find("r=\"50.000\" fill=\"none\" stroke=\"#b06000\""), std::string::npos);
  EXPECT_NE(svg.find("r=\"100.000\" fill=\"none\" stroke=\"#b06000\""), std::string::npos);
  EXPECT_NE(svg.find("<title>pitch circle gear1</title>"), std::string::npos);
  const std::vector<double> a1 = mark_angles(svg, "gear1"), a2 = mark_angles(svg, "gear2");
  ASSERT_EQ(a1.size(), a2.size());
  ASSERT_GT(a1.size(), 10u);
  double turned1 = 0, turned2 = 0;
  for (std::size_t i = 1; i < a1.size(); ++i) {
    turned1 += std::remainder(a1[i] - a1[i - 1], 2 * M_PI);
    turned2 += std::remainder(a2[i] - a2[i - 1], 2 * M_PI);
  }
  EXPECT_NEAR(turned1, 2 * M_PI, 1e-3);  // the sweep: 90 to 450 deg
  EXPECT_NEAR(turned2 / turned1, -0.5, 1e-6);
}

TEST(KinAnimation, LinkNamesStayInsideThePicture) {
  // slider_crank.yaml: the piston's name starts at its pin B, the right end of the mechanism; in
  // every frame its text (6 bold characters, about 0.68 of the font size each in a sans-serif)
  // ends inside the viewBox. It ran past the right edge.
  const std::string svg = animate("slider_crank.yaml", "--sweep 0:360:5");
  double w = 0, h = 0;
  ASSERT_EQ(std::sscanf(svg.c_str() + svg.find("viewBox=\"") + 9, "0 0 %lf %lf", &w, &h), 2);
  const std::size_t label = svg.find("font-weight=\"bold\">piston<animate attributeName=\"x\"");
  ASSERT_NE(label, std::string::npos);
  const std::size_t size_at = svg.rfind("font-size=\"", label) + 11;
  const double size = std::stod(svg.substr(size_at));
  const std::size_t values = svg.find("values=\"", label) + 8;
  std::istringstream xs(svg.substr(values, svg.find('"', values) - values));
  double right = 0;
  for (std::string x; std::getline(xs, x, ';');) right = std::max(right, std::stod(x) + 0.68 * size * 6);
  EXPECT_LE(right, w);
}
