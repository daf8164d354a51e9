// Biarc fitting and arc-spline utilities in double precision (the exact offset is in offset_cgal.cpp).
#include <gearkit/cam/arc_spline.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace gearkit::cam {

namespace {
constexpr double pi = std::numbers::pi;

double wrap_pi(double a) { return std::remainder(a, 2 * pi); }
}  // namespace

Direction Direction::from_angle(double angle_rad) {
  const double a = wrap_pi(angle_rad);
  Direction d;
  if (std::abs(a) <= pi / 2) {
    d.m = std::tan(a / 2);
  } else {
    d.reversed = true;
    d.m = std::tan(wrap_pi(a - pi) / 2);
  }
  return d;
}

double Direction::x() const { return (reversed ? -1 : 1) * (1 - m * m) / (1 + m * m); }
double Direction::y() const { return (reversed ? -1 : 1) * 2 * m / (1 + m * m); }
double Direction::angle() const { return wrap_pi(2 * std::atan(m) + (reversed ? pi : 0)); }

double turning_angle(double ax, double ay, double bx, double by, double sign) {
  double delta = std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  if (sign > 0 && delta < 0) delta += 2 * pi;
  if (sign < 0 && delta > 0) delta -= 2 * pi;
  return delta;
}

namespace {

/// The two pieces of a biarc (see add_biarc in offset_cgal.cpp for the equations), in doubles.
void biarc_pieces(const Knot& a, const Knot& b, const Direction& joint, std::vector<Piece>& out) {
  const double t0x = a.tangent.x(), t0y = a.tangent.y(), t1x = b.tangent.x(), t1y = b.tangent.y();
  const double wx = joint.x(), wy = joint.y();
  const double rx = b.y - a.y, ry = -(b.x - a.x);
  const double ux = t0x - wx, uy = t0y - wy, vx = wx - t1x, vy = wy - t1y;
  const double det = ux * vy - uy * vx;
  if (det == 0) {
    out.push_back({a.x, a.y, b.x, b.y, 0, 0, 0, 0});
    return;
  }
  const double RA = (rx * vy - ry * vx) / det;
  const double RB = (ux * ry - uy * rx) / det;
  const double cAx = a.x - RA * t0y, cAy = a.y + RA * t0x;
  const double mx = cAx + RA * wy, my = cAy - RA * wx;
  const double cBx = mx - RB * wy, cBy = my + RB * wx;
  out.push_back({a.x, a.y, mx, my, cAx, cAy, RA, turning_angle(t0x, t0y, wx, wy, RA)});
  out.push_back({mx, my, b.x, b.y, cBx, cBy, RB, turning_angle(wx, wy, t1x, t1y, RB)});
}

Knot knot_at(const std::function<CurvePoint(double)>& curve, double t) {
  const CurvePoint p = curve(t);
  return {p.x, p.y, Direction::from_angle(std::atan2(p.ty, p.tx))};
}

/// The joint tangent that makes the biarc a single arc when the data lie on a circle:
/// angle(w) = 2 angle(chord) - (angle(t0) + angle(t1)) / 2.
Direction joint_for(const Knot& a, const Knot& b) {
  const double chord = std::atan2(b.y - a.y, b.x - a.x);
  const double a0 = a.tangent.angle();
  const double a1 = a0 + wrap_pi(b.tangent.angle() - a0);
  return Direction::from_angle(2 * chord - 0.5 * (a0 + a1));
}

double biarc_error(const std::function<CurvePoint(double)>& curve, double ta, double tb,
                   const std::vector<Piece>& pieces) {
  double worst = 0;
  for (int i = 1; i <= 5; ++i) {
    const CurvePoint p = curve(ta + (tb - ta) * i / 6.0);
    double d = INFINITY;
    for (const Piece& piece : pieces) d = std::min(d, distance_to_piece(piece, p.x, p.y));
    worst = std::max(worst, d);
  }
  for (const Piece& piece : pieces)  // a biarc that loops is wrong even if it passes near the points
    if (std::abs(piece.sweep) > pi / 2) worst = INFINITY;
  return worst;
}

void fit_interval(const std::function<CurvePoint(double)>& curve, double ta, double tb, const Knot& ka,
                  const Knot& kb, const FitOptions& options, int depth, BiarcSpline& out) {
  const Direction joint = joint_for(ka, kb);
  std::vector<Piece> pieces;
  biarc_pieces(ka, kb, joint, pieces);
  if (biarc_error(curve, ta, tb, pieces) <= options.tolerance) {
    out.joints.push_back(joint);
    out.knots.push_back(kb);
    return;
  }
  if (depth >= options.max_depth) {
    throw GeometryError("cannot fit arcs to the curve near parameter " + std::to_string(0.5 * (ta + tb)) +
                        " (a cusp or corner?)");
  }
  const double tm = 0.5 * (ta + tb);
  const Knot km = knot_at(curve, tm);
  fit_interval(curve, ta, tm, ka, km, options, depth + 1, out);
  fit_interval(curve, tm, tb, km, kb, options, depth + 1, out);
}

}  // namespace

BiarcSpline fit_biarcs(const std::function<CurvePoint(double)>& curve, std::vector<double> breaks,
                       const FitOptions& options, bool closed) {
  std::sort(breaks.begin(), breaks.end());
  // Breaks that differ by rounding only would make a biarc with no length and a random chord.
  const double span = breaks.empty() ? 0 : breaks.back() - breaks.front();
  breaks.erase(std::unique(breaks.begin(), breaks.end(), [&](double a, double b) { return b - a <= 1e-9 * span; }),
               breaks.end());
  if (breaks.size() < 2) throw GeometryError("fit_biarcs: the parameter range is empty");
  BiarcSpline spline;
  const Knot first = knot_at(curve, breaks.front());
  spline.knots.push_back(first);
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const bool last = i + 2 == breaks.size();
    const Knot kb = closed && last ? first : knot_at(curve, breaks[i + 1]);
    fit_interval(curve, breaks[i], breaks[i + 1], spline.knots.back(), kb, options, 0, spline);
  }
  return spline;
}

std::vector<Piece> pieces_of(const BiarcSpline& spline) {
  std::vector<Piece> out;
  for (std::size_t k = 0; k + 1 < spline.knots.size(); ++k) {
    std::vector<Piece> two;
    biarc_pieces(spline.knots[k], spline.knots[k + 1], spline.joints[k], two);
    for (const Piece& p : two)
      if (p.x0 != p.x1 || p.y0 != p.y1) out.push_back(p);
  }
  return out;
}

double distance_to_piece(const Piece& p, double x, double y) {
  if (!p.is_arc()) {
    const double dx = p.x1 - p.x0, dy = p.y1 - p.y0;
    const double len2 = dx * dx + dy * dy;
    const double t = len2 == 0 ? 0 : std::clamp(((x - p.x0) * dx + (y - p.y0) * dy) / len2, 0.0, 1.0);
    return std::hypot(x - (p.x0 + t * dx), y - (p.y0 + t * dy));
  }
  const double start = std::atan2(p.y0 - p.cy, p.x0 - p.cx);
  double rel = std::atan2(y - p.cy, x - p.cx) - start;
  rel = p.sweep > 0 ? std::fmod(std::fmod(rel, 2 * pi) + 2 * pi, 2 * pi)
                    : -std::fmod(std::fmod(-rel, 2 * pi) + 2 * pi, 2 * pi);
  if (std::abs(rel) <= std::abs(p.sweep)) return std::abs(std::hypot(x - p.cx, y - p.cy) - std::abs(p.radius));
  return std::min(std::hypot(x - p.x0, y - p.y0), std::hypot(x - p.x1, y - p.y1));
}

namespace {

bool mergeable(const Piece& a, const Piece& b, double rel_tol) {
  if (a.is_arc() != b.is_arc()) return false;
  if (!a.is_arc()) {
    const double cross = (a.x1 - a.x0) * (b.y1 - b.y0) - (a.y1 - a.y0) * (b.x1 - b.x0);
    const double la = std::hypot(a.x1 - a.x0, a.y1 - a.y0), lb = std::hypot(b.x1 - b.x0, b.y1 - b.y0);
    const double dot = (a.x1 - a.x0) * (b.x1 - b.x0) + (a.y1 - a.y0) * (b.y1 - b.y0);
    return dot > 0 && std::abs(cross) <= rel_tol * la * lb;
  }
  const double r = std::abs(a.radius);
  return (a.radius > 0) == (b.radius > 0) && std::abs(a.radius - b.radius) <= rel_tol * r &&
         std::hypot(a.cx - b.cx, a.cy - b.cy) <= rel_tol * r && std::abs(a.sweep + b.sweep) <= 1.5 * pi;
}

Piece joined(const Piece& a, const Piece& b) {
  Piece m = a;
  m.x1 = b.x1;
  m.y1 = b.y1;
  m.sweep = a.sweep + b.sweep;
  return m;
}

}  // namespace

std::vector<Piece> merge_pieces(const std::vector<Piece>& pieces, double rel_tol) {
  std::vector<Piece> out;
  for (const Piece& p : pieces) {
    if (!out.empty() && mergeable(out.back(), p, rel_tol))
      out.back() = joined(out.back(), p);
    else
      out.push_back(p);
  }
  // A closed chain may start in the middle of an arc: join its two ends too.
  if (out.size() > 2 && out.back().x1 == out.front().x0 && out.back().y1 == out.front().y0 &&
      mergeable(out.back(), out.front(), rel_tol)) {
    out.front() = joined(out.back(), out.front());
    out.pop_back();
  }
  return out;
}

std::vector<BulgeVertex> bulge_vertices(const std::vector<Piece>& loop) {
  std::vector<BulgeVertex> out;
  for (const Piece& p : merge_pieces(loop)) out.push_back({p.x0, p.y0, p.is_arc() ? std::tan(p.sweep / 4) : 0.0});
  return out;
}

}  // namespace gearkit::cam
