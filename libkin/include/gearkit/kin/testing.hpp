#pragma once
// A test helper for anyone who writes a Constraint (a joint, a driver, a plugin's element): its
// Phi_q, Phi_t and gamma checked against finite differences of its own Phi at random
// configurations. It is how libkin's built-in joints and libelements' elements (the element
// types the plugins register) are tested (tests/kin/test_joints.cpp, tests/elements), and what
// an out-of-tree plugin should run on its own elements. Not used by the solver.
//
// What is compared, at each configuration (q, qd, qdd, t, f0) drawn at random (positions in
// [-position_range, position_range] m, angles in [-pi, pi] rad, velocities and accelerations in
// [-rate_range, rate_range] per s and per s^2, t in [0, 1] s, f0 in [-1, 1]):
//   - Phi_q, column by column, with central differences of Phi in that coordinate (step h_q);
//   - Phi_t with central differences of Phi in t at fixed q (step h_t);
//   - gamma through the second time derivative of Phi along the trajectory
//     q(s) = q + qd s + qdd s^2 / 2:  d2/ds2 Phi(q(s), t + s) = Phi_q qdd - gamma (step h_t);
//   - that evaluate() writes every entry of its rows (the outputs are filled with NaN first).
// Central differences are exact to O(h^2): with the default steps the truncation error is
// ~1e-12 for the Jacobian and ~1e-8 for gamma for links of decimetres and rates of a few per
// second, far below the tolerances, while a missing term (a forgotten omega^2) is of order 1.
// A constraint whose Phi is only piecewise smooth (a cam's motion program at a segment end) can
// fail at a configuration within a step of the break: the default seed avoids the built-in ones.
#include <gearkit/kin/constraint.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace gearkit::kin::testing {

struct DerivativeCheckOptions {
  int configurations = 16;           ///< random configurations tried
  std::uint64_t seed = 20261129;     ///< of the random configurations (std::mt19937_64)
  double position_range = 0.2;       ///< [m] body origins in [-range, range]
  double rate_range = 2.0;           ///< [m/s, rad/s and /s^2] velocities and accelerations
  double h_q = 1e-6;                 ///< [m or rad] step of the Jacobian's differences
  double h_t = 1e-4;                 ///< [s] step of the time differences (Phi_t, gamma)
  /// An entry passes when |analytic - numeric| <= absolute + relative * max(|analytic|, |numeric|).
  double absolute = 1e-6, relative = 1e-6;
  /// The same for gamma, whose second differences carry rounding of eps |Phi| / h_t^2 (~2e-8).
  double absolute_gamma = 1e-5, relative_gamma = 1e-5;
};

/// One entry that disagrees with its finite difference.
struct DerivativeMismatch {
  std::string quantity;  ///< "Phi_q", "Phi_t", "gamma", or "not finite" (an entry evaluate() left or NaN)
  int configuration = 0;
  int row = 0;
  int column = -1;       ///< Phi_q: 3 * slot + (0 x, 1 y, 2 theta) of bodies(); else -1
  double analytic = 0.0, numeric = 0.0;
};

struct DerivativeReport {
  std::vector<DerivativeMismatch> mismatches;
  int entries_checked = 0;  ///< so that a test can see the check did something
  bool ok() const { return mismatches.empty(); }
  /// "kind: gamma row 0 configuration 3: analytic 1.2, numeric 3.4" for the first few
  /// mismatches, one per line; "" when ok().
  std::string describe(const std::string& kind) const;
};

/// Checks `constraint` at options.configurations random configurations of its bodies (kGround
/// entries stay at the origin with zero velocity, as the solver gives them; a body listed twice
/// gets one state and its columns are summed, as the solver assembles them). The constraint is
/// only evaluated, never added to a model.
/// @throws std::invalid_argument if options.configurations < 1 or a step is not > 0;
///   std::bad_alloc. Whatever evaluate() throws (it must throw nothing) passes through.
DerivativeReport check_derivatives(const Constraint& constraint, const DerivativeCheckOptions& options = {});

}  // namespace gearkit::kin::testing
