#pragma once
// Annotation for io::Drawing: text tables (data blocks, motion programs), title blocks, labels
// with leaders, radial dimensions, legends and arrows. Everything is made of the drawing's own
// LINE, LWPOLYLINE and TEXT entities on named layers, so a CAD program shows it without
// dimension styles or fonts of its own, and an SVG viewer shows the same.
//
// Sizes are in drawing millimetres; `h` is a text height. Text widths are estimated at 0.62 h per
// character (a sans-serif or the CAD default font), which is what the layouts leave room for.
#include <gearkit/io/drawing.hpp>

#include <cstddef>
#include <string>
#include <utility>
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

/// The box a text takes as the layouts estimate it: text_width() wide, from 0.25 h below the
/// baseline (descenders) to h above it.
Box text_box(const Text& t);

/// Whether two boxes share any area (touching edges do not count).
bool overlaps(const Box& a, const Box& b);

/// Whether a curve of d (line, polyline with its bulge arcs, circle, arc) passes through box b.
/// Arcs are followed by chords within 1e-3 of their radius: this is for layout, not geometry.
bool crossed_by_curves(const Drawing& d, const Box& b);

/// Label placement: whether the entities of `added` fit into d as they are: no text of `added`
/// overlaps a text of d or is crossed by a curve of d (or of `added` itself, apart from the text's
/// own leader line ending beside it), and no line of `added` runs through a text of d.
bool fits(const Drawing& d, const Drawing& added);

/// Appends every entity of `added` (not its layers) to d.
void append(Drawing& d, const Drawing& added);

/// The first of `candidates` that fits() into d, appended to it; the first candidate when none
/// fits (a crowded drawing still gets its label). Returns the index of the candidate used.
/// Requires at least one candidate.
std::size_t place_first_fitting(Drawing& d, const std::vector<Drawing>& candidates);

/// Layout checks for tests: index pairs (i < j) of d.texts whose boxes overlap, and the indices
/// of the texts whose boxes a curve of d crosses.
std::vector<std::pair<std::size_t, std::size_t>> overlapping_texts(const Drawing& d);
std::vector<std::size_t> texts_crossed_by_curves(const Drawing& d);

/// A rectangle on layer `layer` around everything drawn, `margin` mm outside drawing_box(): CAD
/// programs that print "fit to page" (LibreCAD's dxf2pdf -a) fit the frame, so text whose font
/// runs wider than text_width() estimates still lands on the page.
void add_frame(Drawing& d, double margin, const std::string& layer);

/// A text height that reads well next to a drawing whose largest extent is `size` mm (2.5 mm for
/// small parts, up to 1/60 of the extent).
double text_height_for(double size);

}  // namespace gearkit::io
