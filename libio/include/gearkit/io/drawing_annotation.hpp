#pragma once
// Annotation for io::Drawing: text tables (data blocks, motion programs), title blocks, labels
// with leaders, radial dimensions, legends and arrows. Everything is made of the drawing's own
// LINE, LWPOLYLINE and TEXT entities on named layers, so a CAD program shows it without
// dimension styles or fonts of its own, and an SVG viewer shows the same.
//
// Sizes are in drawing millimetres; `h` is a text height. Text widths are estimated at 0.62 h per
// character (a sans-serif or the CAD default font), which is what the layouts leave room for.
#include <gearkit/io/drawing.hpp>

#include <string>
#include <vector>

namespace gearkit::io {

/// Estimated width of a text of height h, mm.
double text_width(const std::string& text, double h);

/// A table drawn as ruled text: a title row, a header row (optional) and body rows; every row has
/// the same number of cells. Columns are as wide as their widest cell.
struct TextTable {
  std::string title;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

/// Width and height the table takes at text height h.
struct Size {
  double width = 0, height = 0;
};
Size table_size(const TextTable& table, double h);

/// Draws `table` with its top-left corner at (x, y_top): texts on `text_layer`, rules on `rule_layer`.
/// Returns its size.
Size add_table(Drawing& d, const TextTable& table, double x, double y_top, double h, const std::string& text_layer,
               const std::string& rule_layer);

/// A text with a leader: a line from the point (px, py) on the feature to (tx, ty), and the text
/// beside (tx, ty), to its right when tx >= px, else ending at it.
void add_label(Drawing& d, double px, double py, double tx, double ty, const std::string& text, double h,
               const std::string& layer);

/// A filled-looking arrow head (closed triangle) at (x, y) pointing along angle (rad).
void add_arrow_head(Drawing& d, double x, double y, double angle, double size, const std::string& layer);

/// Radial dimension of a circle (cx, cy, r) along angle (rad): a line from the centre to the
/// circle with an arrow at the circle and "R<value>"-style text beyond it.
void add_radius_dimension(Drawing& d, double cx, double cy, double r, double angle, const std::string& text, double h,
                          const std::string& layer);

/// A legend: one row per entry, a short line sample on the entry's layer and its text.
struct LegendEntry {
  std::string layer, text;
};
/// Returns its size; (x, y_top) is its top-left corner.
Size add_legend(Drawing& d, const std::vector<LegendEntry>& entries, double x, double y_top, double h,
                const std::string& text_layer);

/// Extents of everything drawn so far (texts by their estimated boxes): xmin, ymin, xmax, ymax.
struct Box {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
};
Box drawing_box(const Drawing& d);

/// A text height that reads well next to a drawing whose largest extent is `size` mm (2.5 mm for
/// small parts, up to 1/60 of the extent).
double text_height_for(double size);

}  // namespace gearkit::io
