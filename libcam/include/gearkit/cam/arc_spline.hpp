#pragma once
// Closed curves as chains of circular arcs (arc splines), fitted to a smooth curve by biarcs,
// and their offsets computed with CGAL.
//
// Why arcs: the offset of a circular arc is the concentric arc, so the offset of an arc spline is
// exact, and CNC controllers and DXF (LWPOLYLINE bulges) speak arcs natively. A dense polygon of
// the same curve makes the offset only as good as its chords and much slower (docs/cam.md).
//
// Why the odd representation: every tangent direction is stored as the half-angle tangent m of
// its angle, (cos, sin) = ((1 - m^2), 2 m) / (1 + m^2), which is an exact rational for the double
// m. Knots are doubles (exact rationals too), so each biarc's radii solve a 2x2 linear system in
// rational arithmetic and the whole spline and its offset are exact: consecutive arcs meet exactly
// and share their tangent (G1), which CGAL's exact arrangement needs to avoid slivers. Lengths in
// the unit of the caller (mm in gearkit), angles in radians.
#include <functional>
#include <optional>
#include <string>
#include <stdexcept>
#include <vector>

namespace gearkit::cam {

/// Geometric computation failed (CGAL precondition or assertion, degenerate input).
class GeometryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A unit vector, exactly rational: see the file comment. `reversed` adds pi to the angle so that
/// |m| <= 1 always (m = tan of half the angle within (-pi/2, pi/2]).
struct Direction {
  double m = 0;
  bool reversed = false;

  static Direction from_angle(double angle_rad);
  double x() const;
  double y() const;
  double angle() const;
};

/// A point of the spline with its tangent direction (the direction of travel). At a corner the
/// curve arrives with `tangent_in` and leaves with `tangent`: the biarc ending here uses the
/// first, the one starting here the second.
struct Knot {
  double x = 0, y = 0;
  Direction tangent;
  bool corner = false;
  Direction tangent_in;  ///< only if `corner`
};

/// The direction in which the curve arrives at the knot.
inline const Direction& incoming(const Knot& k) { return k.corner ? k.tangent_in : k.tangent; }

/// knots[i] -> knots[i+1] is one biarc whose two arcs meet with tangent joints[i].
/// A closed spline repeats its first knot at the end (knots.front() == knots.back(), the last
/// one with the incoming tangent if the curve has a corner there).
struct BiarcSpline {
  std::vector<Knot> knots;
  std::vector<Direction> joints;
  /// Largest distance from the curve (offset by FitOptions::offsets[i]) to the arcs (offset
  /// alike), found by maximisation over every biarc [length]; one value per offset.
  std::vector<double> max_error;
};

/// A straight segment (radius == 0) or a circular arc from (x0, y0) to (x1, y1) about (cx, cy);
/// radius > 0 turns counter-clockwise, < 0 clockwise. sweep is the signed included angle [rad].
struct Piece {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double cx = 0, cy = 0;
  double radius = 0;
  double sweep = 0;

  bool is_arc() const { return radius != 0; }
};

/// A point and unit tangent of a parametric curve at parameter t.
struct CurvePoint {
  double x = 0, y = 0;
  double tx = 0, ty = 0;
};

/// Where a piecewise smooth curve has a corner: its parameter and the unit tangents with which
/// the curve arrives (from smaller parameters) and leaves.
struct CurveCorner {
  double t = 0;
  double in_x = 0, in_y = 0, out_x = 0, out_y = 0;
};

struct FitOptions {
  double tolerance = 1e-4;  ///< largest distance from the curve to the arcs [length]
  int max_depth = 24;       ///< interval halvings before giving up on an interval
  /// Distances to the left of the curve at which the tolerance must hold as well: the offsets
  /// that will be made of the spline (a roller cam's profile at +R_r, a tool path at R_r - R_c).
  /// Distance 0 (the curve itself) is always checked and comes first in BiarcSpline::max_error.
  /// Where an arc is smaller than the offset (it would turn inside out, the offset folds and
  /// is trimmed) that arc is not checked at that offset.
  std::vector<double> offsets;
  /// The curve's corners (each is made a break): the fit keeps both tangents there instead of
  /// chasing the corner with ever smaller biarcs. For a closed curve a corner at its start is
  /// given at breaks.front() (the tangent it leaves with) or breaks.back() (arrives with), or both.
  std::vector<CurveCorner> corners;
};

/// The fit cannot meet the tolerance near curve parameter `parameter` (a cusp or a corner).
class FitError : public GeometryError {
 public:
  FitError(const std::string& message, double parameter) : GeometryError(message), parameter_(parameter) {}
  double parameter() const { return parameter_; }

 private:
  double parameter_;
};

/// Fits biarcs to curve(t) on [breaks.front(), breaks.back()], interpolating the curve's points and
/// tangents at the breaks and at as many more parameters as the tolerance needs (interval halving).
/// A biarc is accepted when the largest distance from the curve to it -- found by maximising the
/// distance over the biarc's interval (sampling to bracket each local maximum, then golden-section
/// search), at every requested offset -- is within the tolerance; the tolerance is thus a bound
/// on the exported arcs, not a sampled estimate. With `closed`, the last knot is made identical
/// to the first. Breaks should include the places where the curvature jumps; corners (where the
/// tangent jumps) go in FitOptions::corners.
/// @throws FitError if an interval cannot meet the tolerance within max_depth halvings
///         (a cusp or a corner in the curve); GeometryError if the range is empty.
BiarcSpline fit_biarcs(const std::function<CurvePoint(double)>& curve, std::vector<double> breaks,
                       const FitOptions& options, bool closed);

/// The piece offset by `distance` to its left (arcs: concentric, radius reduced by the distance
/// for a counter-clockwise arc); std::nullopt if an arc would turn inside out (|distance| beyond
/// its radius on its centre's side).
std::optional<Piece> offset_piece(const Piece& piece, double distance);

/// The arcs of a biarc spline (two per biarc, evaluated in double precision).
std::vector<Piece> pieces_of(const BiarcSpline& spline);

/// Signed angle [rad] turning vector a into vector b in the sense of `sign` (> 0
/// counter-clockwise, < 0 clockwise), in (0, 2 pi] or [-2 pi, 0): the sweep of an arc from its
/// centre's view of the start and end points, or between its end tangents.
double turning_angle(double ax, double ay, double bx, double by, double sign);

/// Distance from (x, y) to a piece.
double distance_to_piece(const Piece& piece, double x, double y);

/// Joins consecutive arcs on the same circle (and collinear segments), within rel_tol of the
/// radius, never beyond 270 deg of sweep (bulges stay finite).
std::vector<Piece> merge_pieces(const std::vector<Piece>& pieces, double rel_tol = 1e-9);

/// A point in polar coordinates about the origin [length, rad].
struct PolarPoint {
  double r = 0, phi = 0;
};

/// The chain of pieces as points in polar coordinates, the angle unwrapped along the way, such
/// that moving linearly in radius and angle from one point to the next (a rotary table turning
/// while a radial axis moves) stays within `tolerance` of the pieces: each move's largest
/// deviation is found by maximisation (sampled to bracket, then golden-section search) and the
/// piece halved until it fits. The first point is the first piece's start.
std::vector<PolarPoint> polar_moves(const std::vector<Piece>& chain, double tolerance);

/// A polyline vertex in the DXF convention: the segment that starts here is an arc of included
/// angle 4 atan(bulge) (positive counter-clockwise), or straight for bulge 0.
struct BulgeVertex {
  double x = 0, y = 0, bulge = 0;
};

/// A closed chain of pieces as bulge vertices, consecutive arcs on one circle merged first.
std::vector<BulgeVertex> bulge_vertices(const std::vector<Piece>& loop);

/// The result of offsetting a closed spline.
struct OffsetCurve {
  std::vector<std::vector<Piece>> loops;  ///< closed, counter-clockwise
  bool trimmed = false;  ///< parts of the raw offset were cut away (the offset folded over: undercut)
};

/// Offsets a closed, counter-clockwise, non-self-intersecting biarc spline by `distance` to its
/// left (inwards: the inset of the region it bounds; negative: outwards). The raw offset (each
/// arc's concentric arc, and at each corner the arc of radius |distance| about the corner that
/// joins the offsets of its two sides) is built exactly and put in a CGAL arrangement of circular arcs
/// (Arr_circle_segment_traits_2, exact kernel); the faces at the right distance from the spline
/// are kept. distance == 0 returns the spline's own arcs.
/// @throws GeometryError if CGAL reports a failure (its error behaviour is set to throw) or the
///         inset is empty (distance larger than the region allows).
OffsetCurve offset_closed_spline(const BiarcSpline& spline, double distance);

/// The reference method the arc-spline offset is checked against: CGAL's approximated_inset_2
/// (the Minkowski sum of the complement with a disc, by convolution) of the simple,
/// counter-clockwise polygon through `points` [x, y], with CGAL's error bound `eps` on the
/// irrational offset edges. Its result is exact for the polygon, so it differs from the smooth
/// curve's offset by the polygon's chord sag. Seconds for thousands of vertices: for tests.
/// @throws GeometryError if CGAL fails (error behaviour set to throw) or the inset is empty.
std::vector<std::vector<Piece>> polygon_inset(const std::vector<std::pair<double, double>>& points, double distance,
                                              double eps);

}  // namespace gearkit::cam
