#pragma once
// Rank and dependent columns of a sparse matrix by SuiteSparseQR (private to libkin): the
// multifrontal sparse QR of SuiteSparse, with a fill-reducing column ordering and Heath's rank
// detection. Its cost follows the fill of R, which for the banded Jacobians of linkages
// (chains, lattices) grows linearly with the size, where a dense or left-looking QR grows
// cubically.
#include <Eigen/SparseCore>
#include <vector>

namespace gearkit::kin {

struct SparseRank {
  int rank = 0;
  /// Columns of the matrix that depend on the others (as many as columns - rank), in
  /// increasing order. Which columns of a dependent set are named follows SuiteSparseQR's
  /// ordering: each is dependent on the columns ordered before it.
  std::vector<int> dependent_columns;
};

/// Rank of `a` with a column counted dependent when, after the Householder reflections of the
/// columns ordered before it, its remaining 2-norm is at most `relative_tolerance` times the
/// largest column 2-norm of `a`. @throws std::runtime_error if SuiteSparseQR fails (out of
/// memory).
SparseRank sparse_rank(const Eigen::SparseMatrix<double>& a, double relative_tolerance);

}  // namespace gearkit::kin
