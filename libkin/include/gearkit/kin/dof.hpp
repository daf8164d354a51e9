#pragma once
// Degrees of freedom: the Gruebler-Kutzbach count and the rank of the constraint Jacobian.
#include <gearkit/kin/data.hpp>
#include <string>
#include <vector>

namespace gearkit::kin {

struct DofReport {
  int moving_bodies = 0;
  int constraint_equations = 0;  ///< joints and elements, drivers excluded
  int gruebler = 0;              ///< 3 * moving_bodies - constraint_equations
  std::string gruebler_count;    ///< the count written out, e.g. "3*5 - 2*6 - 2*1 = 1"
  int rank = 0;                  ///< rank of Phi_q (drivers excluded) at data.q
  int dof = 0;                   ///< coordinates - rank: the true mobility at this configuration
  int redundant = 0;             ///< constraint_equations - rank (0 when the counts agree)
  /// Names of constraint rows that are linearly dependent on the others ("joint 'R2'
  /// row 1"), when redundant > 0.
  std::vector<std::string> redundant_rows;
  int drivers = 0;               ///< driver equations in the model
};

/// Gruebler-Kutzbach count and the rank of Phi_q at data.q (call after solve_position so
/// that the rank is that of an assembled configuration). The rank uses column-pivoting QR of
/// Phi_q^T with a relative threshold of 1e-9.
DofReport dof(const Model& model, Data& data);

}  // namespace gearkit::kin
