// Tables, labels, dimensions and legends built from the drawing's plain entities.
#include <gearkit/io/drawing_annotation.hpp>

#include "drawing_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace gearkit::io {

namespace {

// Characters, counting a UTF-8 sequence as one.
std::size_t glyphs(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0u) != 0x80u;
  return n;
}

std::vector<double> column_widths(const TextTable& t, double h) {
  std::size_t columns = t.header.size();
  for (const auto& row : t.rows) columns = std::max(columns, row.size());
  std::vector<double> w(columns, 0.0);
  auto widen = [&](const std::vector<std::string>& row) {
    for (std::size_t i = 0; i < row.size(); ++i) w[i] = std::max(w[i], text_width(row[i], h) + 1.2 * h);
  };
  widen(t.header);
  for (const auto& row : t.rows) widen(row);
  double total = 0.0;
  for (double v : w) total += v;
  const double title = text_width(t.title, h) + 1.2 * h;
  if (title > total && !w.empty()) w.back() += title - total;  // room for the title
  return w;
}

}  // namespace

double text_width(const std::string& text, double h) { return 0.62 * h * static_cast<double>(glyphs(text)); }

double text_height_for(double size) { return std::max(2.5, size / 60.0); }

Size table_size(const TextTable& t, double h) {
  const auto w = column_widths(t, h);
  Size s;
  for (double v : w) s.width += v;
  const std::size_t lines = t.rows.size() + (t.header.empty() ? 0 : 1) + (t.title.empty() ? 0 : 1);
  s.height = 1.8 * h * static_cast<double>(lines);
  return s;
}

Size add_table(Drawing& d, const TextTable& t, double x, double y_top, double h, const std::string& text_layer,
               const std::string& rule_layer) {
  const auto w = column_widths(t, h);
  const Size size = table_size(t, h);
  const double row_h = 1.8 * h, pad = 0.6 * h;
  double y = y_top;
  auto rule = [&](double yy) { d.lines.push_back({rule_layer, x, yy, x + size.width, yy}); };
  rule(y);
  if (!t.title.empty()) {
    d.texts.push_back({text_layer, x + pad, y - row_h + 0.55 * h, h, t.title});
    y -= row_h;
    rule(y);
  }
  auto put_row = [&](const std::vector<std::string>& row) {
    double cx = x;
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (!row[i].empty()) d.texts.push_back({text_layer, cx + pad, y - row_h + 0.55 * h, h, row[i]});
      cx += w[i];
    }
    y -= row_h;
    rule(y);
  };
  if (!t.header.empty()) put_row(t.header);
  for (const auto& row : t.rows) put_row(row);
  // Vertical rules: the frame, and the column borders below the title.
  const double y_cols = t.title.empty() ? y_top : y_top - row_h;
  d.lines.push_back({rule_layer, x, y_top, x, y});
  double cx = x;
  for (std::size_t i = 0; i < w.size(); ++i) {
    cx += w[i];
    d.lines.push_back({rule_layer, cx, i + 1 == w.size() ? y_top : y_cols, cx, y});
  }
  return size;
}

void add_label(Drawing& d, double px, double py, double tx, double ty, const std::string& text, double h,
               const std::string& layer) {
  const double run = 0.8 * h * (tx >= px ? 1.0 : -1.0);
  d.lines.push_back({layer, px, py, tx, ty});
  d.lines.push_back({layer, tx, ty, tx + run, ty});
  const double x = tx >= px ? tx + run + 0.4 * h : tx + run - 0.4 * h - text_width(text, h);
  d.texts.push_back({layer, x, ty - 0.4 * h, h, text});
}

void add_arrow_head(Drawing& d, double x, double y, double angle, double size, const std::string& layer) {
  const double back = angle + std::numbers::pi, spread = 0.35;
  Polyline p;
  p.layer = layer;
  p.closed = true;
  p.vertices = {{x, y, 0.0},
                {x + size * std::cos(back + spread / 2), y + size * std::sin(back + spread / 2), 0.0},
                {x + size * std::cos(back - spread / 2), y + size * std::sin(back - spread / 2), 0.0}};
  d.polylines.push_back(std::move(p));
}

void add_radius_dimension(Drawing& d, double cx, double cy, double r, double angle, const std::string& text, double h,
                          const std::string& layer) {
  const double ux = std::cos(angle), uy = std::sin(angle);
  const double ex = cx + r * ux, ey = cy + r * uy;
  d.lines.push_back({layer, cx, cy, ex, ey});
  add_arrow_head(d, ex, ey, angle, 1.2 * h, layer);
  add_label(d, ex, ey, ex + 2.0 * h * ux, ey + 2.0 * h * uy, text, h, layer);
}

Size add_legend(Drawing& d, const std::vector<LegendEntry>& entries, double x, double y_top, double h,
                const std::string& text_layer) {
  const double row_h = 1.8 * h, sample = 4.0 * h;
  Size s{0.0, row_h * static_cast<double>(entries.size())};
  double y = y_top - 0.9 * h;
  for (const LegendEntry& e : entries) {
    d.lines.push_back({e.layer, x, y, x + sample, y});
    d.texts.push_back({text_layer, x + sample + h, y - 0.4 * h, h, e.text});
    s.width = std::max(s.width, sample + h + text_width(e.text, h));
    y -= row_h;
  }
  return s;
}

Box drawing_box(const Drawing& d) {
  Extents e;
  for (const Polyline& p : d.polylines) {
    for_each_segment(p, [&](const Vertex& a, const Vertex& b) { e.add_segment(a, b); });
    for (const Vertex& v : p.vertices) e.add(v.x, v.y);
  }
  for (const Line& l : d.lines) {
    e.add(l.x1, l.y1);
    e.add(l.x2, l.y2);
  }
  for (const Circle& c : d.circles) {
    e.add(c.cx - c.r, c.cy - c.r);
    e.add(c.cx + c.r, c.cy + c.r);
  }
  for (const Arc& a : d.arcs) e.add_arc(a);
  for (const Text& t : d.texts) {
    e.add(t.x, t.y);
    e.add(t.x + text_width(t.text, t.height), t.y + t.height);
  }
  if (e.empty()) return {};
  return {e.xmin, e.ymin, e.xmax, e.ymax};
}

}  // namespace gearkit::io
