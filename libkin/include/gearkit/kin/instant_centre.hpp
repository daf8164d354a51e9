#pragma once
// Instant centres of rotation from the velocity state (after solve_velocity).
#include <gearkit/kin/data.hpp>
#include <optional>

namespace gearkit::kin {

/// The instant centre I_ij of body i relative to body j (either may be kGround): the point [m]
/// where both bodies have the same velocity. By Kennedy's theorem I_ij lies on the line
/// through I_0i and I_0j (the tests check this).
/// @returns nullopt when the relative motion is a translation (the centre is at infinity: also
///          a centre farther than 1e8 m, where a translating body's rounding-noise rotation puts
///          it) or both bodies move alike (|omega_i - omega_j| below 1e-12 of the speeds).
/// @param i, j  body indices (kGround or indices of Model::bodies()); not checked against a model.
/// Never throws.
std::optional<Eigen::Vector2d> instant_centre(const Data& data, int i, int j = kGround);

/// The same for coordinates q and any compatible velocity field v (e.g. input_sensitivity,
/// the velocities per unit input speed, which also serves quasi-static models).
/// @param q  coordinates [m, rad]
/// @param v  velocities [m/s, rad/s] or any field of the same units per unit input
/// Never throws.
std::optional<Eigen::Vector2d> instant_centre(const Eigen::VectorXd& q, const Eigen::VectorXd& v, int i, int j = kGround);

/// The intersection of line (a1, a2) with line (b1, b2) [m], as Kennedy's construction draws
/// a centre from two others. @returns nullopt for parallel lines. Never throws.
std::optional<Eigen::Vector2d> line_intersection(const Eigen::Vector2d& a1, const Eigen::Vector2d& a2,
                                                 const Eigen::Vector2d& b1, const Eigen::Vector2d& b2);

}  // namespace gearkit::kin
