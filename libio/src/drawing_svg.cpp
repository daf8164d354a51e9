// SVG writer: one <g> per layer, coordinates in millimetres with y flipped (the drawing's y points
// up, SVG's down), so that the picture a browser shows is the picture a CAD program shows.
#include <gearkit/io/drawing.hpp>

#include "drawing_geometry.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>
#include <gearkit/io/xml.hpp>

namespace gearkit::io {
namespace {

/// Coordinates with 4 decimals (0.1 micrometre), enough for any drawing and compact.
/// An XML id from a layer name ("pitch curve" -> "layer-pitch_curve").
std::string layer_id(const std::string& name) {
  std::string id = "layer-";
  for (char c : name) id += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
  if (name.empty()) id += '0';
  return id;
}

std::string num(double v) {
  if (!std::isfinite(v)) throw std::invalid_argument("to_svg: non-finite coordinate in drawing");
  std::string s = fmt::format("{:.4f}", v);
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

std::string point(double x, double y) { return fmt::format("{},{}", num(x), num(-y)); }

/// SVG arc command to `to`. A counter-clockwise arc in the drawing (y up) is drawn with
/// sweep-flag 0 in SVG's y-down frame.
std::string arc_command(double r, double sweep_deg, bool ccw, double x, double y) {
  return fmt::format("A{} {} 0 {} {} {}", num(r), num(r), std::abs(sweep_deg) > 180 ? 1 : 0, ccw ? 0 : 1,
                     point(x, y));
}

std::string polyline_path(const Polyline& p) {
  std::string d = fmt::format("M{}", point(p.vertices.front().x, p.vertices.front().y));
  for_each_segment(p, [&](const Vertex& a, const Vertex& b) {
    if (a.bulge == 0 || (a.x == b.x && a.y == b.y)) {
      d += fmt::format(" L{}", point(b.x, b.y));
    } else {
      const Arc arc = arc_of_bulge(a, b);
      d += ' ';
      d += arc_command(arc.r, 4 * std::atan(a.bulge) * 180 / std::numbers::pi, a.bulge > 0, b.x, b.y);
    }
  });
  if (p.closed) d += " Z";
  return d;
}

std::string arc_path(const Arc& a) {
  const double rad = std::numbers::pi / 180;
  double sweep = std::fmod(std::fmod(a.end_deg - a.start_deg, 360) + 360, 360);
  if (sweep == 0) sweep = 360;
  const double x0 = a.cx + a.r * std::cos(a.start_deg * rad), y0 = a.cy + a.r * std::sin(a.start_deg * rad);
  if (sweep >= 360) {  // a full turn needs two half arcs in SVG
    const double xm = 2 * a.cx - x0, ym = 2 * a.cy - y0;
    return fmt::format("M{} {} {}", point(x0, y0), arc_command(a.r, 180, true, xm, ym),
                       arc_command(a.r, 180, true, x0, y0));
  }
  const double x1 = a.cx + a.r * std::cos((a.start_deg + sweep) * rad);
  const double y1 = a.cy + a.r * std::sin((a.start_deg + sweep) * rad);
  return fmt::format("M{} {}", point(x0, y0), arc_command(a.r, sweep, true, x1, y1));
}

struct LayerOut {
  const Layer* style = nullptr;
  std::string body;
};

}  // namespace

std::string to_svg(const Drawing& drawing, const SvgOptions& options) {
  std::map<std::string, LayerOut> layers;
  std::vector<std::string> order;  // layers in the order the drawing lists them, then by first use
  auto layer = [&](const std::string& name) -> LayerOut& {
    auto [it, inserted] = layers.try_emplace(name);
    if (inserted) order.push_back(name);
    return it->second;
  };
  for (const Layer& l : drawing.layers) layer(l.name).style = &l;

  Extents e;
  for (const Polyline& p : drawing.polylines) {
    if (p.vertices.empty()) continue;
    for_each_segment(p, [&](const Vertex& a, const Vertex& b) { e.add_segment(a, b); });
    for (const Vertex& v : p.vertices) e.add(v.x, v.y);
    layer(p.layer).body += fmt::format("    <path d=\"{}\"/>\n", polyline_path(p));
  }
  for (const Line& l : drawing.lines) {
    e.add(l.x1, l.y1);
    e.add(l.x2, l.y2);
    layer(l.layer).body += fmt::format("    <line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>\n", num(l.x1), num(-l.y1),
                                       num(l.x2), num(-l.y2));
  }
  for (const Circle& c : drawing.circles) {
    e.add(c.cx - c.r, c.cy - c.r);
    e.add(c.cx + c.r, c.cy + c.r);
    layer(c.layer).body +=
        fmt::format("    <circle cx=\"{}\" cy=\"{}\" r=\"{}\"/>\n", num(c.cx), num(-c.cy), num(c.r));
  }
  for (const Arc& a : drawing.arcs) {
    e.add_arc(a);
    layer(a.layer).body += fmt::format("    <path d=\"{}\"/>\n", arc_path(a));
  }
  for (const Text& t : drawing.texts) {
    e.add(t.x, t.y);
    e.add(t.x + 0.6 * t.height * static_cast<double>(t.text.size()), t.y + t.height);
    layer(t.layer).body += fmt::format(
        "    <text x=\"{}\" y=\"{}\" font-size=\"{}\" font-family=\"sans-serif\" stroke=\"none\" "
        "fill=\"currentColor\">{}</text>\n",
        num(t.x), num(-t.y), num(t.height > 0 ? t.height : 2.5), xml_escape(t.text));
  }
  if (e.empty()) e = Extents{0, 0, 100, 100};

  const double m = options.margin_mm;
  const double width = e.xmax - e.xmin + 2 * m, height = e.ymax - e.ymin + 2 * m;
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}mm\" height=\"{}mm\" viewBox=\"{} {} {} {}\">\n",
      num(width), num(height), num(e.xmin - m), num(-e.ymax - m), num(width), num(height));
  if (!options.title.empty()) out += fmt::format("  <title>{}</title>\n", xml_escape(options.title));
  out += fmt::format("  <rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"white\"/>\n", num(e.xmin - m),
                     num(-e.ymax - m), num(width), num(height));
  for (const std::string& name : order) {
    const LayerOut& l = layers.at(name);
    if (l.body.empty()) continue;
    const std::string color = l.style ? l.style->svg_color : "#000";
    std::string dash;
    if (l.style && l.style->dashed) {
      dash = fmt::format(" stroke-dasharray=\"{} {}\"", num(12 * options.stroke_mm), num(6 * options.stroke_mm));
    }
    out += fmt::format(
        "  <g id=\"{}\" fill=\"none\" stroke=\"{}\" color=\"{}\" stroke-width=\"{}\" stroke-linecap=\"round\" "
        "stroke-linejoin=\"round\"{}>\n",
        layer_id(name), xml_escape(color), xml_escape(color), num(options.stroke_mm), dash);
    out += l.body;
    out += "  </g>\n";
  }
  out += "</svg>\n";
  return out;
}

}  // namespace gearkit::io
