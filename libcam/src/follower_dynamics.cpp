// Kinetostatics of the follower train: forces, torque, stress at each cam angle.
#include <gearkit/cam/follower_dynamics.hpp>

#include "dynamics_terms.hpp"

#include <cmath>
#include <numbers>

namespace gearkit::cam {
namespace {

constexpr double kMetresPerMm = 1e-3;

Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
Vec2 operator*(double k, Vec2 a) { return {k * a.x, k * a.y}; }
double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
Vec2 J(Vec2 a) { return {-a.y, a.x}; }

/// Velocity [m/s] of the follower's material point at `point` [mm, fixed frame].
Vec2 follower_velocity(const CamDesign& d, const ContactState& c, double qdot, Vec2 point) {
  if (d.follower.motion == FollowerMotion::translating) return {0, qdot};
  const Vec2 pivot{d.follower.pivot_distance, 0};
  return (c.spin_per_s * qdot * kMetresPerMm) * J(point - pivot);  // qdot = dpsi/dt
}

/// Velocity [m/s] of the cam's material point at `point` [mm, fixed frame].
Vec2 cam_velocity(const CamDesign& d, double omega, Vec2 point) {
  return (rotation_sign(d.rotation) * omega * kMetresPerMm) * J(point);
}

/// Absolute angular speed of a rolling roller [rad/s]: the roller's point at the contact moves
/// with the cam's point there, tangentially.
double rolling_speed(const CamDesign& d, const ContactState& c, double omega, double qdot) {
  const double Rr = roller_radius(d) * kMetresPerMm;
  const Vec2 t = J(c.normal);
  const Vec2 v_centre = follower_velocity(d, c, qdot, c.follower_point);
  return (dot(t, v_centre) - dot(t, cam_velocity(d, omega, c.contact_fixed))) / Rr;
}

/// Radius of curvature of the follower's surface at the contact [m]: the roller, a flat face
/// (infinity), a knife edge (NaN: no Hertz contact).
double follower_radius(const CamDesign& d) {
  switch (d.follower.contact) {
    case Contact::roller: return roller_radius(d) * kMetresPerMm;
    case Contact::flat_face: return INFINITY;
    case Contact::knife_edge: return NAN;
  }
  return NAN;
}

/// The surface carrying a negative Q under form closure.
CamDesign other_wall(const CamDesign& d) {
  return d.follower.closure == Closure::groove ? outer_wall_of(d) : conjugate_cam_of(d);
}

/// Contact force, sliding, rolling and stress on the surface `s` carrying Q.
void contact_quantities(const CamDesign& s, const FollowerTrain& train, double omega, const ContactState& c,
                        double h, const ContactMaterial* material, DynamicState& out) {
  out.lever = h;
  out.contact_force = out.wall == 0 ? 0.0 : out.force / h;
  out.rho_cam = 1 / c.curvature_profile * kMetresPerMm;
  if (s.follower.contact == Contact::roller) {
    out.roller_speed = rolling_speed(s, c, omega, out.v) - detail::follower_spin(s, c, out.v);
  } else {
    const Vec2 rel = follower_velocity(s, c, out.v, c.contact_fixed) - cam_velocity(s, omega, c.contact_fixed);
    out.sliding_speed = std::abs(dot(J(c.normal), rel));
  }
  out.hertz_stress = NAN;
  if (material && material->width > 0 && s.follower.contact != Contact::knife_edge) {
    const double E_star = contact_modulus(material->E_cam, material->nu_cam, material->E_follower, material->nu_follower);
    out.hertz_stress = hertz_line_stress(out.contact_force, material->width, out.rho_cam, follower_radius(s), E_star);
  }
  (void)train;
}

/// The roller's tangential force to follow the cam's acceleration of its spin: I alpha / R_r.
double roller_traction(const CamDesign& s, const FollowerTrain& train, double omega, double theta) {
  if (train.roller_inertia <= 0 || s.follower.contact != Contact::roller) return 0;
  const double h = 1e-5;
  auto spin = [&](double t) {
    const detail::Terms tt = detail::terms_at(s, t);
    return rolling_speed(s, tt.contact, omega, tt.dq * omega);
  };
  const double alpha = (spin(theta + h) - spin(theta - h)) / (2 * h) * omega;
  return train.roller_inertia * std::abs(alpha) / (roller_radius(s) * kMetresPerMm);
}

}  // namespace

double damping_for_ratio(const FollowerTrain& train, double zeta) {
  return 2 * zeta * std::sqrt((train.spring_rate + train.stiffness) * train.mass);
}

double contact_modulus(double E1, double nu1, double E2, double nu2) {
  return 1 / ((1 - nu1 * nu1) / E1 + (1 - nu2 * nu2) / E2);
}

double hertz_line_stress(double force, double width, double rho_1, double rho_2, double E_star) {
  if (!(width > 0)) return NAN;
  const double relative = 1 / rho_1 + 1 / rho_2;  // 1/R
  if (!(relative > 0)) return NAN;
  if (force <= 0) return 0;
  return std::sqrt(force / width * E_star * relative / std::numbers::pi);
}

double lever(const CamDesign& design, const ContactState& c) {
  const double per_unit = design.follower.motion == FollowerMotion::translating ? 1.0 : kMetresPerMm;
  return dot(c.normal, c.point_per_s) * per_unit;
}

DynamicState dynamic_state(const CamDesign& d, const FollowerTrain& train, double omega, double theta,
                           const ContactMaterial* material) {
  const detail::Terms t = detail::terms_at(d, theta);
  DynamicState out;
  out.theta = theta;
  out.q = t.q, out.v = t.dq * omega, out.a = t.d2q * omega * omega;
  out.force = detail::generalised_force(train, t, omega);
  const bool form = d.follower.closure != Closure::spring;
  out.wall = out.force >= 0 ? 1 : form ? -1 : 0;
  if (out.wall == -1) {
    const CamDesign other = other_wall(d);
    const ContactState c2 = contact_at(other, theta);
    contact_quantities(other, train, omega, c2, lever(other, c2), material, out);
    out.traction = roller_traction(other, train, omega, theta);
  } else {
    contact_quantities(d, train, omega, t.contact, t.h, material, out);
    out.traction = roller_traction(d, train, omega, theta);
  }
  // Virtual power: the shaft supplies Q dq/dt and the friction losses at a sliding contact.
  out.torque = out.force * t.dq + train.friction * std::abs(out.contact_force) * out.sliding_speed / omega;
  out.power = out.torque * omega;
  return out;
}

std::vector<DynamicState> dynamics_over_turn(const CamDesign& d, const FollowerTrain& train, double omega,
                                             int samples, const ContactMaterial* material) {
  std::vector<DynamicState> out;
  out.reserve(samples);
  for (int i = 0; i < samples; ++i)
    out.push_back(dynamic_state(d, train, omega, d.program.start() + 2 * std::numbers::pi * i / samples, material));
  return out;
}

}  // namespace gearkit::cam
