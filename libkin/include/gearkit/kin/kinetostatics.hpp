#pragma once
// Kinetostatics at one configuration (after solve_position, solve_velocity,
// solve_acceleration): driving efforts by virtual power and every constraint reaction by
// Lagrange multipliers, from masses, centres of mass, inertias, gravity, external forces and
// torques and linear springs. SI throughout (N, N m).
//
// Equations: M qdd + Phi_q^T lambda = Q, i.e. Phi_q^T lambda = Q* with Q* = Q - M qdd the
// applied forces plus d'Alembert's inertia forces. A driver's effort E_k (torque [N m] or force
// [N] it applies) satisfies, by virtual power with the virtual motion dq_k of a unit input,
//     E_k + Q* . dq_k = 0,
// and also E_k = -lambda_k (its multiplier). The two are computed independently.
//
// Friction (friction.hpp): with joints that have Coulomb friction, Q* also holds the friction
// forces Q_f of the forward motion, and both efforts and every reaction include them.
//
// Inverse kinetostatics: loads marked unknown (PointForce::unknown, BodyTorque::unknown) take the
// magnitudes for which the drivers with a given effort (Driver::effort) apply exactly that
// effort, by virtual power: E_k = -(Q*_known + sum_u F_u Q_u) . dq_k, linear in the F_u without
// friction, solved by Newton's method with it (impending motion in the forward sense).
#include <gearkit/kin/data.hpp>
#include <gearkit/kin/friction.hpp>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::kin {

/// The reaction carried by one constraint (Constraint::reaction), as the force and moment it
/// exerts on its first body, and the quantities the constraint names (an element's tooth or
/// contact force).
struct ConstraintReaction {
  int constraint = 0;
  std::string name, kind;
  int body = kGround;                          ///< the first body of the constraint
  Eigen::Vector2d force = Eigen::Vector2d::Zero();  ///< on `body` from the others [N]
  double moment = 0.0;  ///< on `body` [N m], about `at` if set (a prismatic's slider point)
  std::optional<Eigen::Vector2d> at;           ///< where the force acts [m] (joints)
  bool pin = false;                            ///< a force through `at` only (revolute, pin in slot)
  std::vector<ReactionValue> values;           ///< named by the constraint, SI
  Eigen::VectorXd lambda;                      ///< the raw multipliers of its rows
};

/// A massless, unloaded link with exactly two revolute joints: the force is along the line of
/// the joints.
struct TwoForceMember {
  int body = 0;
  std::string name;
  double axial_force = 0.0;  ///< [N], positive in tension, negative in compression
  bool tension() const { return axial_force > 0.0; }
};

/// The magnitude solved for an unknown load (inverse kinetostatics).
struct UnknownLoad {
  std::string name;
  bool torque = false;
  int index = 0;                                   ///< in Model::forces() or Model::torques()
  double value = 0.0;                              ///< [N] along the direction, or [N m] ccw
  Eigen::Vector2d force = Eigen::Vector2d::Zero(); ///< forces: the force vector [N]
};

struct ForceAnalysis {
  Eigen::VectorXd applied;               ///< Q* = Q - M qdd, per coordinate (with the solved unknown loads)
  Eigen::VectorXd lambda;                ///< multipliers, one per equation
  std::vector<double> effort_lagrange;   ///< per driver: -lambda [N m or N]
  std::vector<double> effort_virtual_power;  ///< per driver: -Q* . dq_k
  std::vector<ConstraintReaction> reactions;  ///< non-driver constraints
  std::vector<TwoForceMember> two_force_members;
  bool determinate = true;               ///< false for redundant models (reactions not unique)
  std::vector<UnknownLoad> unknown_loads;    ///< solved magnitudes, in the model's order
  std::optional<FrictionAnalysis> friction;  ///< when the model has joints with friction
  std::vector<std::string> warnings;         ///< friction: open contacts, self-locking, ...
};

/// One force on a free body: where it acts, the force and the moment about that point.
struct BodyForce {
  std::string source;  ///< the joint, element, driver or load it comes from; "weight", "inertia"
  std::string kind;    ///< "revolute", "contact", ..., "driver", "weight", "inertia", "force", "torque", "spring"
  Eigen::Vector2d at = Eigen::Vector2d::Zero();     ///< [m], ground frame
  Eigen::Vector2d force = Eigen::Vector2d::Zero();  ///< [N] on this body
  double moment = 0.0;                              ///< [N m] about `at`, ccw
  /// Joints with friction: the normal force and the friction force (or couple) on this body,
  /// signed along the joint's axis (NaN otherwise).
  double normal = std::numeric_limits<double>::quiet_NaN();
  double friction = std::numeric_limits<double>::quiet_NaN();
};

/// The free-body diagram of one moving body: every force on it, which balance (d'Alembert's
/// inertia forces included).
struct FreeBody {
  int body = 0;
  std::string name;
  std::vector<BodyForce> forces;
};

/// The free-body diagrams of every moving body from a force analysis at the same state: joint
/// reactions (normal and friction parts named), the drivers' efforts, elements (their generalised
/// forces, about the body's frame origin), weights, inertia forces and the loads.
/// @param forces  solve_forces' result at this data
/// @throws DataMismatch if `data` was not made for `model` as it is now.
std::vector<FreeBody> free_bodies(const Model& model, const Data& data, const ForceAnalysis& forces);

/// Generalised applied and inertia forces Q* [N, N m per coordinate] at the current state
/// (unknown loads left out). @throws DataMismatch if `data` was not made for `model`.
Eigen::VectorXd applied_forces(const Model& model, const Data& data);

/// Potential energy of gravity and springs [J] at data.q (for energy balances).
/// @throws DataMismatch if `data` was not made for `model` as it is now.
double potential_energy(const Model& model, const Data& data);

/// Kinetic energy [J] at data.q, data.qd.
/// @throws DataMismatch if `data` was not made for `model` as it is now.
double kinetic_energy(const Model& model, const Data& data);

/// Full kinetostatic analysis; stores lambda in data.lambda. Needs a factorised Jacobian at a
/// regular configuration. `driver` (default the first) gives the sense of motion of a
/// quasi-static analysis with friction (increasing input; see friction.hpp). With friction and
/// a forward sense that is self-locking, the efforts are NaN and lambda and the reactions are
/// the frictionless ones (a warning says so).
/// When the drivers' given efforts cannot determine the unknown loads (they do no work in the
/// motion, or friction locks it) the loads are NaN and a warning says why.
/// @param driver  index in Model::drivers() (the friction analysis' sense of motion)
/// @throws DataMismatch if `data` was not made for `model` as it is now.
/// @throws std::runtime_error if Phi_q is singular there (a dead point: the driving effort is
/// unbounded).
/// @throws std::invalid_argument if the unknown loads are not as many as the given efforts, or
///   (with friction) `driver` is not an index of Model::drivers().
ForceAnalysis solve_forces(const Model& model, Data& data, int driver = 0);

/// The same into `f`, whose storage (reactions, multipliers) is reused: a sweep analyses every
/// position without allocating them again. @throws as the function above.
void solve_forces(const Model& model, Data& data, int driver, ForceAnalysis& f);

}  // namespace gearkit::kin
