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
/// that the rank is that of an assembled configuration, and away from singular ones: at a
/// dead point or change point the rank drops). The rank is that of Phi_q^T by a rank-revealing
/// QR with a relative threshold of 1e-9: column-pivoting Householder QR for models up to 64
/// coordinates, SuiteSparseQR (multifrontal, fill-reducing ordering, Heath's rank detection)
/// above, whose cost grows linearly with the size of chain- or lattice-like linkages (a chain
/// of 1000 four-bar loops, 6003 coordinates, in a few milliseconds). Evaluates the constraints
/// at data.q (refreshes Phi, Phi_q; the factorisation is marked stale).
/// @throws DataMismatch if `data` was not made for `model` as it is now; std::runtime_error if
///   SuiteSparseQR runs out of memory.
DofReport dof(const Model& model, Data& data);

}  // namespace gearkit::kin
