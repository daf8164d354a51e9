// Exact offsets of biarc splines with CGAL (the one translation unit of libcam that includes CGAL).
//
// The raw offset of a biarc spline is built in exact rational arithmetic: every knot is a double,
// every tangent a rational unit vector, every radius the solution of a rational 2x2 system, so
// the offset arcs (same centres, radii reduced by the distance) meet exactly. The arcs go into a
// CGAL arrangement of circle segments (exact one-root coordinates), which finds where the offset
// folds over itself (a roller larger than the pitch curve's radius of curvature); the faces at the
// right distance from the spline form the offset region.
#include <gearkit/cam/arc_spline.hpp>

#include "simple_offset.hpp"

#include <CGAL/Arr_circle_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/assertions_behaviour.h>
#include <CGAL/exceptions.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace gearkit::cam {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = Kernel::FT;
using Traits = CGAL::Arr_circle_segment_traits_2<Kernel>;
using Arrangement = CGAL::Arrangement_2<Traits>;
using Q = FT::ET;  // the exact rational type under the lazy kernel (GMP)

struct QVec {
  Q x, y;
};

QVec operator+(const QVec& a, const QVec& b) { return {a.x + b.x, a.y + b.y}; }
QVec operator-(const QVec& a, const QVec& b) { return {a.x - b.x, a.y - b.y}; }
QVec operator*(const Q& k, const QVec& a) { return {k * a.x, k * a.y}; }
/// Rotation by +90 deg: the left normal of a direction.
QVec left_normal(const QVec& t) { return {-t.y, t.x}; }

QVec exact(const Direction& d) {
  const Q m(d.m);
  const Q den = 1 + m * m;
  QVec v{(1 - m * m) / den, 2 * m / den};
  if (d.reversed) v = {-v.x, -v.y};
  return v;
}

/// One element of the spline: an arc (centre c, signed radius R, tangent from ts to te) or,
/// for a straight biarc, a segment from p to q with tangent ts; or a corner at c, where the
/// tangent turns from ts to te (radius 0: its offset is the arc about c joining the offsets of
/// the two sides).
struct Element {
  bool arc = true;
  QVec c, ts, te;
  Q R;
  QVec p, q;
  bool corner = false;
};

/// The biarc from knot a to knot b with joint tangent w: with J the left normal, arc centres
/// c = P + R J t, joint M = cA - RA J w = cB - RB J w and end Q = cB - RB J t1 give
/// -J (Q - P) = RA (t0 - w) + RB (w - t1), two linear equations for the radii.
void add_biarc(const Knot& a, const Knot& b, const Direction& joint, std::vector<Element>& out) {
  const QVec P{Q(a.x), Q(a.y)}, Qp{Q(b.x), Q(b.y)};
  const QVec t0 = exact(a.tangent), t1 = exact(incoming(b)), w = exact(joint);
  const QVec d = Qp - P;
  const QVec rhs{d.y, -d.x};
  const QVec u = t0 - w, v = w - t1;
  const Q det = u.x * v.y - u.y * v.x;
  if (det == 0) {  // all three tangents equal: a straight piece
    if (P.x != Qp.x || P.y != Qp.y) out.push_back({false, {}, t0, t0, Q(0), P, Qp});
    return;
  }
  const Q RA = (rhs.x * v.y - rhs.y * v.x) / det;
  const Q RB = (u.x * rhs.y - u.y * rhs.x) / det;
  const QVec cA = P + RA * left_normal(t0);
  const QVec M = cA - RA * left_normal(w);
  const QVec cB = M + RB * left_normal(w);
  if (t0.x != w.x || t0.y != w.y) out.push_back({true, cA, t0, w, RA, {}, {}});
  if (w.x != t1.x || w.y != t1.y) out.push_back({true, cB, w, t1, RB, {}, {}});
}

/// The corner at knot k, if the curve turns there (the offsets of its two sides do not meet).
void add_corner(const Knot& k, std::vector<Element>& out) {
  if (!k.corner) return;
  const QVec tin = exact(k.tangent_in), tout = exact(k.tangent);
  if (tin.x == tout.x && tin.y == tout.y) return;
  Element e;
  e.corner = true;
  e.c = {Q(k.x), Q(k.y)};
  e.ts = tin, e.te = tout;
  e.R = Q(0);
  out.push_back(e);
}

Traits::Point_2 one_root(const QVec& p) { return Traits::Point_2(FT(p.x), FT(p.y)); }

/// The offset of a corner: the arc of radius |d| about it from the offset of the arriving side to
/// that of the leaving side, turning as the tangent turns (the shorter way: a corner turns by
/// less than 180 deg; a reversal is taken counter-clockwise).
Traits::Curve_2 corner_offset(const Element& e, const Q& distance) {
  const QVec source = e.c + distance * left_normal(e.ts);
  const QVec target = e.c + distance * left_normal(e.te);
  const Q turn = e.ts.x * e.te.y - e.ts.y * e.te.x;
  const Kernel::Circle_2 circle(Kernel::Point_2(FT(e.c.x), FT(e.c.y)), FT(distance * distance),
                                turn >= 0 ? CGAL::COUNTERCLOCKWISE : CGAL::CLOCKWISE);
  return Traits::Curve_2(circle, one_root(source), one_root(target));
}

/// The element moved `distance` to its left, as a CGAL curve; false if it shrinks to a point.
bool offset_curve(const Element& e, const Q& distance, Traits::Curve_2& curve, bool& folded) {
  if (e.corner) {
    curve = corner_offset(e, distance);
    return true;
  }
  if (!e.arc) {
    const QVec shift = distance * left_normal(e.ts);
    curve = Traits::Curve_2(Kernel::Point_2(FT((e.p + shift).x), FT((e.p + shift).y)),
                            Kernel::Point_2(FT((e.q + shift).x), FT((e.q + shift).y)));
    return true;
  }
  // A point of the arc is c - R J t, its offset c - (R - d) J t: the concentric arc, traversed in
  // the same turning sense as the original (sign of R) even where R - d changed sign (a fold).
  const Q r = e.R - distance;
  if (r == 0) {
    folded = true;
    return false;
  }
  if ((r > 0) != (e.R > 0)) folded = true;
  const QVec source = e.c - r * left_normal(e.ts);
  const QVec target = e.c - r * left_normal(e.te);
  const Kernel::Circle_2 circle(Kernel::Point_2(FT(e.c.x), FT(e.c.y)), FT(r * r),
                                e.R > 0 ? CGAL::COUNTERCLOCKWISE : CGAL::CLOCKWISE);
  curve = Traits::Curve_2(circle, one_root(source), one_root(target));
  return true;
}

double to_double(const Traits::CoordNT& v) { return CGAL::to_double(v); }

/// The piece a halfedge traverses, from its source to its target.
Piece piece_of(Arrangement::Halfedge_const_handle he) {
  Piece p;
  p.x0 = to_double(he->source()->point().x());
  p.y0 = to_double(he->source()->point().y());
  p.x1 = to_double(he->target()->point().x());
  p.y1 = to_double(he->target()->point().y());
  const auto& cv = he->curve();
  if (cv.is_linear()) return p;
  const auto circle = cv.supporting_circle();
  p.cx = CGAL::to_double(circle.center().x());
  p.cy = CGAL::to_double(circle.center().y());
  const double r = std::sqrt(CGAL::to_double(circle.squared_radius()));
  const bool along_curve = (he->direction() == CGAL::ARR_LEFT_TO_RIGHT) == cv.is_directed_right();
  const bool ccw = along_curve == (cv.orientation() == CGAL::COUNTERCLOCKWISE);
  p.radius = ccw ? r : -r;
  p.sweep = turning_angle(p.x0 - p.cx, p.y0 - p.cy, p.x1 - p.cx, p.y1 - p.cy, ccw ? 1.0 : -1.0);
  return p;
}

template <class Circulator>
std::vector<Piece> loop_of(Circulator first) {
  std::vector<Piece> loop;
  auto he = first;
  do {
    loop.push_back(piece_of(he));
  } while (++he != first);
  return loop;
}

std::vector<Piece> reversed(const std::vector<Piece>& loop) {
  std::vector<Piece> out;
  for (auto it = loop.rbegin(); it != loop.rend(); ++it) {
    Piece p = *it;
    std::swap(p.x0, p.x1);
    std::swap(p.y0, p.y1);
    p.radius = -p.radius;
    p.sweep = -p.sweep;
    out.push_back(p);
  }
  return out;
}

/// A point just inside the face on the left of the piece, near the piece's middle.
void point_left_of(const Piece& p, double step, double& x, double& y) {
  double mx, my, nx, ny;
  if (!p.is_arc()) {
    mx = 0.5 * (p.x0 + p.x1), my = 0.5 * (p.y0 + p.y1);
    const double len = std::hypot(p.x1 - p.x0, p.y1 - p.y0);
    nx = -(p.y1 - p.y0) / len, ny = (p.x1 - p.x0) / len;
  } else {
    const double a = std::atan2(p.y0 - p.cy, p.x0 - p.cx) + 0.5 * p.sweep;
    const double r = std::abs(p.radius);
    mx = p.cx + r * std::cos(a), my = p.cy + r * std::sin(a);
    // Left of a counter-clockwise arc is towards its centre.
    nx = (p.radius > 0 ? -1 : 1) * std::cos(a), ny = (p.radius > 0 ? -1 : 1) * std::sin(a);
  }
  x = mx + step * nx;
  y = my + step * ny;
}

/// Signed distance from the spline: positive on its left (inside a counter-clockwise spline).
double signed_distance(const std::vector<Piece>& spline, double x, double y) {
  double best = INFINITY;
  const Piece* nearest = nullptr;
  for (const Piece& p : spline) {
    const double d = distance_to_piece(p, x, y);
    if (d < best) best = d, nearest = &p;
  }
  if (!nearest) return best;
  bool left;
  if (nearest->is_arc()) {
    const double r = std::hypot(x - nearest->cx, y - nearest->cy);
    left = nearest->radius > 0 ? r < nearest->radius : r > -nearest->radius;
  } else {
    left = (nearest->x1 - nearest->x0) * (y - nearest->y0) - (nearest->y1 - nearest->y0) * (x - nearest->x0) > 0;
  }
  return left ? best : -best;
}

}  // namespace

OffsetCurve offset_closed_spline(const BiarcSpline& spline, double distance) {
  OffsetCurve result;
  const std::vector<Piece> own = pieces_of(spline);
  if (distance == 0) {
    result.loops.push_back(own);
    return result;
  }
  // Most offsets neither fold nor cross themselves: then the raw offset is the answer and the
  // exact arrangement below (three quarters of the time of a cam) would only confirm it.
  if (auto raw = detail::simple_raw_offset(own, distance)) {
    result.loops.push_back(std::move(*raw));
    return result;
  }
  const CGAL::Failure_behaviour old_error = CGAL::set_error_behaviour(CGAL::THROW_EXCEPTION);
  const CGAL::Failure_behaviour old_warning = CGAL::set_warning_behaviour(CGAL::CONTINUE);
  try {
    std::vector<Element> elements;
    for (std::size_t k = 0; k + 1 < spline.knots.size(); ++k) {
      add_biarc(spline.knots[k], spline.knots[k + 1], spline.joints[k], elements);
      add_corner(spline.knots[k + 1], elements);
    }
    const Q d(distance);
    std::vector<Traits::Curve_2> curves;
    curves.reserve(elements.size());
    for (const Element& e : elements) {
      Traits::Curve_2 curve;
      if (offset_curve(e, d, curve, result.trimmed)) curves.push_back(curve);
    }
    Arrangement arrangement;
    CGAL::insert(arrangement, curves.begin(), curves.end());

    double scale = 0;
    for (const Knot& k : spline.knots) scale = std::max({scale, std::abs(k.x), std::abs(k.y)});
    const double step = 1e-7 * std::max(scale, 1.0);

    int bounded_faces = 0;
    for (auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f) {
      if (f->is_unbounded()) {
        if (distance < 0) {
          for (auto hole = f->inner_ccbs_begin(); hole != f->inner_ccbs_end(); ++hole)
            result.loops.push_back(reversed(loop_of(*hole)));
        }
        continue;
      }
      ++bounded_faces;
      if (distance < 0) continue;
      // Keep the face if points just inside it are farther inside the spline than the offset: a
      // step s in from a true offset edge lands at distance + s, while inside a fold (swallowtail)
      // every point is closer than the offset distance.
      const std::vector<Piece> loop = loop_of(f->outer_ccb());
      const double s = std::min(step, 1e-3 * std::abs(distance));
      int votes = 0, valid = 0;
      for (std::size_t i = 0; i < loop.size(); i += std::max<std::size_t>(1, loop.size() / 7)) {
        double x, y;
        point_left_of(loop[i], s, x, y);
        ++votes;
        if (signed_distance(own, x, y) >= distance + 0.25 * s) ++valid;
      }
      if (2 * valid > votes) result.loops.push_back(loop);
    }
    if (bounded_faces != 1) result.trimmed = true;
  } catch (const CGAL::Failure_exception& error) {
    CGAL::set_error_behaviour(old_error);
    CGAL::set_warning_behaviour(old_warning);
    throw GeometryError(std::string("CGAL failed while offsetting the curve: ") + error.what());
  }
  CGAL::set_error_behaviour(old_error);
  CGAL::set_warning_behaviour(old_warning);
  if (result.loops.empty()) {
    throw GeometryError("the offset by " + std::to_string(distance) + " leaves no region (the curve is too small)");
  }
  return result;
}

}  // namespace gearkit::cam
