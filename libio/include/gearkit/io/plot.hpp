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

/// How an axis is ticked. `automatic`: `degrees` when its label carries "[deg]", else `linear`.
/// `degrees`: ticks at multiples of 30, 45 or 90 deg (15, 10, 5... for short spans, 180, 360...
/// for long ones). `linear`: 1, 2 or 5 times a power of ten. Labels of large or small numbers
/// carry an SI prefix ("200k", "6M", "250µ") instead of an exponent.
enum class AxisScale { automatic, linear, degrees };

/// One panel: shared x axis, any number of series on one y axis.
struct PlotPanel {
  std::string y_label;
  std::vector<Series> series;
  std::vector<ShadedArea> areas;
  AxisScale y_scale = AxisScale::automatic;
};

/// A place on the x axis where something happened, e.g. a sweep that stopped at a dead point or a
/// limit: a dashed vertical line through every panel, a marker on it and the note above the plot.
struct PlotMark {
  double x = 0;
  std::string note;             ///< e.g. "dead point at 132.5 deg: sweep stopped"
  std::string color = "#c00000";
};

struct Plot {
  std::string title;
  std::string x_label;
  std::vector<PlotPanel> panels;  ///< stacked vertically (e.g. s, v, a, j)
  double width_px = 800;
  double panel_height_px = 220;
  std::vector<PlotMark> marks = {};
  AxisScale x_scale = AxisScale::automatic;
  /// The x axis grows to the left: a sweep that runs to decreasing values (a clockwise input)
  /// reads left to right in the order it was swept.
  bool x_reversed = false;
};

/// Ticks of an axis over [lo, hi] (about `target` of them) and their labels.
struct AxisTicks {
  double lo = 0, hi = 1;        ///< the range drawn (y axes are widened to whole steps)
  double step = 1;
  std::vector<double> values;
  std::vector<std::string> labels;
};

/// The ticks `to_svg` draws. `widen` extends [lo, hi] to whole steps (y axes). A non-finite or
/// empty range gives [0, 1].
AxisTicks axis_ticks(double lo, double hi, int target, AxisScale scale, bool widen);

/// A tick label: fixed decimals from `step`, and for |values| of 10^4 and more or below 10^-2 an SI
/// prefix chosen from `magnitude` (the axis' largest |value|), so one axis uses one prefix.
std::string tick_label(double value, double step, double magnitude);

/// Renders the plot as a standalone SVG document with axes, ticks, grid and legends. A legend sits
/// in the corner of its panel that no curve, area or mark crosses; when every corner is crossed
/// the legends go in a column right of the panels. Non-finite values break the line instead of
/// corrupting the path. Elements carry classes for tools and tests: "series" (curves), "legend"
/// (a legend's box), "mark" (a PlotMark line).
std::string to_svg(const Plot& plot);

}  // namespace gearkit::io
