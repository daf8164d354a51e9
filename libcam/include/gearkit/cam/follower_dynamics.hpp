#pragma once
// Dynamics of a cam's follower train, kinetostatic (the follower moves as the cam dictates; the
// forces follow from that motion): contact force, jump (separation) speed, spring sizing,
// camshaft torque and power, Hertz contact stress, roller speed and slip.
//
// The follower train is reduced to the follower coordinate q (Norton, Design of Machinery, 5th
// ed., ch. 15, "Cam dynamics", lumped model of fig. 15-1): q = s for a translating follower [m]
// and q = psi for an oscillating one [rad]. Units: SI throughout this header (m, kg, N, s, rad);
// the motion program's millimetres are converted here. "Force" means force [N] for a
// translating follower and torque about the pivot [N m] for an oscillating one, "mass" mass [kg]
// or moment of inertia [kg m^2], and so on: the equations are the same.
//
// Force closure: the cam pushes, the spring pulls back; the generalised force the cam must give,
//   Q(theta) = M q'' omega^2 + c q' omega + k q + F_0 + F_load          (Norton, eq. 15.8),
// must stay >= 0 (the contact force F_n = Q / h with the lever h = n . dx/dq > 0). Form closure
// (groove, conjugate cam): no spring; Q < 0 is taken by the other wall or the second roller.
#include <gearkit/cam/cam_design.hpp>

#include <optional>
#include <vector>

namespace gearkit::cam {

/// The follower train reduced to q (see the file comment for units).
struct FollowerTrain {
  double mass = 0;         ///< effective mass [kg] (oscillating: moment of inertia about the pivot [kg m^2])
  double spring_rate = 0;  ///< return spring [N/m] ([N m/rad]); form closure: usually 0
  double preload = 0;      ///< spring force at q = 0, the base circle [N] ([N m])
  double damping = 0;      ///< viscous damping [N s/m] ([N m s/rad])
  double load = 0;         ///< constant force pressing the follower onto the cam [N] ([N m]): weight, process
  double friction = 0;     ///< coefficient of friction at the contact: sliding for knife edges and flat faces
                           ///< (it adds to the camshaft torque), the grip limit of a roller (slip check)
  double roller_inertia = 0;  ///< roller about its pin [kg m^2]; 0: no slip check
  double stiffness = 0;    ///< follower train between the cam and its mass [N/m] ([N m/rad]); 0: rigid
};

/// Materials and width of the contact, for the Hertz stress.
struct ContactMaterial {
  double width = 0;          ///< length of the line contact (face width) [m]
  double E_cam = 206e9;      ///< Young's modulus of the cam [Pa]
  double nu_cam = 0.3;       ///< Poisson's ratio of the cam
  double E_follower = 206e9; ///< of the roller or face [Pa]
  double nu_follower = 0.3;
};

/// Damping coefficient for a damping ratio zeta of the follower train's own mode: c = 2 zeta
/// sqrt(k_total M), k_total = spring + follower stiffness (Norton, eq. 15.3).
double damping_for_ratio(const FollowerTrain& train, double zeta);

/// The dynamic state at one cam angle.
struct DynamicState {
  double theta = 0;          ///< cam angle [rad]
  double q = 0, v = 0, a = 0;  ///< follower coordinate [m | rad] and its rates [per s, per s^2]
  double force = 0;          ///< Q, the generalised force the cam(s) give [N | N m]
  double lever = 0;          ///< h = n . dx/dq of the driving surface [m per m | m per rad]
  double contact_force = 0;  ///< normal force at the contact carrying Q [N]; 0 when separated
  int wall = 1;              ///< which surface carries it: +1 the cam, -1 the groove's outer wall or the
                             ///< conjugate cam, 0 none (force closure with Q < 0: the follower has jumped)
  double torque = 0;         ///< camshaft torque, positive when the shaft drives the cam [N m]
  double power = 0;          ///< torque times speed [W]
  double sliding_speed = 0;  ///< relative tangential speed at a sliding contact [m/s]
  double roller_speed = 0;   ///< roller relative to its arm or slider [rad/s] (roller followers)
  double traction = 0;       ///< tangential force the roller needs to keep rolling [N]
  double rho_cam = 0;        ///< radius of curvature of the surface in contact, + convex towards the follower [m]
  double hertz_stress = 0;   ///< largest contact pressure p_0 [Pa]; NaN if not defined (knife edge, no width)
};

/// Reduced contact modulus E* with 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Johnson, Contact
/// Mechanics, eq. 4.22; Norton, Machine Design, eq. 7.9 uses m_i = (1 - nu_i^2)/E_i alike) [Pa].
double contact_modulus(double E1, double nu1, double E2, double nu2);

/// Largest pressure of a Hertz line contact between two parallel cylinders: p_0 = sqrt(P E* /
/// (pi R)), P = force / width, 1/R = 1/rho_1 + 1/rho_2 (Johnson, eq. 4.45; rho < 0 for a concave
/// surface, infinity for a flat one) [Pa]. NaN if 1/R <= 0 (a roller that does not fit the
/// hollow) or the width is not > 0; 0 for force <= 0.
double hertz_line_stress(double force, double width, double rho_1, double rho_2, double E_star);

/// The lever h of the surface the design describes: the normal component of the displacement
/// of the follower's force point per unit q [m per unit q] (translating: cos phi; oscillating
/// roller: L cos phi in m). > 0 where the cam pushes q up.
double lever(const CamDesign& design, const ContactState& contact);

/// The state at cam angle theta, cam speed omega [rad/s] (> 0). `material` may be null (no
/// Hertz stress). Form closure picks the wall by the sign of Q.
DynamicState dynamic_state(const CamDesign& design, const FollowerTrain& train, double omega, double theta,
                           const ContactMaterial* material);

/// dynamic_state at `samples` cam angles evenly over the turn, from the program's start.
std::vector<DynamicState> dynamics_over_turn(const CamDesign& design, const FollowerTrain& train, double omega,
                                             int samples, const ContactMaterial* material);

/// The smallest cam speed at which the contact force of a force-closed follower falls below
/// `min_force` [N] somewhere in the turn (0: the follower jumps off the cam).
struct JumpSpeed {
  double omega = 0;  ///< [rad/s]; 0 if the spring cannot hold min_force even at rest
  double theta = 0;  ///< where it first happens [rad]
};

/// Closed form per cam angle: Q - F_min h = A omega^2 + B omega + C with A = M q'', B = c q',
/// C = k q + F_0 + F_load - F_min h, whose smallest positive root is the speed at which this
/// angle separates; the jump speed is the least of these over the turn, found piece by piece
/// (sampled, then golden-section search). std::nullopt if no angle separates below omega_max.
std::optional<JumpSpeed> jump_speed(const CamDesign& design, const FollowerTrain& train, double min_force,
                                    double omega_max);

/// The least margin Q - F_min h over the turn at speed omega [N | N m], found (not sampled):
/// >= 0 keeps the contact force at or above F_min.
double least_contact_margin(const CamDesign& design, const FollowerTrain& train, double omega, double min_force);

/// Speed sweep: the least contact force margin at each speed (the margin's coefficients are
/// tabulated at 3600 angles once; the least sampled value is refined by golden-section search
/// around it), and the jump speed bracketed by the sweep and refined by bisection on that least
/// margin: a second method for jump_speed, which it must agree with.
struct SpeedSweep {
  std::vector<double> omega;   ///< [rad/s]
  std::vector<double> margin;  ///< least Q - F_min h [N | N m]
  std::optional<double> jump;  ///< [rad/s]
};
SpeedSweep sweep_speeds(const CamDesign& design, const FollowerTrain& train, double min_force,
                        const std::vector<double>& omegas);

/// A return spring for a force-closed follower.
struct SpringSizing {
  double spring_rate = 0;  ///< [N/m | N m/rad]
  double preload = 0;      ///< [N | N m]
  double damping = 0;      ///< the damping used [N s/m | N m s/rad]
};

/// What the sizing may choose.
struct SizingRequest {
  double omega = 0;                   ///< highest cam speed to hold the contact at [rad/s]
  double min_force = 0;               ///< least contact force wanted at every speed up to omega [N]
  std::optional<double> spring_rate;  ///< given: only the preload is sized
  std::optional<double> preload;      ///< given: only the rate is sized
  std::optional<double> damping_ratio;  ///< if given, c = 2 zeta sqrt(k_total M) follows the rate
};

/// The spring (rate k >= 0, preload F_0 >= 0) that keeps the contact force >= min_force at every
/// cam angle and every speed up to omega. Each angle asks k q + F_0 >= R(theta) = F_min h -
/// F_load + max over [0, omega] of -(M q'' w^2 + c q' w). Given the rate, F_0 = sup(R - k q);
/// given the preload, k = sup((R - F_0)/q) over q > 0. Given neither, the spring with the least
/// mean force over the turn (least mean contact force, friction, wear and torque): the line k q +
/// F_0 touching the upper hull of (q, R) over the mean lift. The supremum is found over the turn
/// (sampled at 3600 angles, then golden-section search), so the spring returned holds.
/// @throws std::invalid_argument if no spring can hold (a given preload below what the follower
///         needs at q = 0).
SpringSizing size_spring(const CamDesign& design, const FollowerTrain& train, const SizingRequest& request);

}  // namespace gearkit::cam
