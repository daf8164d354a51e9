#pragma once
// Position, velocity and acceleration analysis of a Model at one instant, as free functions
// on (const Model&, Data&). Units SI (m, rad, s).
//
// The system is square when the model has as many equations (joints + elements + drivers) as
// coordinates; it is solved with the sparse LU of SuiteSparse's KLU (ordering analysed once
// per model, pivots reused from one position to the next while they stay good), which keeps
// a chain of N loops linear in N and a four-bar well under a microsecond per factorisation. A model with redundant but
// consistent equations (more rows than coordinates, e.g. a parallelogram with an extra link)
// is solved in the least-squares sense with column-pivoting QR.
#include <gearkit/kin/data.hpp>
#include <string>

namespace gearkit::kin {

struct SolverOptions {
  double tolerance = 1e-10;      ///< on max |Phi_i| [m or rad]
  int max_iterations = 30;       ///< Newton-Raphson iterations before giving up
  double max_angle_step = 0.5;   ///< [rad] a larger Newton step is scaled down (keeps the branch)
  /// Take the first Newton step with the factorisation already in the Data (a chord step),
  /// evaluating Phi without its Jacobian. Only for a guess near the position where that
  /// factorisation was computed, as in a sweep; it saves one factorisation per position. A
  /// chord step that does not reduce the residual is undone.
  bool reuse_factorization = false;
};

/// The outcome of a position analysis.
struct PositionReport {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;   ///< max |Phi_i| at the returned q
  bool singular = false;   ///< the Jacobian was singular (dead point / toggle / redundancy)
  std::string message;     ///< why it failed, one line; empty on success
};

/// Assembles Phi, Phi_q, Phi_t and gamma at (data.q, data.qd, t). Stores t in data.t.
void evaluate_constraints(const Model& model, Data& data, double t);

/// Factorises the assembled Phi_q. @returns false if it is singular (data.singular is set).
bool factorize(const Model& model, Data& data);

/// Newton-Raphson on Phi(q, t) = 0 from data.q (the initial guess: previous solution or the
/// drawn configuration, which selects the assembly branch). At most options.max_iterations
/// iterations; never throws. On success data.q is the solution and Phi_q is factorised at it.
/// On failure data.q is left at the initial guess and the report says why (under-driven model,
/// singular Jacobian, no convergence: the mechanism cannot be assembled at this input).
PositionReport solve_position(const Model& model, Data& data, double t, const SolverOptions& options = {});

/// solve_position from a drawing, with a fallback for a lazy one: a drawing whose links lie in
/// line (every angle drawn 0) puts Newton on a singular Jacobian although the mechanism
/// assembles. When the drawing itself fails that way (or does not converge), Newton is
/// restarted from 48 deterministic perturbations of the drawn link angles (0.1 to 1 rad) and the
/// regular assembly nearest the drawing (least sum of link-angle changes) is kept. @returns the
/// report of the solution kept, or the drawing's own report (data.q left at the drawing) when no
/// restart assembles either.
PositionReport assemble(const Model& model, Data& data, double t, const SolverOptions& options = {});

/// Solves Phi_q qd = -Phi_t for data.qd at the current position (after solve_position).
/// Also refreshes gamma with the new qd. @returns false if Phi_q is singular.
bool solve_velocity(const Model& model, Data& data);

/// The velocity analysis when only one driver moves: data.qd = input_speed * dq, where dq is
/// that driver's input_sensitivity() at the current position and input_speed [rad/s or m/s]
/// its input's rate (-Phi_t on its row). Exact when Phi_t vanishes on every other row; saves the
/// solve of solve_velocity(). Refreshes gamma like it. @returns false if Phi_q is singular.
bool solve_velocity_along(const Model& model, Data& data, const Eigen::VectorXd& dq, double input_speed);

/// Solves Phi_q qdd = gamma for data.qdd (after solve_velocity). @returns false if singular.
bool solve_acceleration(const Model& model, Data& data);

/// dq/df0: how the coordinates change per unit of driver `driver`'s input value, with the other
/// drivers held (the velocity field of a unit input speed). Needs a factorised Jacobian.
/// @returns an empty vector if Phi_q is singular.
Eigen::VectorXd input_sensitivity(const Model& model, Data& data, int driver);

/// The same into `dq` (resized only when its size differs). @returns false if Phi_q is singular.
bool input_sensitivity(const Model& model, Data& data, int driver, Eigen::VectorXd& dq);

/// Solves Phi_q x = rhs with the current factorisation (least squares when redundant).
Eigen::VectorXd solve_with_jacobian(Data& data, const Eigen::VectorXd& rhs);

/// Solves Phi_q^T y = rhs with the current factorisation (square systems only).
Eigen::VectorXd solve_with_jacobian_transpose(Data& data, const Eigen::VectorXd& rhs);

/// max |Phi_i| of the assembled Phi.
double residual(const Data& data);

/// Global position [m] of a body point at data.q, and its velocity [m/s] and acceleration
/// [m/s^2] from data.qd and data.qdd.
Eigen::Vector2d point_position(const Data& data, const BodyPoint& p);
Eigen::Vector2d point_velocity(const Data& data, const BodyPoint& p);
Eigen::Vector2d point_acceleration(const Data& data, const BodyPoint& p);

}  // namespace gearkit::kin
