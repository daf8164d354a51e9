// The raw offset of an arc spline, used as the offset when it provably does not cross itself.
#include "simple_offset.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace gearkit::cam::detail {
namespace {

constexpr double pi = std::numbers::pi;

struct Point {
  double x = 0, y = 0;
};

/// Unit tangent of an arc (signed radius R) at its point p: J(p - c) / R.
Point arc_tangent(const Piece& a, double px, double py) { return {-(py - a.cy) / a.radius, (px - a.cx) / a.radius}; }

/// The arc's offset end point: c + (R - d) / R (p - c).
Point moved(const Piece& a, double px, double py, double d) {
  const double k = (a.radius - d) / a.radius;
  return {a.cx + k * (px - a.cx), a.cy + k * (py - a.cy)};
}

/// Whether angle `a` (of a point seen from an arc's centre) lies within the arc's sweep.
bool within(const Piece& arc, double x, double y) {
  const double start = std::atan2(arc.y0 - arc.cy, arc.x0 - arc.cx);
  const double rel = std::remainder(std::atan2(y - arc.cy, x - arc.cx) - start - 0.5 * arc.sweep, 2 * pi);
  return std::abs(rel) <= 0.5 * std::abs(arc.sweep) + 1e-12;
}

/// Smallest distance between two arcs: their end points against the other arc, their
/// intersections, and the interior pairs on the line of centres (where both normals meet).
double arc_distance(const Piece& a, const Piece& b) {
  double best = std::min({distance_to_piece(b, a.x0, a.y0), distance_to_piece(b, a.x1, a.y1),
                          distance_to_piece(a, b.x0, b.y0), distance_to_piece(a, b.x1, b.y1)});
  const double ra = std::abs(a.radius), rb = std::abs(b.radius);
  const double dx = b.cx - a.cx, dy = b.cy - a.cy, dc = std::hypot(dx, dy);
  if (dc == 0) return best;  // concentric: closest points are the ends
  const double ux = dx / dc, uy = dy / dc;
  if (dc <= ra + rb && dc >= std::abs(ra - rb)) {  // the circles cross: where?
    const double along = (dc * dc + ra * ra - rb * rb) / (2 * dc), h = std::sqrt(std::max(0.0, ra * ra - along * along));
    for (double s : {-1.0, 1.0}) {
      const double x = a.cx + along * ux - s * h * uy, y = a.cy + along * uy + s * h * ux;
      if (within(a, x, y) && within(b, x, y)) return 0;
    }
  }
  for (double sa : {-1.0, 1.0})
    for (double sb : {-1.0, 1.0}) {
      const double xa = a.cx + sa * ra * ux, ya = a.cy + sa * ra * uy, xb = b.cx + sb * rb * ux, yb = b.cy + sb * rb * uy;
      if (within(a, xa, ya) && within(b, xb, yb)) best = std::min(best, std::hypot(xa - xb, ya - yb));
    }
  return best;
}

/// Axis-aligned box of an arc: its ends and the axis points its sweep passes.
std::array<double, 4> box(const Piece& a) {
  std::array<double, 4> b{std::min(a.x0, a.x1), std::min(a.y0, a.y1), std::max(a.x0, a.x1), std::max(a.y0, a.y1)};
  const double r = std::abs(a.radius);
  const Point axes[4] = {{a.cx + r, a.cy}, {a.cx, a.cy + r}, {a.cx - r, a.cy}, {a.cx, a.cy - r}};
  for (const Point& p : axes)
    if (within(a, p.x, p.y)) b = {std::min(b[0], p.x), std::min(b[1], p.y), std::max(b[2], p.x), std::max(b[3], p.y)};
  return b;
}

/// Whether two pieces that are not neighbours come within `gap` of each other.
bool any_close_pair(const std::vector<Piece>& loop, double gap) {
  std::vector<std::array<double, 4>> boxes;
  for (const Piece& p : loop) boxes.push_back(box(p));
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j + 1 == n) continue;  // neighbours across the closing point
      const auto &p = boxes[i], &q = boxes[j];
      if (p[0] > q[2] + gap || q[0] > p[2] + gap || p[1] > q[3] + gap || q[1] > p[3] + gap) continue;
      if (arc_distance(loop[i], loop[j]) < gap) return true;
    }
  return false;
}

/// Twice the signed area enclosed by a closed chain of arcs (chords plus circular segments).
double twice_area(const std::vector<Piece>& loop) {
  double a = 0;
  for (const Piece& p : loop) {
    a += p.x0 * p.y1 - p.x1 * p.y0;
    a += p.radius * p.radius * (p.sweep - std::sin(p.sweep));  // segment between chord and arc, signed by the sweep
  }
  return a;
}

/// The arc about a corner of the chain at (x, y), from `from` to `to` (the offsets of its two
/// sides), turning by `turn`.
Piece corner_arc(double x, double y, Point from, Point to, double distance, double turn) {
  return {from.x, from.y, to.x, to.y, x, y, turn > 0 ? std::abs(distance) : -std::abs(distance), turn};
}

}  // namespace

std::optional<std::vector<Piece>> simple_raw_offset(const std::vector<Piece>& pieces, double distance) {
  double scale = 0;
  for (const Piece& p : pieces) {
    if (!p.is_arc()) return std::nullopt;
    const double r = p.radius - distance;
    if (r == 0 || (r > 0) != (p.radius > 0)) return std::nullopt;  // turns inside out: a fold
    scale = std::max({scale, std::abs(p.x0), std::abs(p.y0)});
  }
  std::vector<Piece> out;
  const std::size_t n = pieces.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Piece& a = pieces[i];
    const Piece& b = pieces[(i + 1) % n];
    Piece m = a;
    m.radius = a.radius - distance;
    const Point s = moved(a, a.x0, a.y0, distance), e = moved(a, a.x1, a.y1, distance);
    m.x0 = out.empty() ? s.x : out.back().x1, m.y0 = out.empty() ? s.y : out.back().y1;
    m.x1 = e.x, m.y1 = e.y;
    out.push_back(m);
    const Point ta = arc_tangent(a, a.x1, a.y1), tb = arc_tangent(b, b.x0, b.y0);
    const double turn = std::atan2(ta.x * tb.y - ta.y * tb.x, ta.x * tb.x + ta.y * tb.y);
    if (std::abs(turn) <= 1e-9) continue;  // smooth: the next offset piece starts here
    if (turn * distance > 0) return std::nullopt;  // the offsets of the two sides overlap: a fold
    out.push_back(corner_arc(a.x1, a.y1, e, moved(b, b.x0, b.y0, distance), distance, turn));
  }
  out.front().x0 = out.back().x1, out.front().y0 = out.back().y1;  // close exactly
  if (any_close_pair(out, 1e-6 * std::max(scale, 1.0)) || !(twice_area(out) > 0)) return std::nullopt;
  return out;
}

}  // namespace gearkit::cam::detail
