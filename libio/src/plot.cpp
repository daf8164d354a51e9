#include <gearkit/io/plot.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <gearkit/io/xml.hpp>

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

Range padded(Range r) {
  if (r.empty()) return {0, 1};
  if (r.hi - r.lo < 1e-12 * std::max(1.0, std::abs(r.hi))) {
    double d = std::max(1.0, std::abs(r.hi)) * 0.5;
    return {r.lo - d, r.hi + d};
  }
  return r;
}

std::string tick_label(double v, double step) {
  if (std::abs(v) < step * 1e-9) v = 0;
  int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
  if (std::abs(v) >= 1e5 || (std::abs(v) < 1e-3 && v != 0)) return fmt::format("{:.3g}", v);
  return fmt::format("{:.{}f}", v, decimals);
}

/// The mapping of one panel from data to SVG coordinates.
struct Frame {
  double left, plot_w, y0, ph;
  Range xr, yr;
  double xstep, ystep;
  double X(double x) const { return left + (x - xr.lo) / (xr.hi - xr.lo) * plot_w; }
  double Y(double y) const { return y0 + ph - (y - yr.lo) / (yr.hi - yr.lo) * ph; }
};

/// The x range of every panel's series and areas, padded.
Range x_range(const Plot& plot) {
  Range xr;
  for (const auto& p : plot.panels) {
    for (const auto& s : p.series)
      for (double v : s.x) xr.add(v);
    for (const auto& a : p.areas)
      for (double v : a.x) xr.add(v);
  }
  return padded(xr);
}

/// The y range of one panel, padded and rounded out to its tick step.
Range y_range(const PlotPanel& panel, double& ystep) {
  Range yr;
  for (const auto& s : panel.series)
    for (double v : s.y) yr.add(v);
  for (const auto& a : panel.areas) {
    for (double v : a.y_low) yr.add(v);
    for (double v : a.y_high) yr.add(v);
  }
  yr = padded(yr);
  ystep = nice_step(yr.hi - yr.lo, 5);
  yr.lo = std::floor(yr.lo / ystep) * ystep;
  yr.hi = std::ceil(yr.hi / ystep) * ystep;
  return yr;
}

/// Grid lines, tick labels, the zero line, the frame and the y label of a panel.
std::string panel_grid(const Frame& f, const std::string& y_label) {
  std::string svg;
  for (double t = std::ceil(f.xr.lo / f.xstep) * f.xstep; t <= f.xr.hi + 1e-9 * f.xstep; t += f.xstep) {
    svg += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{0:.2f}\" y2=\"{2:.2f}\" stroke=\"#ddd\"/>\n", f.X(t),
                       f.y0, f.y0 + f.ph);
    svg += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"middle\">{}</text>\n", f.X(t), f.y0 + f.ph + 15,
                       tick_label(t, f.xstep));
  }
  for (double t = f.yr.lo; t <= f.yr.hi + 1e-9 * f.ystep; t += f.ystep) {
    svg += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{2:.2f}\" y2=\"{1:.2f}\" stroke=\"#ddd\"/>\n", f.left,
                       f.Y(t), f.left + f.plot_w);
    svg += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"end\">{}</text>\n", f.left - 6, f.Y(t) + 4,
                       tick_label(t, f.ystep));
  }
  if (f.yr.lo < 0 && f.yr.hi > 0)
    svg += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{2:.2f}\" y2=\"{1:.2f}\" stroke=\"#888\"/>\n", f.left,
                       f.Y(0), f.left + f.plot_w);
  svg += fmt::format("<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"none\" stroke=\"#444\"/>\n",
                     f.left, f.y0, f.plot_w, f.ph);
  svg += fmt::format(
      "<text transform=\"translate({:.2f},{:.2f}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n", 18.0,
      f.y0 + f.ph / 2, xml_escape(y_label));
  return svg;
}

/// A shaded area, with its label at the area's centroid.
std::string area_svg(const Frame& f, const ShadedArea& a) {
  std::size_t m = std::min({a.x.size(), a.y_low.size(), a.y_high.size()});
  if (m < 2) return {};
  std::string d;
  for (std::size_t i = 0; i < m; ++i) d += fmt::format("{}{:.2f},{:.2f}", i ? " L" : "M", f.X(a.x[i]), f.Y(a.y_high[i]));
  for (std::size_t i = m; i-- > 0;) d += fmt::format(" L{:.2f},{:.2f}", f.X(a.x[i]), f.Y(a.y_low[i]));
  std::string svg = fmt::format("<path d=\"{} Z\" fill=\"{}\" fill-opacity=\"0.35\" stroke=\"none\"/>\n", d, a.color);
  if (a.label.empty()) return svg;
  double cx = 0, cy = 0, wsum = 0;
  for (std::size_t i = 0; i < m; ++i) {
    double h = std::abs(a.y_high[i] - a.y_low[i]);
    cx += a.x[i] * h;
    cy += 0.5 * (a.y_high[i] + a.y_low[i]) * h;
    wsum += h;
  }
  if (wsum > 0) {
    svg += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"middle\" font-weight=\"bold\">{}</text>\n",
                       f.X(cx / wsum), f.Y(cy / wsum) + 4, xml_escape(a.label));
  }
  return svg;
}

/// The line of series `si` (a non-finite value breaks it) and its legend entry.
std::string series_svg(const Frame& f, const Series& s, std::size_t si) {
  std::string color = s.color.empty() ? kPalette[si % kPalette.size()] : s.color;
  std::string d;
  bool pen_down = false;
  for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
    if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
      pen_down = false;
      continue;
    }
    d += fmt::format("{}{:.2f},{:.2f}", pen_down ? " L" : (d.empty() ? "M" : " M"), f.X(s.x[i]), f.Y(s.y[i]));
    pen_down = true;
  }
  std::string svg;
  if (!d.empty()) svg += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.5\"/>\n", d, color);
  svg += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{2:.2f}\" y2=\"{1:.2f}\" stroke=\"{3}\" stroke-width=\"2\"/>"
                     "<text x=\"{4:.2f}\" y=\"{5:.2f}\">{6}</text>\n",
                     f.left + 10, f.y0 + 14 + 16 * si, f.left + 30, color, f.left + 36, f.y0 + 18 + 16 * si,
                     xml_escape(s.name));
  return svg;
}

std::string panel_svg(const Frame& f, const PlotPanel& panel) {
  std::string svg = "<g>\n" + panel_grid(f, panel.y_label);
  // Shaded areas under the curves, so the lines stay visible on top.
  for (const auto& a : panel.areas) svg += area_svg(f, a);
  for (std::size_t si = 0; si < panel.series.size(); ++si) svg += series_svg(f, panel.series[si], si);
  return svg + "</g>\n";
}

}  // namespace

std::string to_svg(const Plot& plot) {
  const double left = 80, right = 20, top = plot.title.empty() ? 20 : 44, gap = 40, bottom = 50;
  const double w = plot.width_px, ph = plot.panel_height_px;
  const double plot_w = w - left - right;
  const std::size_t n = plot.panels.size();
  const double height = top + n * ph + (n > 0 ? (n - 1) * gap : 0) + bottom;
  const Range xr = x_range(plot);
  const double xstep = nice_step(xr.hi - xr.lo, 8);

  std::string svg = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" height=\"{1:.0f}\" viewBox=\"0 0 {0:.0f} {1:.0f}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      w, height);
  if (!plot.title.empty())
    svg += fmt::format("<text x=\"{:.1f}\" y=\"24\" text-anchor=\"middle\" font-size=\"16\">{}</text>\n", w / 2,
                       xml_escape(plot.title));
  for (std::size_t pi = 0; pi < n; ++pi) {
    double ystep = 1;
    const Range yr = y_range(plot.panels[pi], ystep);
    const Frame frame{left, plot_w, top + pi * (ph + gap), ph, xr, yr, xstep, ystep};
    svg += panel_svg(frame, plot.panels[pi]);
  }
  svg += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"middle\">{}</text>\n", left + plot_w / 2,
                     height - 12, xml_escape(plot.x_label));
  svg += "</svg>\n";
  return svg;
}

}  // namespace gearkit::io
