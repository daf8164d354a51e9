// Chains of arcs as moves of a rotary table and a radial axis (G-code's angle-radius form).
#include <gearkit/cam/arc_spline.hpp>

#include "extremum.hpp"

#include <cmath>
#include <numbers>

namespace gearkit::cam {
namespace {

constexpr double pi = std::numbers::pi;

/// The point of a piece at fraction t of its length.
void point_on(const Piece& p, double t, double& x, double& y) {
  if (!p.is_arc()) {
    x = p.x0 + t * (p.x1 - p.x0), y = p.y0 + t * (p.y1 - p.y0);
    return;
  }
  const double a = std::atan2(p.y0 - p.cy, p.x0 - p.cx) + t * p.sweep, r = std::abs(p.radius);
  x = p.cx + r * std::cos(a), y = p.cy + r * std::sin(a);
}

/// (r, phi) of a point, phi taken within pi of `near` (continuous along a path).
PolarPoint polar_of(double x, double y, double near) {
  double phi = std::atan2(y, x);
  phi += 2 * pi * std::round((near - phi) / (2 * pi));
  return {std::hypot(x, y), phi};
}

/// Largest distance from the move a -> b, linear in r and phi, to the piece.
double move_error(const Piece& p, const PolarPoint& a, const PolarPoint& b) {
  auto dist = [&](double lambda) {
    const double r = a.r + lambda * (b.r - a.r), phi = a.phi + lambda * (b.phi - a.phi);
    return distance_to_piece(p, r * std::cos(phi), r * std::sin(phi));
  };
  return detail::find_maximum(dist, 0.0, 1.0, 8, 1e-4).value;
}

void split(const Piece& p, double t0, double t1, const PolarPoint& a, double tol, std::vector<PolarPoint>& out,
           int depth) {
  double x, y;
  point_on(p, t1, x, y);
  const PolarPoint b = polar_of(x, y, a.phi);
  if (depth >= 40 || move_error(p, a, b) <= tol) {
    out.push_back(b);
    return;
  }
  const double tm = 0.5 * (t0 + t1);
  point_on(p, tm, x, y);
  const PolarPoint m = polar_of(x, y, a.phi);
  split(p, t0, tm, a, tol, out, depth + 1);
  split(p, tm, t1, m, tol, out, depth + 1);
}

}  // namespace

std::vector<PolarPoint> polar_moves(const std::vector<Piece>& chain, double tolerance) {
  std::vector<PolarPoint> out;
  if (chain.empty()) return out;
  out.push_back(polar_of(chain.front().x0, chain.front().y0, 0));
  for (const Piece& p : chain) split(p, 0, 1, out.back(), tolerance, out, 0);
  return out;
}

}  // namespace gearkit::cam
