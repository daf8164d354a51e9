// Tests for gearkit/io/plot.hpp: a well-formed SVG with the data where the axes say.
#include <gearkit/io/plot.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <algorithm>

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
  // x ticks at the nice values 0..360 step 50.
  EXPECT_NE(svg.find(">350<"), std::string::npos);
}

TEST(Plot, NonFiniteValuesBreakTheLine) {
  Plot p;
  PlotPanel panel{"y", {}, {}};
  double nan = std::numeric_limits<double>::quiet_NaN();
  panel.series.push_back({"y", {0, 1, 2, 3, 4}, {0, 1, nan, 3, 4}, ""});
  p.panels.push_back(panel);
  std::string svg = to_svg(p);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  const std::string open = "<path d=\"M";
  const std::size_t at = svg.find(open);
  ASSERT_NE(at, std::string::npos);
  const std::size_t end = svg.find('"', at + open.size());
  ASSERT_NE(end, std::string::npos);
  std::string d = svg.substr(at + open.size() - 1, end - (at + open.size() - 1));
  ASSERT_NE(svg.find("\" fill=\"none\"", end), std::string::npos);
  EXPECT_EQ(std::count(d.begin(), d.end(), 'M'), 2);  // two separate runs
}
