// Tests of gearkit/cam/arc_spline.hpp: biarc fitting, exact CGAL offsets against analytic normal
// offsets, folding (trimmed) offsets, merging of arcs.
#include <gearkit/cam/arc_spline.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using namespace gearkit::cam;

constexpr double pi = std::numbers::pi;

std::vector<double> uniform_breaks(int n) {
  std::vector<double> b;
  for (int i = 0; i <= n; ++i) b.push_back(2 * pi * i / n);
  return b;
}

CurvePoint circle(double t, double cx, double cy, double r) {
  return {cx + r * std::cos(t), cy + r * std::sin(t), -std::sin(t), std::cos(t)};
}

CurvePoint ellipse(double t, double a, double b) {
  return {a * std::cos(t), b * std::sin(t), -a * std::sin(t), b * std::cos(t)};
}

double max_distance(const std::vector<Piece>& pieces, const std::vector<std::pair<double, double>>& points) {
  double worst = 0;
  for (auto [x, y] : points) {
    double best = INFINITY;
    for (const Piece& p : pieces) best = std::min(best, distance_to_piece(p, x, y));
    worst = std::max(worst, best);
  }
  return worst;
}

TEST(ArcSpline, DirectionsAreUnitVectorsAtTheirAngle) {
  for (double a = -3.1; a < 3.2; a += 0.37) {
    const Direction d = Direction::from_angle(a);
    EXPECT_NEAR(std::hypot(d.x(), d.y()), 1, 1e-15);
    EXPECT_NEAR(std::remainder(d.angle() - a, 2 * pi), 0, 1e-14);
    EXPECT_LE(std::abs(d.m), 1.0 + 1e-15);
  }
}

TEST(ArcSpline, CircleIsFittedByArcsOfItsOwnRadius) {
  const auto spline = fit_biarcs([](double t) { return circle(t, 3, -2, 25); }, uniform_breaks(8), {1e-6, 24, {}, {}}, true);
  for (const Piece& p : pieces_of(spline)) {
    EXPECT_NEAR(p.radius, 25, 1e-9);
    EXPECT_NEAR(p.cx, 3, 1e-9);
    EXPECT_NEAR(p.cy, -2, 1e-9);
  }
  // Merged: one circle in at most a few arcs of <= 270 deg.
  const auto merged = merge_pieces(pieces_of(spline));
  EXPECT_LE(merged.size(), 2u);
  double sweep = 0;
  for (const Piece& p : merged) sweep += p.sweep;
  EXPECT_NEAR(sweep, 2 * pi, 1e-9);
}

TEST(ArcSpline, FitStaysWithinTolerance) {
  for (double tol : {1e-2, 1e-4}) {
    const auto spline = fit_biarcs([](double t) { return ellipse(t, 50, 30); }, uniform_breaks(12), {tol, 24, {}, {}}, true);
    std::vector<std::pair<double, double>> pts;
    for (int i = 0; i < 2000; ++i) pts.push_back({50 * std::cos(2 * pi * i / 2000), 30 * std::sin(2 * pi * i / 2000)});
    EXPECT_LE(max_distance(pieces_of(spline), pts), tol);
    // Consecutive pieces meet exactly (the last knot is the first).
    const auto pieces = pieces_of(spline);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const Piece& a = pieces[i];
      const Piece& b = pieces[(i + 1) % pieces.size()];
      EXPECT_EQ(a.x1, b.x0);
      EXPECT_EQ(a.y1, b.y0);
    }
  }
}

TEST(ArcSpline, CgalOffsetOfACircleIsTheConcentricCircle) {
  const auto spline = fit_biarcs([](double t) { return circle(t, 0, 0, 40); }, uniform_breaks(6), {1e-6, 24, {}, {}}, true);
  for (double d : {10.0, -7.5}) {
    const OffsetCurve off = offset_closed_spline(spline, d);
    ASSERT_EQ(off.loops.size(), 1u);
    EXPECT_FALSE(off.trimmed);
    double sweep = 0;
    for (const Piece& p : off.loops[0]) {
      EXPECT_NEAR(std::abs(p.radius), 40 - d, 1e-9);
      EXPECT_NEAR(std::hypot(p.x0, p.y0), 40 - d, 1e-9);
      sweep += p.sweep;
    }
    EXPECT_NEAR(sweep, 2 * pi, 1e-9);  // counter-clockwise, once round
  }
}

TEST(ArcSpline, CgalInsetMatchesTheAnalyticNormalOffset) {
  // Ellipse a = 50, b = 30: smallest radius of curvature b^2/a = 18 mm. An inset of 10 mm does not
  // fold; its exact points are X(t) - 10 n(t) with n the outward unit normal.
  const double tol = 1e-4;
  const auto spline = fit_biarcs([](double t) { return ellipse(t, 50, 30); }, uniform_breaks(36), {tol, 24, {}, {}}, true);
  const OffsetCurve off = offset_closed_spline(spline, 10);
  ASSERT_EQ(off.loops.size(), 1u);
  EXPECT_FALSE(off.trimmed);
  std::vector<std::pair<double, double>> analytic;
  for (int i = 0; i < 3600; ++i) {
    const double t = 2 * pi * i / 3600;
    const double tx = -50 * std::sin(t), ty = 30 * std::cos(t), n = std::hypot(tx, ty);
    analytic.push_back({50 * std::cos(t) - 10 * ty / n, 30 * std::sin(t) + 10 * tx / n});
  }
  // Fitting error carries over to the offset (concentric arcs): within the fit tolerance.
  EXPECT_LE(max_distance(off.loops[0], analytic), tol * 1.01);
  // And the other way round: every offset piece end is on the analytic curve's neighbourhood.
  std::vector<Piece> analytic_polyline;
  for (std::size_t i = 0; i < analytic.size(); ++i) {
    const auto [x0, y0] = analytic[i];
    const auto [x1, y1] = analytic[(i + 1) % analytic.size()];
    analytic_polyline.push_back({x0, y0, x1, y1, 0, 0, 0, 0});
  }
  std::vector<std::pair<double, double>> ends;
  for (const Piece& p : off.loops[0]) ends.push_back({p.x0, p.y0});
  EXPECT_LE(max_distance(analytic_polyline, ends), tol + 1e-3);  // + chord sag of the 0.1 deg polyline
}

TEST(ArcSpline, FoldingInsetIsTrimmedToPointsAtTheOffsetDistance) {
  // Inset by 25 mm > 18 mm: the raw offset folds near the ends of the major axis (swallowtails).
  const auto spline = fit_biarcs([](double t) { return ellipse(t, 50, 30); }, uniform_breaks(36), {1e-4, 24, {}, {}}, true);
  const OffsetCurve off = offset_closed_spline(spline, 25);
  EXPECT_TRUE(off.trimmed);
  ASSERT_FALSE(off.loops.empty());
  const auto own = pieces_of(spline);
  // Every point of the trimmed inset is at least 25 mm from the ellipse (within the fit tolerance).
  for (const auto& loop : off.loops) {
    for (const Piece& p : loop) {
      double best = INFINITY;
      for (const Piece& q : own) best = std::min(best, distance_to_piece(q, p.x0, p.y0));
      EXPECT_GE(best, 25 - 1e-3);
      EXPECT_LE(best, 25 + 1e-3);
    }
  }
  // Where the ellipse is sharper than the inset (rho = 18 < 25 at the major axis) the inset stays
  // short of the naive normal offset point (50 - 25, 0).
  for (const Piece& p : off.loops[0]) EXPECT_LT(std::abs(p.x0), 50 - 25);
}

TEST(ArcSpline, InsetLargerThanTheRegionFails) {
  const auto spline = fit_biarcs([](double t) { return circle(t, 0, 0, 10); }, uniform_breaks(4), {1e-6, 24, {}, {}}, true);
  EXPECT_THROW(offset_closed_spline(spline, 12), GeometryError);
}

// A lens: the intersection of two discs of radius R = 30 about (-18, 0) and (18, 0), corners at
// (0, +-24) (h = sqrt(30^2 - 18^2)). Counter-clockwise: t in [0, pi] runs up its right flank (the
// left circle), t in [pi, 2 pi] down its left flank. Each flank turns through 2 alpha,
// alpha = atan2(24, 18).
constexpr double kLensR = 30, kLensC = 18, kLensH = 24;
const double kLensAlpha = std::atan2(kLensH, kLensC);

CurvePoint lens(double t) {
  const bool right = t <= pi;
  const double phi = right ? -kLensAlpha + 2 * kLensAlpha * t / pi : pi - kLensAlpha + 2 * kLensAlpha * (t - pi) / pi;
  const double cx = right ? -kLensC : kLensC;
  return {cx + kLensR * std::cos(phi), kLensR * std::sin(phi), -std::sin(phi), std::cos(phi)};
}

std::vector<std::pair<double, double>> arc_points(double cx, double cy, double r, double from, double to) {
  std::vector<std::pair<double, double>> p;
  for (int i = 0; i <= 200; ++i) {
    const double a = from + (to - from) * i / 200;
    p.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  return p;
}

double distance_to_loops(const std::vector<std::vector<Piece>>& loops, const std::vector<std::pair<double, double>>& points) {
  std::vector<Piece> all;
  for (const auto& loop : loops) all.insert(all.end(), loop.begin(), loop.end());
  return max_distance(all, points);
}

TEST(ArcSpline, CornersAreFittedAsCornersAndOffsetExactly) {
  // The tangent turns at both corners (lens(t) on either side): at (0, 24) it arrives along
  // (-sin a, cos a) and leaves along (-sin a, -cos a); at (0, -24), the start, it arrives along
  // (sin a, -cos a) and leaves along (sin a, cos a).
  const double a = kLensAlpha, sa = std::sin(a), ca = std::cos(a);
  FitOptions options{1e-6, 24, {5, -5}, {}};
  options.corners = {{pi, -sa, ca, -sa, -ca}, {2 * pi, sa, -ca, sa, ca}};
  const std::vector<double> breaks{0, pi / 2, pi, 3 * pi / 2, 2 * pi};
  // Without the corners the offsets cannot be fitted: a tangent is wrong by 2 alpha at a corner.
  FitOptions blind = options;
  blind.corners.clear();
  EXPECT_THROW(fit_biarcs(lens, breaks, blind, true), FitError);
  const BiarcSpline spline = fit_biarcs(lens, breaks, options, true);
  // Each flank is one circular arc: the biarcs are arcs of it, no chase into the corners.
  EXPECT_EQ(spline.knots.size(), 5u);
  for (const Piece& p : pieces_of(spline)) EXPECT_NEAR(std::abs(p.radius), kLensR, 1e-9);
  // Outwards by 5 (the lens dilated): its flanks on circles of radius 35, and about each corner an
  // arc of radius 5 from the right flank's outer normal (cos a, sin a) to the left flank's
  // (-cos a, sin a) (mirrored below): the Minkowski sum of the lens and a disc.
  const OffsetCurve out = offset_closed_spline(spline, -5);
  ASSERT_EQ(out.loops.size(), 1u);
  EXPECT_FALSE(out.trimmed);
  EXPECT_LE(distance_to_loops(out.loops, arc_points(0, kLensH, 5, a, pi - a)), 1e-9);
  EXPECT_LE(distance_to_loops(out.loops, arc_points(0, -kLensH, 5, pi + a, 2 * pi - a)), 1e-9);
  EXPECT_LE(distance_to_loops(out.loops, arc_points(-kLensC, 0, 35, -a, a)), 1e-9);
  EXPECT_LE(distance_to_loops(out.loops, arc_points(kLensC, 0, 35, pi - a, pi + a)), 1e-9);
  // Inwards by 5 (eroded): the intersection of the discs of radius 25, corners at
  // (0, +-sqrt(25^2 - 18^2)); the raw offsets cross there and are trimmed.
  const OffsetCurve in = offset_closed_spline(spline, 5);
  ASSERT_EQ(in.loops.size(), 1u);
  EXPECT_TRUE(in.trimmed);
  const double h5 = std::sqrt(25.0 * 25 - kLensC * kLensC), a5 = std::atan2(h5, kLensC);
  EXPECT_LE(distance_to_loops(in.loops, arc_points(-kLensC, 0, 25, -a5, a5)), 1e-9);
  EXPECT_LE(distance_to_loops(in.loops, arc_points(kLensC, 0, 25, pi - a5, pi + a5)), 1e-9);
  double top = -INFINITY;
  for (const Piece& p : in.loops[0]) top = std::max(top, p.y0);
  EXPECT_NEAR(top, h5, 1e-9);
}

// A peanut: (40 cos t, sin t (8 + 20 cos^2 t)), two lobes joined by a neck of half-width 8 at
// x = 0 whose flanks are concave (y = 8 + x^2 / 100 near it: radius 50); its sharpest convex
// radius is 28^2 / 40 = 19.6 mm at the lobes' ends.
CurvePoint peanut(double t) {
  const double c = std::cos(t), s = std::sin(t);
  return {40 * c, s * (8 + 20 * c * c), -40 * s, c * (8 + 20 * c * c) - 40 * s * s * c};
}

TEST(ArcSpline, OffsetThatCrossesItselfWithoutFoldingIsTrimmed) {
  // No arc turns inside out at 10 mm (every radius > 10 mm), yet the neck is only 16 mm wide: the
  // raw inset's two flanks cross there and the inset is two lobes. At 5 mm it is one loop, the
  // analytic normal offset X(t) - 5 n(t).
  const auto spline = fit_biarcs(peanut, uniform_breaks(36), {1e-5, 24, {}, {}}, true);
  const OffsetCurve narrow = offset_closed_spline(spline, 10);
  EXPECT_TRUE(narrow.trimmed);
  ASSERT_EQ(narrow.loops.size(), 2u);
  const auto own = pieces_of(spline);
  for (const auto& loop : narrow.loops)
    for (const Piece& p : loop) {
      double best = INFINITY;
      for (const Piece& q : own) best = std::min(best, distance_to_piece(q, p.x0, p.y0));
      EXPECT_NEAR(best, 10, 1e-4);
      EXPECT_GT(std::abs(p.x0), 1);  // nothing left in the neck
    }
  const OffsetCurve wide = offset_closed_spline(spline, 5);
  EXPECT_FALSE(wide.trimmed);
  ASSERT_EQ(wide.loops.size(), 1u);
  std::vector<std::pair<double, double>> analytic;
  for (int i = 0; i < 3600; ++i) {
    const CurvePoint p = peanut(2 * pi * i / 3600);
    const double n = std::hypot(p.tx, p.ty);
    analytic.push_back({p.x - 5 * p.ty / n, p.y + 5 * p.tx / n});
  }
  EXPECT_LE(max_distance(wide.loops[0], analytic), 1e-5 * 1.01);
}

TEST(ArcSpline, MergeJoinsArcsOnOneCircleOnly) {
  const Piece a{10, 0, 0, 10, 0, 0, 10, pi / 2};
  const Piece b{0, 10, -10, 0, 0, 0, 10, pi / 2};
  const Piece c{-10, 0, -10, -5, -15, 0, -5, -pi / 2};
  const auto m = merge_pieces({a, b, c});
  ASSERT_EQ(m.size(), 2u);
  EXPECT_NEAR(m[0].sweep, pi, 1e-15);
  EXPECT_EQ(m[0].x1, -10);
}

}  // namespace

namespace {

using namespace gearkit::cam;

/// Largest distance from the ends of the pieces of `from` to the pieces of `to`, both ways.
double hausdorff_at_ends(const std::vector<std::vector<Piece>>& a, const std::vector<std::vector<Piece>>& b) {
  auto one_way = [](const std::vector<std::vector<Piece>>& from, const std::vector<std::vector<Piece>>& to) {
    double worst = 0;
    for (const auto& loop : from)
      for (const Piece& p : loop) {
        double best = INFINITY;
        for (const auto& other : to)
          for (const Piece& q : other) best = std::min(best, distance_to_piece(q, p.x0, p.y0));
        worst = std::max(worst, best);
      }
    return worst;
  };
  return std::max(one_way(a, b), one_way(b, a));
}

TEST(ArcSpline, ExactArcOffsetAgreesWithCgalApproximatedInsetOfThePolygon) {
  // Two methods: (1) biarcs fitted to the ellipse, offset exactly and trimmed in an arrangement;
  // (2) CGAL's approximated_inset_2 (Minkowski sum by convolution) of the 720-gon through the
  // ellipse. They differ by the polygon's chord sag, at most L^2 / (8 rho) = 0.44^2 / (8 * 18)
  // = 1.3e-3 mm, plus the fit tolerance and CGAL's eps. Checked without folding (inset 10 mm) and
  // with it (25 mm > rho_min = 18 mm), where both must trim the same swallowtails.
  std::vector<std::pair<double, double>> polygon;
  for (int i = 0; i < 720; ++i) polygon.push_back({50 * std::cos(2 * pi * i / 720), 30 * std::sin(2 * pi * i / 720)});
  const auto spline = fit_biarcs([](double t) { return ellipse(t, 50, 30); }, uniform_breaks(36), {1e-5, 24, {}, {}}, true);
  for (double d : {10.0, 25.0}) {
    const auto reference = polygon_inset(polygon, d, 1e-6);
    const OffsetCurve ours = offset_closed_spline(spline, d);
    EXPECT_EQ(ours.loops.size(), reference.size()) << d;
    EXPECT_LE(hausdorff_at_ends(ours.loops, reference), 1.5e-3) << d;
  }
}

}  // namespace
