#pragma once
// Geometry shared by the DXF and SVG writers (private to libio): bulge arcs and extents.
#include <gearkit/io/drawing.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace gearkit::io {

/// The arc that a polyline segment with bulge b = tan(theta/4) describes from a to b.
/// Its centre lies on the chord's perpendicular bisector, at (1 - b^2)/(4 b) chord lengths to the
/// left of the chord direction; the radius is chord (1 + b^2)/(4 |b|). Requires a.bulge != 0 and a != b.
inline Arc arc_of_bulge(const Vertex& a, const Vertex& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double k = (1 - a.bulge * a.bulge) / (4 * a.bulge);
  Arc arc;
  arc.cx = 0.5 * (a.x + b.x) - dy * k;
  arc.cy = 0.5 * (a.y + b.y) + dx * k;
  arc.r = std::hypot(dx, dy) * (1 + a.bulge * a.bulge) / (4 * std::abs(a.bulge));
  const double deg = 180 / std::numbers::pi;
  const double angle_a = std::atan2(a.y - arc.cy, a.x - arc.cx) * deg;
  const double angle_b = std::atan2(b.y - arc.cy, b.x - arc.cx) * deg;
  // ARC entities run counter-clockwise: a clockwise bulge arc is the same arc from b to a.
  arc.start_deg = a.bulge > 0 ? angle_a : angle_b;
  arc.end_deg = a.bulge > 0 ? angle_b : angle_a;
  return arc;
}

/// Calls f(from, to) for every segment of the polyline, including the closing one.
template <class F>
void for_each_segment(const Polyline& p, F&& f) {
  const std::size_t n = p.vertices.size();
  if (n < 2) return;
  for (std::size_t i = 0; i + 1 < n; ++i) f(p.vertices[i], p.vertices[i + 1]);
  if (p.closed) f(p.vertices[n - 1], p.vertices[0]);
}

/// Whether the segment (x1, y1)-(x2, y2) has a point in the closed box [xmin, xmax] x [ymin, ymax]
/// (Liang-Barsky: the parameter interval left after clipping against each slab is not empty).
/// Shared by the plot's legend placement and the drawings' label placement.
inline bool segment_meets_box(double xmin, double ymin, double xmax, double ymax, double x1, double y1, double x2,
                              double y2) {
  double t0 = 0, t1 = 1;
  const double dx = x2 - x1, dy = y2 - y1;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {x1 - xmin, xmax - x1, y1 - ymin, ymax - y1};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;  // parallel to this edge and outside it
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  return true;
}

/// Axis-aligned bounding box.
struct Extents {
  double xmin = std::numeric_limits<double>::infinity(), ymin = std::numeric_limits<double>::infinity();
  double xmax = -std::numeric_limits<double>::infinity(), ymax = -std::numeric_limits<double>::infinity();

  bool empty() const { return !(xmin <= xmax && ymin <= ymax); }

  void add(double x, double y) {
    xmin = std::min(xmin, x);
    ymin = std::min(ymin, y);
    xmax = std::max(xmax, x);
    ymax = std::max(ymax, y);
  }

  /// Endpoints plus every quadrant point (0, 90, 180, 270 deg) the arc passes through.
  void add_arc(const Arc& a) {
    const double rad = std::numbers::pi / 180;
    add(a.cx + a.r * std::cos(a.start_deg * rad), a.cy + a.r * std::sin(a.start_deg * rad));
    add(a.cx + a.r * std::cos(a.end_deg * rad), a.cy + a.r * std::sin(a.end_deg * rad));
    const double start = std::fmod(std::fmod(a.start_deg, 360) + 360, 360);
    double sweep = std::fmod(std::fmod(a.end_deg - a.start_deg, 360) + 360, 360);
    if (sweep == 0) sweep = 360;
    for (int q = 0; q < 8; ++q) {  // two turns so that sweeps across 0 deg are covered
      const double angle = 90.0 * q;
      if (angle >= start && angle <= start + sweep) {
        add(a.cx + a.r * std::cos(angle * rad), a.cy + a.r * std::sin(angle * rad));
      }
    }
  }

  void add_segment(const Vertex& a, const Vertex& b) {
    add(a.x, a.y);
    add(b.x, b.y);
    if (a.bulge != 0 && (a.x != b.x || a.y != b.y)) add_arc(arc_of_bulge(a, b));
  }
};

}  // namespace gearkit::io
