#pragma once
// Line charts as SVG: motion diagrams (s, v, a, j against cam angle), kinematic outputs against
// the input, torque against angle, speed against time. Opens in any browser.
#include <string>
#include <vector>

namespace gearkit::io {

struct Series {
  std::string name;            ///< legend text, e.g. "s [mm]"
  std::vector<double> x, y;    ///< same length
  std::string color;           ///< empty: chosen from a palette
};

/// A region between two curves (y_low..y_high over x) shaded and labelled, as textbooks draw
/// the energy areas between driving and resisting torque.
struct ShadedArea {
  std::vector<double> x, y_low, y_high;
  std::string label;           ///< drawn at the area's centroid, e.g. "+1234 J"
  std::string color = "#88c";
};

/// One panel: shared x axis, any number of series on one y axis.
struct PlotPanel {
  std::string y_label;
  std::vector<Series> series;
  std::vector<ShadedArea> areas;
};

struct Plot {
  std::string title;
  std::string x_label;
  std::vector<PlotPanel> panels;  ///< stacked vertically (e.g. s, v, a, j)
  double width_px = 800;
  double panel_height_px = 220;
};

/// Renders the plot as a standalone SVG document with axes, ticks, grid and legends.
/// Non-finite values break the line instead of corrupting the path.
std::string to_svg(const Plot& plot);

}  // namespace gearkit::io
