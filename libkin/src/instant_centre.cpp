#include <gearkit/kin/instant_centre.hpp>

#include <cmath>

namespace gearkit::kin {

namespace {
struct Motion2 {
  Eigen::Vector2d r = Eigen::Vector2d::Zero(), v = Eigen::Vector2d::Zero();
  double omega = 0.0;
};
Motion2 motion_of(const Eigen::VectorXd& q, const Eigen::VectorXd& v, int body) {
  Motion2 m;
  if (body == kGround) return m;
  m.r = q.segment<2>(3 * body);
  m.v = v.segment<2>(3 * body);
  m.omega = v(3 * body + 2);
  return m;
}
}  // namespace

std::optional<Eigen::Vector2d> instant_centre(const Data& data, int i, int j) {
  return instant_centre(data.q, data.qd, i, j);
}

std::optional<Eigen::Vector2d> instant_centre(const Eigen::VectorXd& q, const Eigen::VectorXd& v, int i, int j) {
  const Motion2 a = motion_of(q, v, i), b = motion_of(q, v, j);
  const double w = a.omega - b.omega;
  // Same velocity at P: (v_a - v_b) + omega_a perp(P - r_a) - omega_b perp(P - r_b) = 0.
  const Eigen::Vector2d c = -(a.v - b.v) + a.omega * perp(a.r) - b.omega * perp(b.r);
  const double scale = std::max({std::abs(a.omega), std::abs(b.omega), 1e-300});
  if (std::abs(w) <= 1e-12 * scale || w == 0.0) return std::nullopt;
  const Eigen::Vector2d centre = -perp(c) / w;
  // A body that translates through a parallelogram turns at rounding noise (1e-17 rad/s) and
  // would put its centre 5e15 m away: farther than 1e4 times the largest length a model may
  // hold (1e4 m, docs/units.md), the centre is the point at infinity of a translation.
  constexpr double kFarthestCentre = 1e8;  // m
  if (!(centre.norm() <= kFarthestCentre)) return std::nullopt;
  return centre;
}

std::optional<Eigen::Vector2d> line_intersection(const Eigen::Vector2d& a1, const Eigen::Vector2d& a2,
                                                 const Eigen::Vector2d& b1, const Eigen::Vector2d& b2) {
  const Eigen::Vector2d da = a2 - a1, db = b2 - b1;
  const double den = cross(da, db);
  if (std::abs(den) <= 1e-14 * da.norm() * db.norm() || den == 0.0) return std::nullopt;
  const double t = cross(b1 - a1, db) / den;
  return Eigen::Vector2d(a1 + t * da);
}

}  // namespace gearkit::kin
