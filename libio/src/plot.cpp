#include <gearkit/io/plot.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <gearkit/io/xml.hpp>

#include "drawing_geometry.hpp"
#include "glyphs.hpp"

namespace gearkit::io {

namespace {

constexpr std::array kPalette = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b"};

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool empty() const { return !(lo <= hi); }
};

// "Nice" tick step (1, 2 or 5 times a power of ten) for about `target` ticks.
double nice_step(double span, int target) {
  if (!(span > 0)) return 1.0;
  double raw = span / target;
  double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double f = raw / mag;
  double nice = f < 1.5 ? 1 : f < 3 ? 2 : f < 7 ? 5 : 10;
  return nice * mag;
}

// An angle step: the multiple of 30, 45 or 90 deg (or a divisor of 30 for short spans, 180 x 2^k
// for long ones) nearest to span / target on a log scale.
double angle_step(double span, int target) {
  const double raw = span / target;
  if (!(raw >= 1.0)) return nice_step(span, target);
  static constexpr std::array kSteps = {1.0, 2.0, 5.0, 10.0, 15.0, 30.0, 45.0, 90.0, 180.0, 360.0, 720.0, 1440.0, 2880.0};
  if (raw > kSteps.back()) return nice_step(span, target);
  double best = kSteps.front();
  for (double s : kSteps)
    if (std::abs(std::log(s / raw)) < std::abs(std::log(best / raw))) best = s;
  return best;
}

Range padded(Range r) {
  if (r.empty()) return {0, 1};
  if (r.hi - r.lo < 1e-12 * std::max(1.0, std::abs(r.hi))) {
    double d = std::max(1.0, std::abs(r.hi)) * 0.5;
    return {r.lo - d, r.hi + d};
  }
  return r;
}

bool degrees(AxisScale scale, const std::string& label) {
  return scale == AxisScale::degrees || (scale == AxisScale::automatic && label.find("[deg]") != std::string::npos);
}

struct Rect {
  double x = 0, y = 0, w = 0, h = 0;
};

struct Segment {
  double x1, y1, x2, y2;
};

// Whether the segment has a point inside the rectangle.
bool crosses(const Segment& s, const Rect& r) { return segment_meets_box(r.x, r.y, r.x + r.w, r.y + r.h, s.x1, s.y1, s.x2, s.y2); }

Rect legend_size(const PlotPanel& p) {
  double w = 0;
  for (const Series& s : p.series) w = std::max(w, 7.0 * static_cast<double>(detail::glyphs(s.name)));
  return {0, 0, w + 44.0, 16.0 * static_cast<double>(p.series.size()) + 8.0};
}

// Pixel geometry of the whole plot.
struct Frame {
  double left = 80, right = 20, top = 20, gap = 40, bottom = 50;
  double width = 800, panel_h = 220;
  double plot_w() const { return width - left - right; }
  double panel_top(std::size_t i) const { return top + static_cast<double>(i) * (panel_h + gap); }
};

struct Panel {
  AxisTicks y;
  double y0 = 0;
  double Y(double v, double h) const { return y0 + h - (v - y.lo) / (y.hi - y.lo) * h; }
};

struct Layout {
  Frame f;
  AxisTicks x;
  std::vector<Panel> panels;
  std::vector<Rect> legends;  // per panel
  bool x_reversed = false;
  double X(double v) const {
    const double t = (v - x.lo) / (x.hi - x.lo);
    return f.left + (x_reversed ? 1.0 - t : t) * f.plot_w();
  }
};

// Everything drawn inside a panel that a legend must not cover, in pixels.
std::vector<Segment> obstacles(const Plot& plot, const Layout& L, std::size_t pi) {
  const PlotPanel& p = plot.panels[pi];
  const Panel& g = L.panels[pi];
  const double h = L.f.panel_h;
  std::vector<Segment> out;
  for (const Series& s : p.series)
    for (std::size_t i = 1; i < std::min(s.x.size(), s.y.size()); ++i)
      if (std::isfinite(s.x[i - 1] + s.y[i - 1] + s.x[i] + s.y[i]))
        out.push_back({L.X(s.x[i - 1]), g.Y(s.y[i - 1], h), L.X(s.x[i]), g.Y(s.y[i], h)});
  for (const ShadedArea& a : p.areas)
    for (std::size_t i = 0; i < std::min({a.x.size(), a.y_low.size(), a.y_high.size()}); ++i)
      out.push_back({L.X(a.x[i]), g.Y(a.y_low[i], h), L.X(a.x[i]), g.Y(a.y_high[i], h)});
  for (const PlotMark& m : plot.marks) out.push_back({L.X(m.x), g.y0, L.X(m.x), g.y0 + h});
  return out;
}

// A free corner of the panel for its legend, or nullopt.
std::optional<Rect> free_corner(const Plot& plot, const Layout& L, std::size_t pi) {
  const Rect size = legend_size(plot.panels[pi]);
  const std::vector<Segment> segments = obstacles(plot, L, pi);
  const double x0 = L.f.left + 8, x1 = L.f.left + L.f.plot_w() - 8 - size.w;
  const double y0 = L.panels[pi].y0 + 6, y1 = L.panels[pi].y0 + L.f.panel_h - 6 - size.h;
  for (const Rect r : {Rect{x0, y0, size.w, size.h}, Rect{x1, y0, size.w, size.h}, Rect{x0, y1, size.w, size.h},
                       Rect{x1, y1, size.w, size.h}}) {
    if (std::none_of(segments.begin(), segments.end(), [&](const Segment& s) { return crosses(s, r); })) return r;
  }
  return std::nullopt;
}

Layout make_layout(const Plot& plot, double right) {
  Layout L;
  L.f.width = plot.width_px;
  L.f.panel_h = plot.panel_height_px;
  L.f.right = right;
  L.f.top = (plot.title.empty() ? 20 : 44) + 16.0 * static_cast<double>(plot.marks.size());
  Range xr;
  for (const auto& p : plot.panels) {
    for (const auto& s : p.series)
      for (double v : s.x) xr.add(v);
    for (const auto& a : p.areas)
      for (double v : a.x) xr.add(v);
  }
  for (const PlotMark& m : plot.marks) xr.add(m.x);
  xr = padded(xr);
  L.x = axis_ticks(xr.lo, xr.hi, 8, degrees(plot.x_scale, plot.x_label) ? AxisScale::degrees : AxisScale::linear, false);
  L.x_reversed = plot.x_reversed;
  for (std::size_t i = 0; i < plot.panels.size(); ++i) {
    const PlotPanel& p = plot.panels[i];
    Range yr;
    for (const auto& s : p.series)
      for (double v : s.y) yr.add(v);
    for (const auto& a : p.areas) {
      for (double v : a.y_low) yr.add(v);
      for (double v : a.y_high) yr.add(v);
    }
    yr = padded(yr);
    const AxisScale scale = degrees(p.y_scale, p.y_label) ? AxisScale::degrees : AxisScale::linear;
    L.panels.push_back({axis_ticks(yr.lo, yr.hi, 5, scale, true), L.f.panel_top(i)});
  }
  return L;
}

// Legends in free corners; when a panel has none, every legend of that kind goes into a column
// right of the panels (the layout is made again with room for it).
Layout place_legends(const Plot& plot) {
  Layout L = make_layout(plot, 20);
  std::vector<std::optional<Rect>> corner(plot.panels.size());
  bool all_inside = true;
  for (std::size_t i = 0; i < plot.panels.size(); ++i) {
    if (plot.panels[i].series.empty()) continue;
    corner[i] = free_corner(plot, L, i);
    all_inside = all_inside && corner[i].has_value();
  }
  if (!all_inside) {
    double w = 0;
    for (const PlotPanel& p : plot.panels) w = std::max(w, legend_size(p).w);
    L = make_layout(plot, w + 30);
    for (std::size_t i = 0; i < plot.panels.size(); ++i)
      if (!plot.panels[i].series.empty()) corner[i] = free_corner(plot, L, i);
  }
  for (std::size_t i = 0; i < plot.panels.size(); ++i) {
    const Rect size = legend_size(plot.panels[i]);
    L.legends.push_back(corner[i].value_or(Rect{L.f.width - L.f.right + 10, L.panels[i].y0, size.w, size.h}));
  }
  return L;
}

std::string grid_and_ticks(const Plot& plot, const Layout& L, std::size_t pi) {
  const Panel& g = L.panels[pi];
  const double h = L.f.panel_h, y0 = g.y0, left = L.f.left, w = L.f.plot_w();
  std::string svg;
  for (std::size_t i = 0; i < L.x.values.size(); ++i) {
    const double X = L.X(L.x.values[i]);
    svg += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{0:.2f}\" y2=\"{2:.2f}\" stroke=\"#ddd\"/>\n", X, y0, y0 + h);
    svg += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"middle\">{}</text>\n", X, y0 + h + 15,
                       xml_escape(L.x.labels[i]));
  }
  for (std::size_t i = 0; i < g.y.values.size(); ++i) {
    const double Y = g.Y(g.y.values[i], h);
    svg += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{2:.2f}\" y2=\"{1:.2f}\" stroke=\"#ddd\"/>\n", left, Y, left + w);
    svg += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"end\">{}</text>\n", left - 6, Y + 4,
                       xml_escape(g.y.labels[i]));
  }
  if (g.y.lo < 0 && g.y.hi > 0)
    svg += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{2:.2f}\" y2=\"{1:.2f}\" stroke=\"#888\"/>\n", left,
                       g.Y(0, h), left + w);
  svg += fmt::format("<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"none\" stroke=\"#444\"/>\n",
                     left, y0, w, h);
  svg += fmt::format("<text transform=\"translate({:.2f},{:.2f}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n", 18.0,
                     y0 + h / 2, xml_escape(plot.panels[pi].y_label));
  return svg;
}

// Shaded areas under the curves, so the lines stay visible on top.
std::string areas(const PlotPanel& panel, const Layout& L, const Panel& g) {
  const double h = L.f.panel_h;
  std::string svg;
  for (const auto& a : panel.areas) {
    std::size_t m = std::min({a.x.size(), a.y_low.size(), a.y_high.size()});
    if (m < 2) continue;
    std::string d;
    for (std::size_t i = 0; i < m; ++i) d += fmt::format("{}{:.2f},{:.2f}", i ? " L" : "M", L.X(a.x[i]), g.Y(a.y_high[i], h));
    for (std::size_t i = m; i-- > 0;) d += fmt::format(" L{:.2f},{:.2f}", L.X(a.x[i]), g.Y(a.y_low[i], h));
    svg += fmt::format("<path d=\"{} Z\" fill=\"{}\" fill-opacity=\"0.35\" stroke=\"none\"/>\n", d, a.color);
    if (a.label.empty()) continue;
    double cx = 0, cy = 0, wsum = 0;
    for (std::size_t i = 0; i < m; ++i) {
      const double weight = std::abs(a.y_high[i] - a.y_low[i]);
      cx += a.x[i] * weight;
      cy += 0.5 * (a.y_high[i] + a.y_low[i]) * weight;
      wsum += weight;
    }
    if (wsum > 0)
      svg += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"middle\" font-weight=\"bold\">{}</text>\n",
                         L.X(cx / wsum), g.Y(cy / wsum, h) + 4, xml_escape(a.label));
  }
  return svg;
}

// Series (a non-finite value breaks the line) and their legend.
std::string series(const PlotPanel& panel, const Layout& L, const Panel& g, const Rect& legend) {
  const double h = L.f.panel_h;
  std::string svg, keys;
  for (std::size_t si = 0; si < panel.series.size(); ++si) {
    const Series& s = panel.series[si];
    const std::string color = s.color.empty() ? kPalette[si % kPalette.size()] : s.color;
    std::string d;
    bool pen_down = false;
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
        pen_down = false;
        continue;
      }
      d += fmt::format("{}{:.2f},{:.2f}", pen_down ? " L" : (d.empty() ? "M" : " M"), L.X(s.x[i]), g.Y(s.y[i], h));
      pen_down = true;
    }
    if (!d.empty())
      svg += fmt::format("<path class=\"series\" d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.5\"/>\n", d, color);
    const double ky = legend.y + 12 + 16.0 * static_cast<double>(si);
    keys += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{2:.2f}\" y2=\"{1:.2f}\" stroke=\"{3}\" stroke-width=\"2\"/>"
                        "<text x=\"{4:.2f}\" y=\"{5:.2f}\">{6}</text>\n",
                        legend.x + 6, ky, legend.x + 26, color, legend.x + 32, ky + 4, xml_escape(s.name));
  }
  if (!panel.series.empty())
    svg += fmt::format("<rect class=\"legend\" x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"white\" "
                       "fill-opacity=\"0.85\" stroke=\"#bbb\"/>\n{}",
                       legend.x, legend.y, legend.w, legend.h, keys);
  return svg;
}

// Marks: a dashed line through every panel, a marker on the first panel's top edge and the note
// on a row of its own above the panels.
std::string marks(const Plot& plot, const Layout& L) {
  std::string svg;
  if (L.panels.empty()) return svg;
  const double top = L.panels.front().y0, bottom = L.panels.back().y0 + L.f.panel_h;
  for (std::size_t i = 0; i < plot.marks.size(); ++i) {
    const PlotMark& m = plot.marks[i];
    const double X = L.X(m.x), row = top - 8 - 16.0 * static_cast<double>(plot.marks.size() - 1 - i);
    svg += fmt::format("<line class=\"mark\" x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{0:.2f}\" y2=\"{2:.2f}\" stroke=\"{3}\" "
                       "stroke-width=\"1.2\" stroke-dasharray=\"5 3\"/>\n",
                       X, row + 4, bottom, m.color);
    svg += fmt::format("<path d=\"M{0:.2f},{1:.2f} l-5,-8 h10 Z\" fill=\"{2}\"/>\n", X, top, m.color);
    const bool right_half = X > L.f.left + 0.6 * L.f.plot_w();
    svg += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"{}\" fill=\"{}\">{}</text>\n", right_half ? X - 4 : X + 4,
                       row, right_half ? "end" : "start", m.color, xml_escape(m.note));
  }
  return svg;
}

}  // namespace

std::string tick_label(double v, double step, double magnitude) {
  if (std::abs(v) < step * 1e-9) v = 0;
  int exponent = 0;
  if (v != 0 && (magnitude >= 1e4 || (magnitude > 0 && magnitude < 1e-2)))
    exponent = std::clamp(static_cast<int>(std::floor(std::log10(std::abs(v)) / 3.0)) * 3, -12, 12);
  static constexpr std::array<const char*, 9> kPrefix = {"p", "n", "µ", "m", "", "k", "M", "G", "T"};
  const double scale = std::pow(10.0, exponent);
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step / scale) + 1e-9)));
  std::string s = fmt::format("{:.{}f}", v / scale, std::min(decimals, 6));
  if (s.front() == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s + kPrefix[static_cast<std::size_t>(exponent / 3 + 4)];
}

AxisTicks axis_ticks(double lo, double hi, int target, AxisScale scale, bool widen) {
  AxisTicks t;
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo)) lo = 0, hi = 1;
  t.step = scale == AxisScale::degrees ? angle_step(hi - lo, target) : nice_step(hi - lo, target);
  if (widen) {
    lo = std::floor(lo / t.step) * t.step;
    hi = std::ceil(hi / t.step) * t.step;
  }
  t.lo = lo;
  t.hi = hi;
  double magnitude = 0;
  for (double v = std::ceil(lo / t.step) * t.step; v <= hi + 1e-9 * t.step; v += t.step) {
    t.values.push_back(std::abs(v) < t.step * 1e-9 ? 0.0 : v);
    magnitude = std::max(magnitude, std::abs(v));
  }
  for (double v : t.values) t.labels.push_back(tick_label(v, t.step, magnitude));
  return t;
}

std::string to_svg(const Plot& plot) {
  const Layout L = place_legends(plot);
  const std::size_t n = plot.panels.size();
  const double height = L.f.top + static_cast<double>(n) * L.f.panel_h + (n > 0 ? static_cast<double>(n - 1) * L.f.gap : 0) +
                        L.f.bottom;
  std::string svg = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" height=\"{1:.0f}\" viewBox=\"0 0 {0:.0f} {1:.0f}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      L.f.width, height);
  if (!plot.title.empty())
    svg += fmt::format("<text x=\"{:.1f}\" y=\"24\" text-anchor=\"middle\" font-size=\"16\">{}</text>\n", L.f.width / 2,
                       xml_escape(plot.title));
  for (std::size_t pi = 0; pi < n; ++pi) {
    svg += "<g>\n" + grid_and_ticks(plot, L, pi) + areas(plot.panels[pi], L, L.panels[pi]) +
           series(plot.panels[pi], L, L.panels[pi], L.legends[pi]) + "</g>\n";
  }
  svg += marks(plot, L);
  svg += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"middle\">{}</text>\n", L.f.left + L.f.plot_w() / 2,
                     height - 12, xml_escape(plot.x_label));
  svg += "</svg>\n";
  return svg;
}

}  // namespace gearkit::io
