#pragma once
// The LU factorisation of a square constraint Jacobian Phi_q, by SuiteSparse's KLU (private to
// libkin). KLU is the sparse LU written for circuit simulation, where a matrix of fixed pattern
// is factorised again and again with new values: exactly a sweep of a mechanism. Its symbolic
// analysis (block triangular form, AMD ordering) is done once per pattern, and refactorisations
// reuse the pivot sequence of the last full factorisation while it stays well conditioned.
#include <Eigen/SparseCore>
#include <vector>

struct klu_common_struct;

namespace gearkit::kin {

class JacobianLU {
 public:
  JacobianLU();
  ~JacobianLU();
  JacobianLU(const JacobianLU&) = delete;
  JacobianLU& operator=(const JacobianLU&) = delete;

  /// Factorises `a` (square, compressed column storage). The first call fixes the pattern;
  /// later calls must pass a matrix of the same pattern (only the values change).
  /// @returns false if `a` is singular (a zero pivot, or rcond() <= 1e-13).
  bool factorize(const Eigen::SparseMatrix<double>& a);

  bool singular() const { return singular_; }
  /// Reciprocal condition estimate: KLU's cheap ratio of the smallest to the largest pivot, or,
  /// when that ratio falls below 1e-4, the reciprocal of KLU's 1-norm condition estimate.
  double rcond() const { return rcond_; }
  /// Sign of det(a) (+1 or -1; 0 when singular). Its change along a path of configurations
  /// shows that the path crossed a singular configuration (a change of assembly branch).
  int determinant_sign() const { return determinant_sign_; }

  /// Solves a x = b in place for `columns` right-hand sides stored one after another in `b`.
  /// Needs a successful factorize().
  void solve(double* b, int columns = 1);
  /// Solves a^T y = b in place.
  void solve_transpose(double* b);

 private:
  bool factor_from_scratch(const Eigen::SparseMatrix<double>& a);
  void finish(const Eigen::SparseMatrix<double>& a);
  double pivot_ratio() const;

  klu_common_struct* common_ = nullptr;
  void* symbolic_ = nullptr;  // klu_symbolic*
  void* numeric_ = nullptr;   // klu_numeric*
  int n_ = 0;
  bool singular_ = true;
  double rcond_ = 0.0;
  double rcond_at_pivoting_ = 0.0;  // rcond right after the last full factorisation
  int column_parity_ = 1;           // sign of KLU's fill-reducing column permutation
  int row_parity_ = 1;              // sign of the row permutation of the last full factorisation
  int determinant_sign_ = 0;
  std::vector<char> visited_;       // scratch for permutation parities
};

}  // namespace gearkit::kin
