#pragma once
// Plane geometry shared by the synthesis units (private to libsynth).
#include <gearkit/synth/linkage.hpp>

#include <cmath>
#include <optional>

namespace gearkit::synth::plane {

inline double cross(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }

inline Vec2 rotate(const Vec2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

inline double angle_of(const Vec2& v) { return std::atan2(v.y(), v.x()); }

/// Centre of the circle through a, b, c; nullopt when they are (nearly) in line.
inline std::optional<Vec2> circumcentre(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 u = b - a, v = c - a;
  const double d = 2 * cross(u, v);
  const double scale = u.squaredNorm() + v.squaredNorm();
  if (std::abs(d) <= 1e-12 * scale || scale == 0) return std::nullopt;
  const Vec2 centre(v.y() * u.squaredNorm() - u.y() * v.squaredNorm(), u.x() * v.squaredNorm() - v.x() * u.squaredNorm());
  return a + centre / d;
}

/// The point X with |X - A| = b and |X - O| = c, left (branch +1) or right (-1) of the directed
/// line A -> O; nullopt when the circles do not meet.
inline std::optional<Vec2> circle_intersection(const Vec2& A, double b, const Vec2& O, double c, int branch) {
  const Vec2 D = O - A;
  const double L = D.norm();
  if (L <= 0) return std::nullopt;
  const double x = (b * b - c * c + L * L) / (2 * L);
  const double h2 = b * b - x * x;
  if (h2 < -1e-12 * b * b) return std::nullopt;
  const Vec2 u = D / L;
  return A + x * u + branch * std::sqrt(h2 > 0 ? h2 : 0.0) * Vec2(-u.y(), u.x());
}

}  // namespace gearkit::synth::plane
