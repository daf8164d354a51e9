// CLI tests of `gearkit kin --animate` (cli/kin_animation_elements.hpp): slider blocks and guides,
// link and point names, the output point's trace through the sweep's positions, and the loop time
// from --speed.
#include "run_gearkit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
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

namespace {

// Runs `gearkit kin` on the model `text` with `options` and returns the animation.
std::string animate_text(const std::string& text, const std::string& options) {
  const fs::path dir = gearkit::testing::scratch_dir("kin-animation-text");
  std::ofstream(dir / "m.yaml") << text;
  const fs::path svg = dir / "a.svg";
  const auto r = run_gearkit("kin " + shell_quote((dir / "m.yaml").string()) + " " + options + " --animate " + shell_quote(svg.string()));
  EXPECT_EQ(r.status, 0) << r.err;
  return gearkit::testing::slurp(svg);
}

// The attribute `attribute` of the element whose <title> is `title` (searched back from it).
std::string attribute_before(const std::string& svg, const std::string& title, const std::string& attribute) {
  const std::size_t at = svg.find("<title>" + title + "</title>");
  EXPECT_NE(at, std::string::npos) << title;
  if (at == std::string::npos) return {};
  const std::size_t start = svg.rfind(" " + attribute + "=\"", at) + attribute.size() + 3;
  return svg.substr(start, svg.find('"', start) - start);
}

// The values of the animateTransform of `type` after `from`.
std::vector<std::string> transform_values(const std::string& svg, std::size_t from, const std::string& type) {
  const std::size_t at = svg.find("type=\"" + type + "\"", from);
  EXPECT_NE(at, std::string::npos) << type;
  std::vector<std::string> out;
  if (at == std::string::npos) return out;
  const std::size_t values = svg.find("values=\"", at) + 8;
  std::istringstream in(svg.substr(values, svg.find('"', values) - values));
  for (std::string v; std::getline(in, v, ';');) out.push_back(v);
  return out;
}

// Points "Mx,y Lx,y ... [Z]" of a path.
std::vector<std::pair<double, double>> path_points(std::string d) {
  for (char& ch : d)
    if (ch == 'M' || ch == 'L' || ch == 'Z') ch = ' ';
  return points_of(d);
}

// A cam turning counter-clockwise about the fixed O lifts a roller follower on a vertical guide
// through O (no offset): base 50 mm, a simple harmonic rise of 20 mm over 180 deg and the same
// return, so s(theta) = 10 (1 - cos theta) mm over the whole turn, and the roller centre is at
// (0, r) with r = 60 - 10 cos theta mm. In the cam's frame (turned by theta) it is at
// P(theta) = r (sin theta, cos theta): the pitch curve. The profile is P + r_r n, n the unit
// normal of P towards O (P runs clockwise, so n is the right-hand normal of P').
const char* kHarmonicCam = R"(ground: {O: [0, 0], G: [0, 0]}
links:
  cam: {points: {O: [0, 0]}}
  follower: {points: {P: [0, 0]}, position: [0, 55]}
joints:
  - {name: shaft, type: revolute, at: [cam.O, ground.O]}
  - {name: guide, type: prismatic, slider: follower.P, guide: ground.G, axis: 90 deg}
elements:
  - name: contact
    type: cam_follower
    cam: cam
    follower_type: translating
    point: follower.P
    guide: ground.G
    axis: 90 deg
    base: 50 mm
    roller_radius: 10 mm
    motion:
      - {type: rise, from: 0 deg, to: 180 deg, law: simple_harmonic, lift: 20 mm}
      - {type: return, from: 180 deg, to: 360 deg, law: simple_harmonic}
drivers:
  - {name: cam angle, type: angle, link: cam}
)";

}  // namespace

TEST(KinAnimation, CamProfileAndPitchCurveFromTheClosedForm) {
  const std::string svg = animate_text(kHarmonicCam, "--sweep 0:360:2");
  // The group's points are in the cam's frame in mm with y down: (x, -y).
  const auto pitch = path_points(attribute_before(svg, "pitch curve contact", "d"));
  const auto profile = path_points(attribute_before(svg, "cam profile contact", "d"));
  ASSERT_EQ(pitch.size(), 180u);  // one turn, 0 to 358 deg: the curve closes
  ASSERT_EQ(profile.size(), pitch.size());
  const double rr = 10.0;
  for (std::size_t i = 0; i < pitch.size(); ++i) {
    const double t = static_cast<double>(i) * 2.0 * M_PI / 180.0, r = 60.0 - 10.0 * std::cos(t), dr = 10.0 * std::sin(t);
    const double px = r * std::sin(t), py = r * std::cos(t);
    EXPECT_NEAR(pitch[i].first, px, 2e-3) << i;
    EXPECT_NEAR(-pitch[i].second, py, 2e-3) << i;
    const double tx = dr * std::sin(t) + r * std::cos(t), ty = dr * std::cos(t) - r * std::sin(t), tn = std::hypot(tx, ty);
    EXPECT_NEAR(profile[i].first, px + rr * ty / tn, 1e-2) << i;
    EXPECT_NEAR(-profile[i].second, py - rr * tx / tn, 1e-2) << i;
  }
  EXPECT_EQ(attribute_before(svg, "roller contact", "r"), "10.000");
  // The group turns with the cam: one value per frame (181 positions, 0 to 360 deg), the model's
  // counter-clockwise angle a negative SVG rotation.
  const std::size_t group = svg.find("<title>cam contact</title>");
  ASSERT_NE(group, std::string::npos);
  const auto rotate = transform_values(svg, group, "rotate"), translate = transform_values(svg, group, "translate");
  ASSERT_EQ(rotate.size(), 181u);
  EXPECT_EQ(translate.size(), 181u);
  for (std::size_t i = 0; i < rotate.size(); ++i) EXPECT_NEAR(std::stod(rotate[i]), -2.0 * static_cast<double>(i), 1e-6) << i;
  EXPECT_NE(svg.find("additive=\"sum\""), std::string::npos);
  EXPECT_EQ(svg.find("only the"), std::string::npos);  // a whole turn: nothing left out
}

TEST(KinAnimation, CamSweptPartlyDrawsOnlyTheTracedPartAndSaysSo) {
  // 0 to 90 deg: 46 pitch points, the last at 90 deg, r = 60 mm, so (60, 0) in the cam's frame.
  const std::string svg = animate_text(kHarmonicCam, "--sweep 0:90:2");
  const auto pitch = path_points(attribute_before(svg, "pitch curve contact", "d"));
  ASSERT_EQ(pitch.size(), 46u);
  EXPECT_NEAR(pitch.back().first, 60.0, 2e-3);
  EXPECT_NEAR(pitch.back().second, 0.0, 2e-3);
  EXPECT_NE(svg.find("cam (contact): only the 90 deg the sweep turns it are drawn"), std::string::npos);
}

namespace {

// A cam turning counter-clockwise about the fixed O lifts a translating flat-faced follower on a
// vertical guide through O (no offset): base circle R_b = 50 mm, a cycloidal rise of h = 20 mm
// over beta = 120 deg, a dwell of 60 deg, a cycloidal return over 120 deg and a dwell.
const char* kFlatFaceCam = R"(ground: {O: [0, 0], G: [0, 0]}
links:
  cam: {points: {O: [0, 0]}}
  follower: {points: {P: [0, 0]}, position: [0, 50]}
joints:
  - {name: shaft, type: revolute, at: [cam.O, ground.O]}
  - {name: guide, type: prismatic, slider: follower.P, guide: ground.G, axis: 90 deg}
elements:
  - name: contact
    type: cam_follower
    cam: cam
    follower_type: translating
    point: follower.P
    guide: ground.G
    axis: 90 deg
    base: 50 mm
    face: flat
    motion:
      - {type: rise, from: 0 deg, to: 120 deg, law: cycloidal, lift: 20 mm}
      - {type: dwell, from: 120 deg, to: 180 deg}
      - {type: return, from: 180 deg, to: 300 deg, law: cycloidal}
      - {type: dwell, from: 300 deg, to: 360 deg}
drivers:
  - {name: cam angle, type: angle, link: cam}
)";

// The cycloidal law (Norton, Design of Machinery, ch. 8, double-dwell cams): s = h (x - sin(2 pi x) /
// (2 pi)), ds/dtheta = (h / beta) (1 - cos(2 pi x)), x = theta / beta; the return mirrors it.
// {s, ds/dtheta} in mm and mm/rad.
std::pair<double, double> flat_face_lift(double theta) {
  const double h = 20.0, beta = 2.0 * M_PI / 3.0;
  if (theta <= beta) {
    const double x = theta / beta;
    return {h * (x - std::sin(2 * M_PI * x) / (2 * M_PI)), h / beta * (1 - std::cos(2 * M_PI * x))};
  }
  if (theta <= M_PI) return {h, 0.0};
  if (theta <= M_PI + beta) {
    const double x = (theta - M_PI) / beta;
    return {h * (1 - x + std::sin(2 * M_PI * x) / (2 * M_PI)), -h / beta * (1 - std::cos(2 * M_PI * x))};
  }
  return {0.0, 0.0};
}

}  // namespace

// Norton (Design of Machinery, ch. 8, radius of curvature of a flat-faced follower): the face y = R_b + s touches the cam at x = ds/dtheta
// from the follower's axis. The sign, for a cam turning counter-clockwise: in the cam's frame the
// face's normal points at alpha = 90 deg - theta and the face lies h(alpha) = R_b + s from O, a
// support function, whose contact point is h u(alpha) + h'(alpha) u'(alpha); h' = -s' and u' =
// (-1, 0) in the ground frame give the contact at (s', R_b + s). So the profile point drawn for
// the frame at theta lies at r = sqrt((R_b + s)^2 + s'^2) from O, at the angle atan2(R_b + s, s')
// - theta in the cam's frame.
TEST(KinAnimation, FlatFaceProfileIsTheEnvelopeOfTheFace) {
  const std::string svg = animate_text(kFlatFaceCam, "--sweep 0:360:2");
  const auto profile = path_points(attribute_before(svg, "cam profile contact", "d"));
  ASSERT_EQ(profile.size(), 180u);  // 0 to 358 deg: the curve closes
  const double rb = 50.0;
  double reach = 0.0, s_max = 0.0, s_min = 0.0;
  for (std::size_t i = 0; i < profile.size(); ++i) {
    const double t = static_cast<double>(i) * 2.0 * M_PI / 180.0;
    const auto [s, ds] = flat_face_lift(t);
    const double r = std::hypot(rb + s, ds), alpha = std::atan2(rb + s, ds) - t;
    const double x = profile[i].first, y = -profile[i].second;  // the group's y points down
    EXPECT_NEAR(std::hypot(x, y), r, 0.01) << i;
    EXPECT_NEAR(r * std::remainder(std::atan2(y, x) - alpha, 2 * M_PI), 0.0, 0.01) << i;
    reach = std::max(reach, rb + s);  // the face's point P is the farthest from O (70 mm)
    s_max = std::max(s_max, ds);      // the samples at 60 and 240 deg hit the extremes, +-2h/beta
    s_min = std::min(s_min, ds);
  }
  EXPECT_EQ(svg.find("pitch curve contact"), std::string::npos);  // no roller: no pitch curve
  EXPECT_EQ(svg.find("roller contact"), std::string::npos);
  // The face: a horizontal segment at y = R_b + s through P = (0, R_b + s), covering the
  // contact's travel along it (s' from -2h/beta to 2h/beta, +-19.099 mm) and a tenth of the cam's
  // reach (70 mm, P at full lift) beyond each end. O's place in the picture is the cam group's
  // translation.
  const std::size_t group = svg.find("<title>cam contact</title>");
  ASSERT_NE(group, std::string::npos);
  const auto origin = transform_values(svg, group, "translate");
  const std::size_t at = svg.find("<title>face contact</title>");
  ASSERT_NE(at, std::string::npos);
  const std::size_t values = svg.find("values=\"", at) + 8;
  std::istringstream in(svg.substr(values, svg.find('"', values) - values));
  std::vector<std::string> frames;
  for (std::string f; std::getline(in, f, ';');) frames.push_back(f);
  ASSERT_EQ(frames.size(), 181u);
  ASSERT_EQ(origin.size(), 181u);
  for (const std::size_t k : {0u, 20u, 30u, 45u, 75u, 100u, 120u, 160u}) {
    const double t = static_cast<double>(k) * 2.0 * M_PI / 180.0;
    const auto [s, ds] = flat_face_lift(t);
    double ox = 0, oy = 0, ax = 0, ay = 0, bx = 0, by = 0;
    ASSERT_EQ(std::sscanf(origin[k].c_str(), "%lf,%lf", &ox, &oy), 2) << origin[k];
    ASSERT_EQ(std::sscanf(frames[k].c_str(), "M%lf,%lf L%lf,%lf", &ax, &ay, &bx, &by), 4) << frames[k];
    const double margin = 0.1 * reach;
    EXPECT_NEAR(ay, oy - (rb + s), 0.01) << k;
    EXPECT_NEAR(by, oy - (rb + s), 0.01) << k;
    EXPECT_NEAR(std::min(ax, bx), ox + s_min - margin, 0.01) << k;  // the segment's ends, in either order
    EXPECT_NEAR(std::max(ax, bx), ox + s_max + margin, 0.01) << k;
    // The face touches the profile turned by theta: its highest point is on the face, at x = s'.
    double top = -1e9, top_x = 0.0;
    for (const auto& [px, py] : profile) {
      const double gx = px * std::cos(t) + py * std::sin(t), gy = px * std::sin(t) - py * std::cos(t);
      if (gy > top) top = gy, top_x = gx;
    }
    EXPECT_NEAR(top, rb + s, 0.01) << k;
    EXPECT_NEAR(top_x, ds, 0.01) << k;
  }
}

namespace {

// A cam turning counter-clockwise about O_c = (0, 0) swings a rocker pivoted at O_f = (100, 0)
// mm whose flat face runs through the pivot along the rocker's x axis, at 150 deg + psi(theta):
// psi a cycloidal rise of 10 deg over 120 deg, a dwell of 60 deg, the same return and a dwell.
const char* kFlatFaceRocker = R"(ground: {Oc: [0, 0], Of: [100, 0]}
links:
  cam: {points: {Oc: [0, 0]}}
  rocker: {points: {Of: [0, 0], E: [120, 0]}, angle: 150 deg}
joints:
  - {name: shaft, type: revolute, at: [cam.Oc, ground.Oc]}
  - {name: pivot, type: revolute, at: [rocker.Of, ground.Of]}
elements:
  - name: contact
    type: cam_follower
    cam: cam
    follower_type: oscillating
    follower: rocker
    base: 150 deg
    face: flat
    face_point: rocker.Of
    face_angle: 0 deg
    motion:
      - {type: rise, from: 0 deg, to: 120 deg, law: cycloidal, lift: 10 deg}
      - {type: dwell, from: 120 deg, to: 180 deg}
      - {type: return, from: 180 deg, to: 300 deg, law: cycloidal}
      - {type: dwell, from: 300 deg, to: 360 deg}
drivers:
  - {name: cam angle, type: angle, link: cam}
)";

}  // namespace

// Kennedy's theorem (Norton, Design of Machinery, ch. 6, instant centres; ch. 8 for the cam):
// the common normal at the contact of cam and rocker passes through their relative instant
// centre I on the line of centres, where both have the same velocity: omega_c I = omega_f (I -
// O_f), so I_x = -psi' a / (1 - psi') with a = 100 mm and psi' = dpsi/dtheta (cycloidal, in the
// lift's scale: the rise's law of flat_face_lift with h = 10 deg). The normal is perpendicular
// to the face, so the contact is the foot of the perpendicular from I on the face's line.
TEST(KinAnimation, FlatFaceOfARockerTouchesAtTheInstantCentresFoot) {
  const std::string svg = animate_text(kFlatFaceRocker, "--sweep 0:360:2");
  const auto profile = path_points(attribute_before(svg, "cam profile contact", "d"));
  ASSERT_EQ(profile.size(), 180u);
  const double a = 100.0, scale = (10.0 * M_PI / 180.0) / 20.0;  // flat_face_lift's h = 20 -> 10 deg
  for (std::size_t i = 0; i < profile.size(); ++i) {
    const double t = static_cast<double>(i) * 2.0 * M_PI / 180.0;
    const auto [s, ds] = flat_face_lift(t);
    const double psi = s * scale, dpsi = ds * scale, phi = 150.0 * M_PI / 180.0 + psi;
    const double ix = -dpsi * a / (1.0 - dpsi);
    const double along = (ix - a) * std::cos(phi);  // (I - O_f) . d, d = (cos phi, sin phi)
    const double cx = a + along * std::cos(phi), cy = along * std::sin(phi);
    // In the cam's frame (turned by theta), the group's y pointing down.
    const double x = cx * std::cos(t) + cy * std::sin(t), y = -cx * std::sin(t) + cy * std::cos(t);
    EXPECT_NEAR(profile[i].first, x, 0.01) << i;
    EXPECT_NEAR(-profile[i].second, y, 0.01) << i;
  }
  EXPECT_NE(svg.find("<title>face contact</title>"), std::string::npos);
}

namespace {

// The total turn [rad] of the line "Mx,y Lx,y" animated in the element titled `title`.
double turned(const std::string& svg, const std::string& title) {
  const std::size_t at = svg.find("<title>" + title + "</title>");
  EXPECT_NE(at, std::string::npos) << title;
  if (at == std::string::npos) return 0.0;
  const std::size_t values = svg.find("values=\"", at) + 8;
  std::istringstream frames(svg.substr(values, svg.find('"', values) - values));
  double total = 0.0, last = 0.0;
  int n = 0;
  for (std::string f; std::getline(frames, f, ';'); ++n) {
    double mx = 0, my = 0, lx = 0, ly = 0;
    EXPECT_EQ(std::sscanf(f.c_str(), "M%lf,%lf L%lf,%lf", &mx, &my, &lx, &ly), 4) << f;
    const double a = std::atan2(-(ly - my), lx - mx);
    if (n > 0) total += std::remainder(a - last, 2 * M_PI);
    last = a;
  }
  return total;
}

// Seed 004's train (test KinCommand.EpicyclicTrainThroughThePlugin): sun 30, planet 45/45, ring
// 90 teeth, tau0 = -(30 45)/(45 90) = -1/3.
const char* kPlanetary = R"(ground: {O: [0, 0]}
links:
  sun: {points: {O: [0, 0]}}
  arm: {points: {O: [0, 0], planet: [40, 0]}}
joints:
  - {type: revolute, at: [sun.O, ground.O]}
  - {type: revolute, at: [arm.O, ground.O]}
elements:
  - {name: train, type: epicyclic_train, input: sun, output: ground, arm: arm, driving: [30, 45], driven: [45, 90], externals: 1}
drivers:
  - {name: sun angle, type: angle, link: sun}
)";

}  // namespace

TEST(KinAnimation, EpicyclicTrainMembersTurnAtWillisSpeeds) {
  // Ring fixed: Willis (w_ring - w_arm) = tau0 (w_sun - w_arm) with w_ring = 0 gives
  // w_arm = tau0 / (tau0 - 1) w_sun = 1/4 w_sun: a turn of the sun turns the arm 90 deg.
  const std::string fixed_ring = animate_text(kPlanetary, "--sweep 0:360:10");
  const double r_sun = std::stod(attribute_before(fixed_ring, "pitch circle sun", "r"));
  const double r_ring = std::stod(attribute_before(fixed_ring, "pitch circle ground", "r"));
  EXPECT_NEAR(r_sun / r_ring, 30.0 / 90.0, 1e-4);
  EXPECT_NEAR(turned(fixed_ring, "tooth mark sun"), 2 * M_PI, 1e-6);
  EXPECT_NEAR(turned(fixed_ring, "tooth mark ground"), 0.0, 1e-12);
  EXPECT_NEAR(turned(fixed_ring, "arm train"), M_PI / 2, 1e-4);
  EXPECT_NE(fixed_ring.find("train (train): pitch circles to a notional scale (no module)"), std::string::npos);
  // Arm fixed, ring free: w_ring = tau0 w_sun = -1/3 w_sun, the ring turns back 120 deg.
  std::string text = kPlanetary;
  text.replace(text.find("arm: {points: {O: [0, 0], planet: [40, 0]}}"), 43, "ring: {points: {O: [0, 0]}}");
  text.replace(text.find("at: [arm.O"), 10, "at: [ring.O");
  text.replace(text.find("output: ground, arm: arm"), 24, "output: ring, arm: ground");
  const std::string fixed_arm = animate_text(text, "--sweep 0:360:10");
  EXPECT_NEAR(std::stod(attribute_before(fixed_arm, "pitch circle sun", "r")) /
                  std::stod(attribute_before(fixed_arm, "pitch circle ring", "r")),
              30.0 / 90.0, 1e-4);
  EXPECT_NEAR(turned(fixed_arm, "tooth mark ring") / turned(fixed_arm, "tooth mark sun"), -1.0 / 3.0, 1e-4);
}

namespace {

std::vector<double> values_after(const std::string& svg, std::size_t from, const std::string& attribute) {
  const std::size_t at = svg.find("attributeName=\"" + attribute + "\"", from);
  const std::size_t v = svg.find("values=\"", at) + 8;
  std::vector<double> out;
  std::istringstream in(svg.substr(v, svg.find('"', v) - v));
  for (std::string x; std::getline(in, x, ';');) out.push_back(std::stod(x));
  return out;
}

}  // namespace

TEST(KinAnimation, LinkNamesKeepClearOfJointsAndPivots) {
  // parallelogram.yaml lies flat at 0 and 180 deg: the rod's name, below the middle of A B, lay on
  // the pivot O4's triangle. In every frame the name's box (bold, about 0.72 of the font size a
  // character, from the font size above the baseline to a quarter below) must miss every joint
  // circle and every ground triangle as the SVG draws them.
  const std::string svg = animate("parallelogram.yaml", "");
  const std::size_t label = svg.find("font-weight=\"bold\">rod<animate");
  ASSERT_NE(label, std::string::npos);
  const double size = std::stod(svg.substr(svg.rfind("font-size=\"", label) + 11));
  const std::vector<double> x = values_after(svg, label, "x"), y = values_after(svg, label, "y");
  ASSERT_EQ(x.size(), 73u);  // 0 to 360 deg by 5 deg
  std::vector<std::array<double, 4>> fixed;  // the ground triangles' boxes
  for (const char* pivot : {"ground.O2", "ground.O4"}) {
    const std::size_t t = svg.find(std::string("<title>") + pivot + "</title>");
    const std::size_t p = svg.rfind("points=\"", t) + 8;
    const auto pts = points_of(svg.substr(p, svg.find('"', p) - p));
    fixed.push_back({pts[1].first, pts[0].second, pts[2].first, pts[1].second});
  }
  for (std::size_t f = 0; f < x.size(); ++f) {
    const double x0 = x[f], x1 = x[f] + 0.72 * size * 3, y0 = y[f] - size, y1 = y[f] + 0.25 * size;
    for (const auto& b : fixed) EXPECT_FALSE(x0 < b[2] && b[0] < x1 && y0 < b[3] && b[1] < y1) << "frame " << f;
    for (const char* joint : {"crank.O2", "crank.A", "rod.A", "rod.B", "rocker.O4", "rocker.B"}) {
      const std::size_t t = svg.find(std::string("<title>") + joint + "</title>");
      ASSERT_NE(t, std::string::npos) << joint;
      const double r = std::stod(svg.substr(svg.rfind(" r=\"", t) + 4));
      const double cx = values_after(svg, t, "cx")[f], cy = values_after(svg, t, "cy")[f];
      EXPECT_FALSE(x0 < cx + r && cx - r < x1 && y0 < cy + r && cy - r < y1) << "frame " << f << " " << joint;
    }
  }
}
