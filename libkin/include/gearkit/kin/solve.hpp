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

// Contracts common to every function below that takes (const Model&, Data&): `data` must have
// been made for `model` as it is now (data.hpp). They call check_data() first and throw
// DataMismatch otherwise: a programming error, never bad input. A constraint's evaluate() must
// not throw (constraint.hpp), so nothing else is thrown but std::bad_alloc where a function
// allocates its result. Numerical failure (a singular Jacobian, no convergence) is reported in
// the return value, never thrown.

/// Assembles Phi, Phi_q, Phi_t and gamma at (data.q, data.qd, t). Stores t in data.t.
/// @param t  time [s] (the drivers' inputs move with it)
/// @throws DataMismatch if `data` was not made for `model` as it is now.
void evaluate_constraints(const Model& model, Data& data, double t);

/// Factorises the assembled Phi_q (after evaluate_constraints); sets data.factored,
/// data.singular, data.rcond and data.determinant_sign. @returns false if it is singular.
/// @throws DataMismatch if `data` was not made for `model` as it is now.
bool factorize(const Model& model, Data& data);

/// Newton-Raphson on Phi(q, t) = 0 from data.q (the initial guess: previous solution or the
/// drawn configuration, which selects the assembly branch). At most options.max_iterations
/// iterations. On success data.q is the solution and Phi_q is factorised at it. On failure
/// data.q is left at the initial guess and the report says why (under-driven model, singular
/// Jacobian, no convergence: the mechanism cannot be assembled at this input); numerical
/// failure is never thrown.
/// @param t  time [s]
/// @param options  tolerance on max |Phi_i| [m or rad], iterations, largest angle step [rad]
/// @throws DataMismatch if `data` was not made for `model` as it is now (the one exception: it
///   is a programming error, checked before any iteration).
PositionReport solve_position(const Model& model, Data& data, double t, const SolverOptions& options = {});

/// solve_position from a drawing, with a fallback for a lazy one: a drawing whose links lie in
/// line (every angle drawn 0) puts Newton on a singular Jacobian although the mechanism
/// assembles. When the drawing itself fails that way (or does not converge), Newton is
/// restarted from 48 deterministic perturbations of the drawn link angles (0.1 to 1 rad) and the
/// regular assembly nearest the drawing (least sum of link-angle changes) is kept. @returns the
/// report of the solution kept, or the drawing's own report (data.q left at the drawing) when no
/// restart assembles either.
/// @param t  time [s]
/// @param options  as for solve_position
/// @throws DataMismatch if `data` was not made for `model` as it is now.
PositionReport assemble(const Model& model, Data& data, double t, const SolverOptions& options = {});

/// Solves Phi_q qd = -Phi_t for data.qd [m/s, rad/s] at the current position (after
/// solve_position). Also refreshes gamma with the new qd. @returns false if Phi_q is singular.
/// @throws DataMismatch if `data` was not made for `model` as it is now.
bool solve_velocity(const Model& model, Data& data);

/// The velocity analysis when only one driver moves: data.qd = input_speed * dq, where dq is
/// that driver's input_sensitivity() at the current position. Exact when Phi_t vanishes on
/// every other row; saves the solve of solve_velocity(). Refreshes gamma like it.
/// @param dq  the moving driver's input_sensitivity() [m or rad per unit input]
/// @param input_speed  its input's rate (-Phi_t on its row) [rad/s or m/s]
/// @returns false if Phi_q is singular.
/// @throws DataMismatch if `data` was not made for `model` as it is now.
bool solve_velocity_along(const Model& model, Data& data, const Eigen::VectorXd& dq, double input_speed);

/// Solves Phi_q qdd = gamma for data.qdd [m/s^2, rad/s^2] (after solve_velocity).
/// @returns false if Phi_q is singular.
/// @throws DataMismatch if `data` was not made for `model` as it is now.
bool solve_acceleration(const Model& model, Data& data);

/// dq/df0: how the coordinates change [m or rad] per unit of driver `driver`'s input value
/// [rad or m], with the other drivers held (the velocity field of a unit input speed).
/// Factorises Phi_q if it is not factorised. @returns an empty vector if Phi_q is singular.
/// @param driver  index in Model::drivers()
/// @throws DataMismatch if `data` was not made for `model` as it is now; std::out_of_range if
///   `driver` is not an index of Model::drivers().
Eigen::VectorXd input_sensitivity(const Model& model, Data& data, int driver);

/// The same into `dq` (resized only when its size differs, so that a sweep does not allocate).
/// @returns false if Phi_q is singular.
/// @throws DataMismatch, std::out_of_range as the function above.
bool input_sensitivity(const Model& model, Data& data, int driver, Eigen::VectorXd& dq);

/// Solves Phi_q x = rhs with the current factorisation (least squares when redundant). The
/// caller guarantees a factorisation that is not singular (factorize() returned true); no
/// model is given, so nothing is checked.
/// @param rhs  one entry per equation, in the units of that equation's Phi row
/// @throws std::bad_alloc only (the result is a new vector).
Eigen::VectorXd solve_with_jacobian(Data& data, const Eigen::VectorXd& rhs);

/// Solves Phi_q^T y = rhs with the current factorisation (square systems only), under the
/// same precondition as solve_with_jacobian.
/// @param rhs  one entry per coordinate
/// @throws std::bad_alloc only (the result is a new vector).
Eigen::VectorXd solve_with_jacobian_transpose(Data& data, const Eigen::VectorXd& rhs);

/// max |Phi_i| of the assembled Phi [m or rad, per row]; 0 for a model without equations.
/// Never throws.
double residual(const Data& data);

/// Global position [m] of a body point at data.q, and its velocity [m/s] and acceleration
/// [m/s^2] from data.qd and data.qdd.
/// @param p  a body index (kGround or an index of Model::bodies() the Data was made for) and a
///   local point [m]; not checked. Never throw.
Eigen::Vector2d point_position(const Data& data, const BodyPoint& p);
Eigen::Vector2d point_velocity(const Data& data, const BodyPoint& p);
Eigen::Vector2d point_acceleration(const Data& data, const BodyPoint& p);

}  // namespace gearkit::kin
