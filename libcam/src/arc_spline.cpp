// Biarc fitting and arc-spline utilities in double precision (the exact offset is in offset_cgal.cpp).
#include <gearkit/cam/arc_spline.hpp>

#include "extremum.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
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
  const double t0x = a.tangent.x(), t0y = a.tangent.y(), t1x = incoming(b).x(), t1y = incoming(b).y();
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
  return {p.x, p.y, Direction::from_angle(std::atan2(p.ty, p.tx)), false, {}};
}

/// The joint tangent that makes the biarc a single arc when the data lie on a circle:
/// angle(w) = 2 angle(chord) - (angle(t0) + angle(t1)) / 2.
Direction joint_for(const Knot& a, const Knot& b) {
  const double chord = std::atan2(b.y - a.y, b.x - a.x);
  const double a0 = a.tangent.angle();
  const double a1 = a0 + wrap_pi(incoming(b).angle() - a0);
  return Direction::from_angle(2 * chord - 0.5 * (a0 + a1));
}

/// At a corner knot the curve's own value at the knot may be the other side's: there the
/// biarc's side is the knot's tangent.
CurvePoint one_sided(const std::function<CurvePoint(double)>& curve, double t, double ta, double tb, const Knot& ka,
                     const Knot& kb) {
  CurvePoint p = curve(t);
  const Direction* side = t == ta && ka.corner ? &ka.tangent : t == tb && kb.corner ? &kb.tangent_in : nullptr;
  if (side) p.tx = side->x(), p.ty = side->y();
  return p;
}

/// Largest distance, over the biarc's parameter interval and every offset d, from the offset
/// curve point p(t) + d n(t) to the nearer of the two offset arcs. Found by maximisation (see
/// extremum.hpp): the error of a biarc is a smooth function with a few humps, so eight samples
/// bracket its maxima and golden-section search pins each to 1e-4 of the interval.
void biarc_error(const std::function<CurvePoint(double)>& curve, double ta, double tb, const Knot& ka, const Knot& kb,
                 const std::vector<Piece>& pieces, const std::vector<double>& offsets, std::vector<double>& errors) {
  for (const Piece& piece : pieces)  // a biarc that loops is wrong even if it passes near the curve
    if (std::abs(piece.sweep) > pi / 2) {
      std::fill(errors.begin(), errors.end(), INFINITY);
      return;
    }
  // The curve at the sampling points of find_maximum (the same abscissae, computed alike), shared
  // by every offset: only the golden-section steps differ between offsets.
  constexpr int kSamples = 8;
  const double h = (tb - ta) / kSamples;
  std::array<double, kSamples + 1> at;
  std::array<CurvePoint, kSamples + 1> sampled;
  for (int i = 0; i <= kSamples; ++i) {
    at[i] = i == kSamples ? tb : ta + h * i;
    sampled[i] = one_sided(curve, at[i], ta, tb, ka, kb);
  }
  auto point = [&](double t) {
    for (int i = 0; i <= kSamples; ++i)
      if (at[i] == t) return sampled[i];
    return one_sided(curve, t, ta, tb, ka, kb);
  };
  for (std::size_t k = 0; k < offsets.size(); ++k) {
    const double d = offsets[k];
    std::vector<Piece> moved;
    for (const Piece& piece : pieces)
      if (const auto m = offset_piece(piece, d)) moved.push_back(*m);
    if (moved.empty()) {
      errors[k] = 0;
      continue;
    }
    auto distance = [&](double t) {
      const CurvePoint p = point(t);
      const double len = std::hypot(p.tx, p.ty);
      const double x = p.x - d * p.ty / len, y = p.y + d * p.tx / len;
      double best = INFINITY;
      for (const Piece& piece : moved) best = std::min(best, distance_to_piece(piece, x, y));
      return best;
    };
    errors[k] = detail::find_maximum(distance, ta, tb, kSamples, 1e-4 * (tb - ta)).value;
  }
}

struct FitState {
  const std::function<CurvePoint(double)>& curve;
  const FitOptions& options;
  std::vector<double> offsets;  // 0 first, then options.offsets
  std::vector<double> errors;   // scratch, one per offset
  BiarcSpline& out;
};

void fit_interval(FitState& st, double ta, double tb, const Knot& ka, const Knot& kb, int depth) {
  const Direction joint = joint_for(ka, kb);
  std::vector<Piece> pieces;
  biarc_pieces(ka, kb, joint, pieces);
  biarc_error(st.curve, ta, tb, ka, kb, pieces, st.offsets, st.errors);
  if (*std::max_element(st.errors.begin(), st.errors.end()) <= st.options.tolerance) {
    st.out.joints.push_back(joint);
    st.out.knots.push_back(kb);
    for (std::size_t k = 0; k < st.errors.size(); ++k)
      st.out.max_error[k] = std::max(st.out.max_error[k], st.errors[k]);
    return;
  }
  if (depth >= st.options.max_depth) {
    throw FitError(fmt::format("cannot fit arcs within {:.6g} to the curve near parameter {:.6g} (a cusp or a corner)",
                               st.options.tolerance, 0.5 * (ta + tb)),
                   0.5 * (ta + tb));
  }
  const double tm = 0.5 * (ta + tb);
  const Knot km = knot_at(st.curve, tm);
  fit_interval(st, ta, tm, ka, km, depth + 1);
  fit_interval(st, tm, tb, km, kb, depth + 1);
}

}  // namespace

namespace {

/// The knot at break t: a corner (both tangents) if the options list one there.
Knot break_knot(const std::function<CurvePoint(double)>& curve, double t, const FitOptions& options, double same) {
  Knot k = knot_at(curve, t);
  for (const CurveCorner& c : options.corners) {
    if (std::abs(c.t - t) > same) continue;
    k.corner = true;
    k.tangent = Direction::from_angle(std::atan2(c.out_y, c.out_x));
    k.tangent_in = Direction::from_angle(std::atan2(c.in_y, c.in_x));
  }
  return k;
}

}  // namespace

BiarcSpline fit_biarcs(const std::function<CurvePoint(double)>& curve, std::vector<double> breaks,
                       const FitOptions& options, bool closed) {
  for (const CurveCorner& c : options.corners) breaks.push_back(c.t);
  std::sort(breaks.begin(), breaks.end());
  // Breaks that differ by rounding only would make a biarc with no length and a random chord.
  const double span = breaks.empty() ? 0 : breaks.back() - breaks.front();
  const double same = 1e-9 * span;
  breaks.erase(std::unique(breaks.begin(), breaks.end(), [&](double a, double b) { return b - a <= same; }),
               breaks.end());
  if (breaks.size() < 2) throw GeometryError("fit_biarcs: the parameter range is empty");
  BiarcSpline spline;
  FitState state{curve, options, {0.0}, {}, spline};
  state.offsets.insert(state.offsets.end(), options.offsets.begin(), options.offsets.end());
  state.errors.assign(state.offsets.size(), 0);
  spline.max_error.assign(state.offsets.size(), 0);
  Knot first = break_knot(curve, breaks.front(), options, same);
  const Knot end = break_knot(curve, breaks.back(), options, same);
  if (closed && end.corner) {  // a corner at the closing point may be given at either end
    if (!first.corner) first.tangent = end.tangent;
    first.corner = true, first.tangent_in = end.tangent_in;
  }
  spline.knots.push_back(first);
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const bool last = i + 2 == breaks.size();
    const Knot kb = !last ? break_knot(curve, breaks[i + 1], options, same) : closed ? first : end;
    fit_interval(state, breaks[i], breaks[i + 1], spline.knots.back(), kb, 0);
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

std::optional<Piece> offset_piece(const Piece& p, double distance) {
  Piece m = p;
  if (!p.is_arc()) {
    const double len = std::hypot(p.x1 - p.x0, p.y1 - p.y0);
    if (len == 0) return m;
    const double nx = -(p.y1 - p.y0) / len * distance, ny = (p.x1 - p.x0) / len * distance;
    m.x0 += nx, m.y0 += ny, m.x1 += nx, m.y1 += ny;
    return m;
  }
  const double r = p.radius - distance;
  if (r == 0 || (r > 0) != (p.radius > 0)) return std::nullopt;
  const double k = r / p.radius;
  m.radius = r;
  m.x0 = p.cx + k * (p.x0 - p.cx), m.y0 = p.cy + k * (p.y0 - p.cy);
  m.x1 = p.cx + k * (p.x1 - p.cx), m.y1 = p.cy + k * (p.y1 - p.cy);
  return m;
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
