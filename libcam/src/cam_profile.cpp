#include <gearkit/cam/cam_profile.hpp>

#include "extremum.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gearkit::cam {
namespace {

constexpr double two_pi = 2 * std::numbers::pi;

/// The pitch curve (or flat-face envelope) as a counter-clockwise curve of t in [0, 2 pi]: the
/// contact runs clockwise for a counter-clockwise cam, so then t runs against theta.
struct CounterClockwiseCurve {
  const CamDesign& design;
  double sigma;

  double theta_of(double t) const {
    const double t0 = design.program.start();
    return sigma < 0 ? t0 + t : t0 + two_pi - t;
  }
  double t_of(double theta) const {
    const double rel = theta - design.program.start();
    return std::clamp(sigma < 0 ? rel : two_pi - rel, 0.0, two_pi);
  }
  CurvePoint operator()(double t) const {
    const ContactState c = contact_at(design, theta_of(t));
    const double k = sigma < 0 ? 1 : -1;
    return {c.pitch.x, c.pitch.y, k * c.pitch_tangent.x, k * c.pitch_tangent.y};
  }
};

std::vector<double> breaks_of(const CamDesign& d, double sigma) {
  std::vector<double> breaks;
  for (int i = 0; i <= 36; ++i) breaks.push_back(two_pi * i / 36);
  for (const Segment& s : d.program.segments()) {
    const double rel = s.end - d.program.start();
    breaks.push_back(sigma < 0 ? rel : two_pi - rel);
    for (const TablePoint& p : s.table) {
      const double r = p.theta - d.program.start();
      breaks.push_back(sigma < 0 ? r : two_pi - r);
    }
  }
  for (double& b : breaks) b = std::clamp(b, 0.0, two_pi);
  return breaks;
}

/// The pitch curve's corners in the curve's parameter: t runs against theta for a
/// counter-clockwise cam, so there the curve arrives with the reversed tangent after the corner.
std::vector<CurveCorner> corners_of(const CamDesign& d, const CounterClockwiseCurve& curve) {
  std::vector<CurveCorner> out;
  for (const PitchCorner& c : pitch_corners(d)) {
    const bool along = curve.sigma < 0;
    const Vec2 in = along ? c.before : Vec2{-c.after.x, -c.after.y};
    const Vec2 out_t = along ? c.after : Vec2{-c.before.x, -c.before.y};
    out.push_back({curve.t_of(c.theta), in.x, in.y, out_t.x, out_t.y});
  }
  return out;
}

/// The envelope as straight segments, each split until the largest distance of the curve from
/// its chord (found by maximisation, extremum.hpp) is within the tolerance; `error` receives
/// the largest such distance.
void chords(const CounterClockwiseCurve& curve, double ta, double tb, const CurvePoint& a, const CurvePoint& b,
            double tolerance, int depth, std::vector<Piece>& out, double& error) {
  const Piece chord{a.x, a.y, b.x, b.y, 0, 0, 0, 0};
  auto distance = [&](double t) {
    const CurvePoint p = curve(t);
    return distance_to_piece(chord, p.x, p.y);
  };
  const double e = detail::find_maximum(distance, ta, tb, 8, 1e-4 * (tb - ta)).value;
  if (e <= tolerance || depth >= 30) {
    out.push_back(chord);
    error = std::max(error, e);
    return;
  }
  const double tm = 0.5 * (ta + tb);
  const CurvePoint m = curve(tm);
  chords(curve, ta, tm, a, m, tolerance, depth + 1, out, error);
  chords(curve, tm, tb, m, b, tolerance, depth + 1, out, error);
}

std::vector<Piece> polyline_of(const CamDesign& d, double sigma, double tolerance, double& error) {
  CounterClockwiseCurve curve{d, sigma};
  std::vector<double> t = breaks_of(d, sigma);
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end(), [](double a, double b) { return b - a <= 1e-9 * two_pi; }), t.end());
  std::vector<Piece> out;
  error = 0;
  const CurvePoint first = curve(t.front());
  CurvePoint a = first;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const CurvePoint b = i + 2 == t.size() ? first : curve(t[i + 1]);
    chords(curve, t[i], t[i + 1], a, b, tolerance, 0, out, error);
    a = b;
  }
  return out;
}

}  // namespace

namespace {

/// The offsets of the fitted curve that will be exported, in the order given to the fit (after
/// the curve itself, offset 0).
struct Exports {
  double profile = 0, tool = 0, outer = 0, outer_tool = 0;
  bool has_profile = false, has_tool = false, has_outer = false, has_outer_tool = false;

  std::vector<double> offsets() const {
    std::vector<double> out;
    if (has_profile) out.push_back(profile);
    if (has_tool) out.push_back(tool);
    if (has_outer) out.push_back(outer);
    if (has_outer_tool) out.push_back(outer_tool);
    return out;
  }
};

Exports exports_of(const CamDesign& d, const ProfileOptions& options) {
  Exports e;
  const double Rr = roller_radius(d);
  const bool groove = d.follower.closure == Closure::groove && d.follower.surface == Surface::cam;
  e.has_profile = Rr > 0, e.profile = Rr;
  e.has_tool = options.cutter_radius.has_value();
  if (e.has_tool) e.tool = Rr - *options.cutter_radius;
  e.has_outer = groove, e.outer = -Rr;
  e.has_outer_tool = groove && e.has_tool, e.outer_tool = -e.tool;
  return e;
}

/// A flat face's envelope, or a roller or knife edge's pitch curve, offset into what is exported.
void offsets_from_spline(const CamDesign& d, const ProfileOptions& options, const Exports& e, const BiarcSpline& spline,
                         CamProfile& out) {
  std::size_t next = 1;
  out.pitch_error = spline.max_error[0];
  out.profile_error = e.has_profile ? spline.max_error[next++] : spline.max_error[0];
  if (e.has_tool) out.tool_path_error = spline.max_error[next++];
  if (e.has_outer) out.outer_error = spline.max_error[next++];
  if (e.has_outer_tool) out.outer_tool_path_error = spline.max_error[next++];
  if (d.follower.contact == Contact::flat_face) {
    out.profile.push_back(pieces_of(spline));
  } else {
    out.pitch_curve = pieces_of(spline);
    const OffsetCurve profile = offset_closed_spline(spline, e.profile);
    out.profile = profile.loops;
    out.profile_trimmed = profile.trimmed;
  }
  if (e.has_tool) {
    const OffsetCurve tool = offset_closed_spline(spline, e.tool);
    out.tool_path = tool.loops;
    out.tool_path_trimmed = tool.trimmed && !out.profile_trimmed;
  }
  if (e.has_outer) {
    const OffsetCurve outer = offset_closed_spline(spline, e.outer);
    out.outer_wall = outer.loops;
    out.outer_wall_trimmed = outer.trimmed;
  }
  if (e.has_outer_tool) {
    const OffsetCurve tool = offset_closed_spline(spline, e.outer_tool);
    out.outer_tool_path = tool.loops;
    out.outer_tool_path_trimmed = tool.trimmed && !out.outer_wall_trimmed;
  }
  (void)options;
}

}  // namespace

CamProfile synthesize_profile(const CamDesign& d, const ProfileOptions& options) {
  CamProfile out;
  const double sigma = rotation_sign(d.rotation);
  const CounterClockwiseCurve curve{d, sigma};
  // The tolerance must hold for what is exported: the profile (the pitch curve offset by the
  // roller), the groove's outer wall and the tool paths, not only for the fitted curve.
  const Exports e = exports_of(d, options);
  FitOptions fit{options.tolerance, 24, e.offsets(), corners_of(d, curve)};
  BiarcSpline spline;
  try {
    spline = fit_biarcs(curve, breaks_of(d, sigma), fit, true);
  } catch (const FitError& err) {
    if (d.follower.contact != Contact::flat_face) {
      throw GeometryError(fmt::format("cannot fit arcs within {:.6g} mm to the cam near cam angle {:.6g} deg "
                                      "(a cusp or a corner of the profile)",
                                      options.tolerance,
                                      std::fmod(curve.theta_of(err.parameter()), two_pi) * 180 / std::numbers::pi));
    }
    // A flat face whose envelope has cusps: no arcs fit the folds; keep the envelope as it is,
    // as straight segments within the tolerance.
    out.profile.push_back(polyline_of(d, sigma, options.tolerance, out.profile_error));
    out.pitch_error = out.profile_error;
    out.profile_is_polyline = true;
    return out;
  }
  out.biarcs = spline.knots.size() - 1;
  offsets_from_spline(d, options, e, spline, out);
  return out;
}

double max_deviation(const std::vector<std::vector<Piece>>& loops, const std::vector<Vec2>& points) {
  std::vector<Piece> all;
  for (const auto& loop : loops) all.insert(all.end(), loop.begin(), loop.end());
  if (all.empty()) return INFINITY;
  const long n = static_cast<long>(all.size());
  long cursor = 0;
  double worst = 0;
  auto full_scan = [&](const Vec2& p, double& best) {
    for (long k = 0; k < n; ++k) {
      const double d = distance_to_piece(all[k], p.x, p.y);
      if (d < best) best = d, cursor = k;
    }
  };
  bool first = true;
  for (const Vec2& p : points) {
    double best = INFINITY;
    if (first) {
      full_scan(p, best);
      first = false;
    } else {
      // Consecutive points lie on the same or neighbouring pieces: look around the last one.
      const long start = cursor;
      for (long k = -6; k <= 6; ++k) {
        const long idx = ((start + k) % n + n) % n;
        const double d = distance_to_piece(all[idx], p.x, p.y);
        if (d < best) best = d, cursor = idx;
      }
      if (best > 1e-2) full_scan(p, best);
    }
    worst = std::max(worst, best);
  }
  return worst;
}

}  // namespace gearkit::cam
