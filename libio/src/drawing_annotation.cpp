// Tables, labels, dimensions and legends built from the drawing's plain entities.
#include <gearkit/io/drawing_annotation.hpp>

#include "drawing_geometry.hpp"
#include "glyphs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace gearkit::io {

namespace {

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

double text_width(const std::string& text, double h) { return 0.62 * h * static_cast<double>(detail::glyphs(text)); }

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

// ---- layout: text boxes against texts and curves ----------------------------------------------

Box text_box(const Text& t) {
  return {t.x, t.y - 0.25 * t.height, t.x + text_width(t.text, t.height), t.y + t.height};
}

bool overlaps(const Box& a, const Box& b) { return a.xmin < b.xmax && b.xmin < a.xmax && a.ymin < b.ymax && b.ymin < a.ymax; }

namespace {

bool segment_crosses(const Box& b, double x1, double y1, double x2, double y2) {
  return segment_meets_box(b.xmin, b.ymin, b.xmax, b.ymax, x1, y1, x2, y2);
}

bool arc_crosses(const Box& b, const Arc& a) {
  constexpr double kStep = 0.0894;  // rad: a chord of this angle is within 1e-3 r of its arc
  const double rad = std::numbers::pi / 180.0;
  double sweep = std::fmod(std::fmod(a.end_deg - a.start_deg, 360.0) + 360.0, 360.0);
  if (sweep == 0.0) sweep = 360.0;
  const int n = std::max(1, static_cast<int>(std::ceil(sweep * rad / kStep)));
  double px = a.cx + a.r * std::cos(a.start_deg * rad), py = a.cy + a.r * std::sin(a.start_deg * rad);
  for (int i = 1; i <= n; ++i) {
    const double t = (a.start_deg + sweep * i / n) * rad;
    const double x = a.cx + a.r * std::cos(t), y = a.cy + a.r * std::sin(t);
    if (segment_crosses(b, px, py, x, y)) return true;
    px = x, py = y;
  }
  return false;
}

// A circle's outline meets the box when the box's nearest point is inside it and its farthest
// corner outside.
bool circle_crosses(const Box& b, const Circle& c) {
  const double nx = std::clamp(c.cx, b.xmin, b.xmax) - c.cx, ny = std::clamp(c.cy, b.ymin, b.ymax) - c.cy;
  const double fx = std::max(std::abs(b.xmin - c.cx), std::abs(b.xmax - c.cx));
  const double fy = std::max(std::abs(b.ymin - c.cy), std::abs(b.ymax - c.cy));
  return std::hypot(nx, ny) < c.r && std::hypot(fx, fy) > c.r;
}

bool polyline_crosses(const Box& b, const Polyline& p) {
  bool hit = false;
  for_each_segment(p, [&](const Vertex& u, const Vertex& v) {
    if (hit) return;
    if (u.bulge == 0.0 || (u.x == v.x && u.y == v.y)) hit = segment_crosses(b, u.x, u.y, v.x, v.y);
    else hit = arc_crosses(b, arc_of_bulge(u, v));
  });
  return hit;
}

// A label's own leader ends 0.4 h before its text (add_label): a line ending that close to the
// box's left or right edge at the text's middle height is the text's own and does not count.
bool own_leader(const Text& t, const Line& l) {
  const Box b = text_box(t);
  for (const auto& [x, y] : {std::pair{l.x1, l.y1}, std::pair{l.x2, l.y2}}) {
    const bool beside = std::min(std::abs(x - b.xmin), std::abs(x - b.xmax)) <= 0.5 * t.height;
    if (beside && y > b.ymin && y < b.ymax) return true;
  }
  return false;
}

}  // namespace

namespace {

// crossed_by_curves, leaving out the leader lines of the text `own` (when given).
bool crossed_except_leader(const Drawing& d, const Box& b, const Text* own) {
  for (const Line& l : d.lines)
    if (!(own && own_leader(*own, l)) && segment_crosses(b, l.x1, l.y1, l.x2, l.y2)) return true;
  for (const Polyline& p : d.polylines)
    if (polyline_crosses(b, p)) return true;
  for (const Circle& c : d.circles)
    if (circle_crosses(b, c)) return true;
  for (const Arc& a : d.arcs)
    if (arc_crosses(b, a)) return true;
  return false;
}

}  // namespace

bool crossed_by_curves(const Drawing& d, const Box& b) { return crossed_except_leader(d, b, nullptr); }

bool fits(const Drawing& d, const Drawing& added) {
  for (const Text& t : added.texts) {
    const Box b = text_box(t);
    if (crossed_by_curves(d, b) || crossed_except_leader(added, b, &t)) return false;
    for (const Text& o : d.texts)
      if (overlaps(b, text_box(o))) return false;
  }
  for (const Line& l : added.lines)
    for (const Text& o : d.texts)
      if (segment_crosses(text_box(o), l.x1, l.y1, l.x2, l.y2)) return false;
  return true;
}

void append(Drawing& d, const Drawing& added) {
  d.polylines.insert(d.polylines.end(), added.polylines.begin(), added.polylines.end());
  d.lines.insert(d.lines.end(), added.lines.begin(), added.lines.end());
  d.circles.insert(d.circles.end(), added.circles.begin(), added.circles.end());
  d.arcs.insert(d.arcs.end(), added.arcs.begin(), added.arcs.end());
  d.texts.insert(d.texts.end(), added.texts.begin(), added.texts.end());
}

std::size_t place_first_fitting(Drawing& d, const std::vector<Drawing>& candidates) {
  std::size_t chosen = 0;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (fits(d, candidates[i])) {
      chosen = i;
      break;
    }
  }
  append(d, candidates.at(chosen));
  return chosen;
}

std::vector<std::pair<std::size_t, std::size_t>> overlapping_texts(const Drawing& d) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t i = 0; i < d.texts.size(); ++i)
    for (std::size_t j = i + 1; j < d.texts.size(); ++j)
      if (overlaps(text_box(d.texts[i]), text_box(d.texts[j]))) out.emplace_back(i, j);
  return out;
}

std::vector<std::size_t> texts_crossed_by_curves(const Drawing& d) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < d.texts.size(); ++i)
    if (crossed_except_leader(d, text_box(d.texts[i]), &d.texts[i])) out.push_back(i);
  return out;
}

void add_frame(Drawing& d, double margin, const std::string& layer) {
  const Box b = drawing_box(d);
  Polyline p;
  p.layer = layer;
  p.closed = true;
  p.vertices = {{b.xmin - margin, b.ymin - margin, 0.0}, {b.xmax + margin, b.ymin - margin, 0.0},
                {b.xmax + margin, b.ymax + margin, 0.0}, {b.xmin - margin, b.ymax + margin, 0.0}};
  d.polylines.push_back(std::move(p));
}

}  // namespace gearkit::io
