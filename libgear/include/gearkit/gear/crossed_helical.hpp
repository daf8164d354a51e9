#pragma once
// Crossed helical (screw) gears: two involute helical gears on crossed, non-intersecting shafts,
// without profile shift (ISO 21771 for each gear; Niemann/Winter, Maschinenelemente III, and
// Shigley/Budynas for the pair). Shaft angle, centre distance, ratio, sliding velocity,
// efficiency in both directions and the forces at the mesh with friction. Lengths in mm, angles
// in rad, speeds in 1/min, velocities in m/s, torques in N m, forces in N, power in W.
//
// Conventions (docs/gear-types.md):
// - Helix angles are signed, > 0 right hand. The shaft angle is Sigma = beta1 + beta2 (same hands
//   add, opposite hands subtract); the formulas work with beta_i' = s beta_i, s = sign(Sigma), so
//   that beta1' + beta2' = |Sigma| > 0 (a pair of two left-hand gears is the mirror image of the
//   right-hand pair).
// - Frame: x along gear 1's axis, z the common perpendicular from gear 1's axis towards gear 2's,
//   y = z x x; gear 2's axis is g2 = (cos Sigma, -sin Sigma, 0). n1 > 0 turns gear 1 about +x;
//   gear 2 then turns about -g2 (omega2 = -omega1 z1/z2 about g2). Axial forces are signed along
//   each gear's own axis (+x, +g2).
// - A worm pair is the special case beta1 = 90 deg - gamma, beta2 = gamma (same hand).
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::gear {

// ---- formulas ----

/// Shaft angle Sigma = beta1 + beta2 (signed helix angles, > 0 right hand).
double crossed_shaft_angle(double beta1, double beta2);

/// Centre distance of unshifted gears a = (d1 + d2) / 2, d_i = z_i m_n / cos beta_i.
double crossed_centre_distance(double d1, double d2);

/// Sliding velocity at the pitch point along the teeth, m/s: v_g = v1 sin|Sigma| / cos beta2
/// (the normal components of the pitch velocities agree, v1 cos beta1 = v2 cos beta2).
double crossed_sliding_velocity(double v1, double Sigma, double beta2);

/// Efficiency with gear 1 driving (Niemann/Winter; reduces to tan gamma / tan(gamma + rho') for a
/// worm): eta_12 = cos(beta2' + rho') cos beta1' / (cos(beta1' - rho') cos beta2').
double crossed_efficiency(double beta1, double beta2, double rho);

// ---- the table ----

struct CrossedHelicalInput {
  int z1 = 0, z2 = 0;          ///< teeth, >= 3
  double m_n = 0;              ///< normal module, mm, > 0
  double alpha_n = 0.3490658503988659;  ///< normal pressure angle, rad
  double beta1 = 0, beta2 = 0; ///< signed helix angles, rad, |beta_i| < 85 deg, beta1 + beta2 != 0
  double h_aP = 1.0, h_fP = 1.25;  ///< basic rack coefficients
  std::optional<double> mu;    ///< friction coefficient (default 0.05, steel on steel, lubricated)
  double n1 = 0;               ///< speed of gear 1, 1/min, signed about +x
};

struct CrossedGear {
  int z = 0;
  double beta = 0, m_t = 0, alpha_t = 0, d = 0, d_a = 0, d_f = 0, p_z = 0;  ///< p_z the lead pi d / tan|beta|
  bool right_hand = true;
};

struct CrossedHelicalResult {
  std::array<CrossedGear, 2> gear;
  double Sigma = 0, a = 0, u = 0;  ///< shaft angle (signed), centre distance, z2 / z1
  double n1 = 0, n2 = 0;           ///< speeds of gear 1 about +x and of gear 2 about g2, 1/min
  double v1 = 0, v2 = 0, v_g = 0;
  double mu = 0, rho = 0, eta_12 = 0, eta_21 = 0;
  bool self_locking_12 = false, self_locking_21 = false;  ///< gear 1 / gear 2 cannot drive
  std::vector<std::string> warnings;
};

/// @throws GeometryError (gear_pair.hpp) naming the member at fault ("z1", "z2", "m_n",
/// "alpha_n", "beta1", "beta2", "mu", "n1").
CrossedHelicalResult compute_crossed_helical(const CrossedHelicalInput& in);

/// Forces for a torque (N m, > 0) on gear `on_gear` (1 or 2), gear `driver` (1 or 2) driving.
/// With K = F_n cos alpha_n / cos rho', gear 1 driving: F_t1 = K cos(beta1' - rho'),
/// F_t2 = K cos(beta2' + rho'), F_a1 = s K sin(beta1' - rho'), F_a2 = -s K sin(beta2' + rho');
/// gear 2 driving: F_t1 = K cos(beta1' + rho'), F_t2 = K cos(beta2' - rho'),
/// F_a1 = -s K sin(beta1' + rho'), F_a2 = s K sin(beta2' - rho'); F_r = F_n sin alpha_n (derived in
/// the pitch plane from the normal force and the friction along the teeth, docs/gear-types.md),
/// there with the axial forces counted along each gear's angular velocity; the struct holds them
/// along the frame's axes: F_a1 along +x, F_a2 along +g2 (signed).
struct CrossedForces {
  int driver = 1;
  double T1 = 0, T2 = 0, F_t1 = 0, F_t2 = 0, F_a1 = 0, F_a2 = 0, F_r = 0, F_n = 0;
  std::array<double, 3> on_1{}, on_2{};  ///< frame of the header; on_2 = -on_1
  double P_in = 0, P_out = 0, P_loss = 0;
};
/// @throws std::domain_error if torque <= 0, on_gear or driver is not 1 or 2, or the driver
/// cannot drive (efficiency <= 0).
CrossedForces crossed_forces(const CrossedHelicalResult& c, double alpha_n, double torque, int on_gear, int driver);

}  // namespace gearkit::gear
