#pragma once
// Coulomb friction in the joints of a mechanism at one configuration, used by solve_forces
// (kinetostatics.hpp) when the model has joints with friction (Model::add_friction): the friction
// forces that oppose the relative motion in each joint, the driving efforts with them for both
// senses of motion, the efficiencies and the self-locking (wedging) limit of the coefficients.
// SI throughout (N, N m, m/s, rad/s, W).
//
// Friction laws (JointFriction): prismatic, pin in slot and contact: a force mu |N| along the
// joint's axis (a contact's tangent) at the slider point (contact point), against the sliding
// velocity of the first body relative to the second; a prismatic with a bearing length b bears
// on both faces of its guide when its moment |M| > |N| b/2, and then carries mu 2|M|/b.
// Revolute: the couple rho |F| of the friction circle, rho = r sin(atan mu), against the relative
// angular velocity, with F the pin force (the resultant of normal and friction forces on the
// journal, so rho |F| = mu r N exactly).
//
// Method. Let y be the multipliers of the joints with friction and y0 their frictionless
// values. The friction forces Q_f(y) are positively homogeneous of degree 1 in y, and
//     y = y0 + k H(y),   H(y) = S Phi_q^-T Q_f(y),
// with k = 1 for the given coefficients (S selects the rows of y). It is solved by Newton's
// method (the Jacobian I - k dH/dy is m x m, m the rows of the joints with friction). Scaling
// every coefficient by k, the solution grows without bound as k approaches the smallest k* at
// which I - k dH/dy becomes singular: k* = 1 / (largest real eigenvalue of dH/dy), exact while
// the signs of the normal forces stay those of the solution (contacts, sliders) and refined by
// continuation towards k* otherwise (friction circles, whose force direction turns). For
// k >= k* no finite driving effort moves the mechanism in that sense: it is wedged, and mu_j k*
// are the coefficients at the wedging limit. Where the loads drive the mechanism (an incline or a
// screw lowering its load) it also self-locks when the friction takes all the power the loads
// give: the driver's power with friction crosses zero, at a factor found by regula falsi.
//
// The sense of motion: the velocities data.qd when they are not zero, else the motion of
// increasing input of driver `driver` (its input sensitivity: the quasi-static case); the
// reverse sense has every relative velocity turned. A joint that does not slide or turn in
// that motion carries no friction (static friction is not determined by the kinetostatics).
#include <gearkit/kin/data.hpp>

#include <limits>
#include <string>
#include <vector>

namespace gearkit::kin {

/// The friction in one joint for the forward sense.
struct JointFrictionForce {
  int constraint = 0;
  std::string name, kind;
  /// Normal force [N]: contact and pin in slot N = -lambda (for a contact positive when it
  /// presses), prismatic the guide's normal force; revolute the magnitude |F| of the pin force.
  double normal = 0.0;
  /// On the joint's first body: friction force [N] along the joint's axis (contact: its tangent,
  /// the line's axis) or, for a revolute, the friction couple [N m] counter-clockwise positive.
  double friction = 0.0;
  /// Relative velocity of the first body to the second in the motion analysed [m/s along the
  /// axis, or rad/s], per unit input speed in the quasi-static case.
  double sliding = 0.0;
  double power = 0.0;  ///< dissipated [W] at the actual velocities (data.qd; 0 when quasi-static)
};

/// The driving efforts with friction for one sense of motion.
struct FrictionSense {
  /// Wedged: no finite driving effort moves the mechanism in this sense (the coefficients are
  /// at or beyond k* = wedging_factor times their values; see above).
  bool wedged = false;
  double wedging_factor = std::numeric_limits<double>::infinity();  ///< k*; +inf if never
  /// Self-locking: wedged or, where the loads would drive the mechanism (the analysed driver's
  /// ideal power is negative: a screw or an incline lowering its load), the driver must now
  /// supply power (efficiency <= 0).
  bool self_locking = false;
  /// The smallest factor on every coefficient at which this sense becomes self-locking: the
  /// wedging factor or the factor where the driver's power with friction crosses zero; +inf if
  /// never. The critical coefficients are mu_j critical_factor.
  double critical_factor = std::numeric_limits<double>::infinity();
  std::vector<double> effort;      ///< per driver [N m or N] with friction; NaN when wedged
  /// Per driver: ideal power / power with friction when the driver drives (gives power), power
  /// with friction / ideal power when it is driven (the loads drive it; <= 0 when it locks);
  /// NaN when the driver does not move, its ideal power is zero or the sense is wedged.
  std::vector<double> efficiency;
};

struct FrictionAnalysis {
  std::vector<JointFrictionForce> joints;  ///< forward sense (empty when it is self-locking)
  std::vector<double> effort_ideal;        ///< per driver, without friction [N m or N]
  FrictionSense forward, reverse;
  double dissipated_power = 0.0;           ///< [W], forward, at the actual velocities
  std::vector<std::string> warnings;       ///< contacts that would open, joints at rest
};

/// The solution with friction, from the frictionless multipliers `lambda0` at a factorised,
/// square, regular Jacobian, for the applied and inertia forces `applied` (Q*). `lambda` gets
/// the forward multipliers with friction (lambda0 when the forward sense is self-locking) and
/// `friction_forces` the generalised friction forces Q_f (zero then).
/// @param driver  index in Model::drivers(): its increasing input is the forward sense
/// @param applied  Q* [N, N m per coordinate]; @param lambda0  one multiplier per equation
/// @throws std::invalid_argument if `driver` is out of range; DataMismatch if `data` was not
///   made for `model` as it is now (when data.qd is zero and the motion is the input's).
FrictionAnalysis analyse_friction(const Model& model, Data& data, int driver, const Eigen::VectorXd& applied,
                                  const Eigen::VectorXd& lambda0, Eigen::VectorXd& lambda,
                                  Eigen::VectorXd& friction_forces);

}  // namespace gearkit::kin
