// Tests for gearkit/io/plot.hpp: a well-formed SVG with the data where the axes say.
#include <gearkit/io/plot.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <algorithm>
#include <array>
#include <sstream>
#include <string>
#include <vector>

using namespace gearkit::io;

TEST(Plot, DrawsSeriesAreasAndLabels) {
  Plot p;
  p.title = "Motion <diagram>";
  p.x_label = "cam angle [deg]";
  PlotPanel s{"s [mm]", {}, {}};
  Series line{"s", {}, {}, ""};
  for (int i = 0; i <= 360; i += 10) {
    line.x.push_back(i);
    line.y.push_back(std::sin(i * M_PI / 180));
  }
  s.series.push_back(line);
  s.areas.push_back({{0, 90, 180}, {0, 0, 0}, {0, 1, 0}, "+12 J", "#8c8"});
  p.panels.push_back(s);
  std::string svg = to_svg(p);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("Motion &lt;diagram&gt;"), std::string::npos);  // escaped
  EXPECT_NE(svg.find("+12 J"), std::string::npos);
  EXPECT_NE(svg.find("cam angle [deg]"), std::string::npos);
  // The x label says [deg]: ticks at multiples of 45 deg over 0..360, not at 50, 100...
  EXPECT_NE(svg.find(">315<"), std::string::npos);
  EXPECT_EQ(svg.find(">350<"), std::string::npos);
}

TEST(Plot, NonFiniteValuesBreakTheLine) {
  Plot p;
  PlotPanel panel{"y", {}, {}};
  double nan = std::numeric_limits<double>::quiet_NaN();
  panel.series.push_back({"y", {0, 1, 2, 3, 4}, {0, 1, nan, 3, 4}, ""});
  p.panels.push_back(panel);
  std::string svg = to_svg(p);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  const std::string open = "<path class=\"series\" d=\"M";
  const std::size_t at = svg.find(open);
  ASSERT_NE(at, std::string::npos);
  const std::size_t end = svg.find('"', at + open.size());
  ASSERT_NE(end, std::string::npos);
  std::string d = svg.substr(at + open.size() - 1, end - (at + open.size() - 1));
  ASSERT_NE(svg.find("\" fill=\"none\"", end), std::string::npos);
  EXPECT_EQ(std::count(d.begin(), d.end(), 'M'), 2);  // two separate runs
}

namespace {

// The numbers of an SVG attribute `name` of the first element that carries `marker` (a class).
double attribute(const std::string& svg, const std::string& marker, const std::string& name, std::size_t from = 0) {
  const std::size_t at = svg.find(marker, from);
  if (at == std::string::npos) return std::nan("");
  const std::size_t a = svg.find(" " + name + "=\"", at);
  return std::stod(svg.substr(a + name.size() + 3));
}

struct Box {
  double x, y, w, h;
};

// Every straight piece of every path of class "series", in pixels.
std::vector<std::array<double, 4>> series_segments(const std::string& svg) {
  std::vector<std::array<double, 4>> out;
  for (std::size_t at = svg.find("class=\"series\""); at != std::string::npos; at = svg.find("class=\"series\"", at + 1)) {
    const std::size_t d = svg.find("d=\"", at) + 3, end = svg.find('"', d);
    std::string path = svg.substr(d, end - d);
    for (char& c : path)
      if (c == ',' || c == 'M' || c == 'L') c = ' ';
    std::istringstream in(path);
    std::vector<double> v;
    for (double x; in >> x;) v.push_back(x);
    for (std::size_t i = 2; i + 1 < v.size(); i += 2) out.push_back({v[i - 2], v[i - 1], v[i], v[i + 1]});
  }
  return out;
}

// Whether the segment passes through the box (sampled finely: pixels are coarse enough).
bool crosses(const std::array<double, 4>& s, const Box& b) {
  for (int k = 0; k <= 200; ++k) {
    const double t = k / 200.0, x = s[0] + t * (s[2] - s[0]), y = s[1] + t * (s[3] - s[1]);
    if (x > b.x && x < b.x + b.w && y > b.y && y < b.y + b.h) return true;
  }
  return false;
}

Box legend_box(const std::string& svg) {
  return {attribute(svg, "class=\"legend\"", "x"), attribute(svg, "class=\"legend\"", "y"),
          attribute(svg, "class=\"legend\"", "width"), attribute(svg, "class=\"legend\"", "height")};
}

}  // namespace

TEST(PlotAxes, AngleAxesTickAtMultiplesOf30_45_90Degrees) {
  // Expected steps: the multiple of 30, 45 or 90 (or 15, 10... below 30) nearest span/target on a
  // log scale, by hand: 360/8 = 45; 720/8 = 90; 180/8 = 22.5 -> 30 (ln 30/22.5 = 0.29 < ln 22.5/15 = 0.41).
  EXPECT_EQ(axis_ticks(0, 360, 8, AxisScale::degrees, false).step, 45.0);
  EXPECT_EQ(axis_ticks(0, 720, 8, AxisScale::degrees, false).step, 90.0);
  EXPECT_EQ(axis_ticks(0, 180, 8, AxisScale::degrees, false).step, 30.0);
  const AxisTicks t = axis_ticks(-90, 90, 5, AxisScale::degrees, true);
  EXPECT_EQ(t.step, 30.0);  // 180/5 = 36: ln(36/30) = 0.18 < ln(45/36) = 0.22
  EXPECT_EQ(t.labels.front(), "-90");
  EXPECT_EQ(t.labels.back(), "90");
  EXPECT_EQ(axis_ticks(0, 360, 8, AxisScale::linear, false).step, 50.0);  // a length axis keeps 1-2-5 steps
}

TEST(PlotAxes, LargeAndSmallNumbersCarrySiPrefixesNotExponents) {
  const AxisTicks mega = axis_ticks(0, 6e6, 6, AxisScale::linear, true);
  EXPECT_EQ(mega.labels, (std::vector<std::string>{"0", "1M", "2M", "3M", "4M", "5M", "6M"}));
  const AxisTicks kilo = axis_ticks(-1e5, 1e5, 4, AxisScale::linear, true);
  EXPECT_EQ(kilo.labels.front(), "-100k");
  EXPECT_EQ(kilo.labels.back(), "100k");
  EXPECT_EQ(tick_label(1.5e6, 5e5, 2e6), "1.5M");
  EXPECT_EQ(tick_label(2.5e-4, 5e-5, 5e-4), "250µ");
  EXPECT_EQ(tick_label(250, 50, 300), "250");  // ordinary magnitudes stay plain
  for (const std::string& l : mega.labels) EXPECT_EQ(l.find('e'), std::string::npos) << l;
}

TEST(PlotLegend, SitsInACornerNoCurveCrosses) {
  // A rising line crosses the top-right and bottom-left corners; a falling one the other two:
  // one of them alone must leave a free corner, and the legend must not touch the curve.
  for (double sign : {1.0, -1.0}) {
    Plot p;
    PlotPanel panel{"y", {}, {}};
    Series s{"a rather long legend text for the curve", {}, {}, ""};
    for (int i = 0; i <= 100; ++i) {
      s.x.push_back(i);
      s.y.push_back(sign * i);
    }
    panel.series.push_back(s);
    p.panels.push_back(panel);
    const std::string svg = to_svg(p);
    const Box b = legend_box(svg);
    ASSERT_FALSE(std::isnan(b.x));
    for (const auto& seg : series_segments(svg)) EXPECT_FALSE(crosses(seg, b)) << sign;
    const std::size_t frame = svg.rfind("<rect", svg.find("stroke=\"#444\""));
    const double frame_right = attribute(svg, "<rect", "x", frame) + attribute(svg, "<rect", "width", frame);
    EXPECT_LT(b.x + b.w, frame_right) << "inside the panel when a corner is free";
  }
}

TEST(PlotLegend, GoesBesideThePanelWhenEveryCornerIsCrossed) {
  Plot p;
  PlotPanel panel{"y", {}, {}};
  Series s{"zigzag", {}, {}, ""};
  for (int i = 0; i <= 400; ++i) {  // fills the panel from edge to edge
    s.x.push_back(i);
    s.y.push_back(i % 2 ? 1.0 : -1.0);
  }
  panel.series.push_back(s);
  p.panels.push_back(panel);
  const std::string svg = to_svg(p);
  const Box b = legend_box(svg);
  for (const auto& seg : series_segments(svg)) EXPECT_FALSE(crosses(seg, b));
  const std::size_t frame = svg.rfind("<rect", svg.find("stroke=\"#444\""));
  EXPECT_GT(b.x, attribute(svg, "<rect", "x", frame) + attribute(svg, "<rect", "width", frame));
  EXPECT_LT(b.x + b.w, p.width_px);
}

TEST(PlotMarks, AMarkIsALineAtItsXWithItsNote) {
  Plot p;
  p.x_label = "crank angle [deg]";
  PlotPanel panel{"theta_4 [deg]", {}, {}};
  panel.series.push_back({"theta_4", {0, 60, 120, 132.5}, {10, 40, 70, 71}, ""});
  p.panels.push_back(panel);
  p.panels.push_back(panel);
  p.marks.push_back({132.5, "dead point at 132.5 deg: sweep stopped", "#c00000"});
  const std::string svg = to_svg(p);
  EXPECT_NE(svg.find(">dead point at 132.5 deg: sweep stopped<"), std::string::npos);
  // The sweep ends at the mark, so the mark is the right edge of the x range: the frame's right side.
  const std::size_t frame = svg.rfind("<rect", svg.find("stroke=\"#444\""));
  const double right = attribute(svg, "<rect", "x", frame) + attribute(svg, "<rect", "width", frame);
  EXPECT_NEAR(attribute(svg, "class=\"mark\"", "x1"), right, 0.01);
  // Through both panels: from above the first to the bottom of the second.
  EXPECT_GT(attribute(svg, "class=\"mark\"", "y2") - attribute(svg, "class=\"mark\"", "y1"), 2 * p.panel_height_px);
}

// A clockwise sweep (input 0 down to -360 deg) reads left to right as swept: 0 at the left edge,
// -360 at the right (issue 13 item 4); the same data unreversed put -360 at the left.
TEST(PlotAxes, AReversedXAxisPutsTheSweepsStartAtTheLeft) {
  Plot p;
  p.x_label = "theta2 [deg]";
  PlotPanel panel{"theta4 [deg]", {}, {}};
  panel.series.push_back({"theta4", {0, -90, -180, -270, -360}, {60, 40, 20, 40, 60}, ""});
  p.panels.push_back(panel);
  const auto tick_x = [](const std::string& svg, const std::string& label) {
    const std::size_t at = svg.find(">" + label + "</text>");
    EXPECT_NE(at, std::string::npos) << label;
    return attribute(svg, "<text", "x", svg.rfind("<text", at));
  };
  const std::string normal = to_svg(p);
  EXPECT_LT(tick_x(normal, "-360"), tick_x(normal, "0"));
  p.x_reversed = true;
  const std::string reversed = to_svg(p);
  EXPECT_GT(tick_x(reversed, "-360"), tick_x(reversed, "0"));
  // The first point of the series (x = 0) is drawn at the left end of the line.
  EXPECT_NEAR(tick_x(reversed, "0"), tick_x(normal, "-360"), 0.01);
}
