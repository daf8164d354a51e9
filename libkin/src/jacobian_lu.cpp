#include "jacobian_lu.hpp"
#include "tolerances.hpp"

#include <klu.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gearkit::kin {

namespace {

klu_symbolic* as_symbolic(void* p) { return static_cast<klu_symbolic*>(p); }
klu_numeric* as_numeric(void* p) { return static_cast<klu_numeric*>(p); }

// KLU takes non-const pointers to the pattern and the values but does not write them.
int* pointers(const Eigen::SparseMatrix<double>& a) { return const_cast<int*>(a.outerIndexPtr()); }
int* indices(const Eigen::SparseMatrix<double>& a) { return const_cast<int*>(a.innerIndexPtr()); }
double* values(const Eigen::SparseMatrix<double>& a) { return const_cast<double*>(a.valuePtr()); }

// Sign of a permutation of 0..n-1: (-1)^(n - number of cycles).
int parity(const int* permutation, int n, std::vector<char>& visited) {
  visited.assign(static_cast<std::size_t>(n), 0);
  int cycles = 0;
  for (int i = 0; i < n; ++i) {
    if (visited[static_cast<std::size_t>(i)]) continue;
    ++cycles;
    for (int j = i; !visited[static_cast<std::size_t>(j)]; j = permutation[j]) visited[static_cast<std::size_t>(j)] = 1;
  }
  return (n - cycles) % 2 == 0 ? 1 : -1;
}

// Systems up to this many coordinates are factorised without the block triangular form.
constexpr int kSmallSystem = 64;
// The pivot and singularity tolerances: tolerances.hpp.
using tolerance::kCheapRcondLimit;
using tolerance::kPivotDecay;
using tolerance::kSingularRcond;

}  // namespace

JacobianLU::JacobianLU() : common_(new klu_common) {
  klu_defaults(common_);
  // No row scaling: every row of a constraint Jacobian already has a largest entry near 1 (the
  // unit coefficients of the coordinates it fixes), and the matrix comes from Eigen sorted and
  // without duplicates, so KLU's scaling pass and its input check would only cost time.
  common_->scale = -1;
}

JacobianLU::~JacobianLU() {
  klu_symbolic* s = as_symbolic(symbolic_);
  klu_numeric* f = as_numeric(numeric_);
  if (f) klu_free_numeric(&f, common_);
  if (s) klu_free_symbolic(&s, common_);
  delete common_;
}

bool JacobianLU::factor_from_scratch(const Eigen::SparseMatrix<double>& a) {
  klu_numeric* f = as_numeric(numeric_);
  if (f) klu_free_numeric(&f, common_);
  numeric_ = klu_factor(pointers(a), indices(a), values(a), as_symbolic(symbolic_), common_);
  if (!numeric_) return false;  // a zero pivot (KLU_SINGULAR) or out of memory
  row_parity_ = parity(as_numeric(numeric_)->Pnum, n_, visited_);
  rcond_at_pivoting_ = pivot_ratio();
  return true;
}

double JacobianLU::pivot_ratio() const {
  // KLU's klu_rcond, without its call overhead: min |U(k,k)| / max |U(k,k)|.
  const double* u = static_cast<const double*>(as_numeric(numeric_)->Udiag);
  double smallest = std::numeric_limits<double>::infinity(), largest = 0.0;
  for (int k = 0; k < n_; ++k) {
    const double v = std::abs(u[k]);
    if (!(v >= 0.0)) return 0.0;  // NaN
    smallest = std::min(smallest, v);
    largest = std::max(largest, v);
  }
  return largest > 0.0 ? smallest / largest : 0.0;
}

bool JacobianLU::factorize(const Eigen::SparseMatrix<double>& a) {
  singular_ = true;
  determinant_sign_ = 0;
  rcond_ = 0.0;
  if (a.rows() == 0) {  // nothing moves: the empty system is regular
    n_ = 0;
    singular_ = false;
    determinant_sign_ = 1;
    rcond_ = 1.0;
    return true;
  }
  if (!symbolic_) {
    n_ = static_cast<int>(a.rows());
    // A small mechanism is one block: the block triangular form only adds per-block overhead
    // to every solve. Large ones (chains of loops) split into many blocks, which pays.
    if (n_ <= kSmallSystem) {
      common_->btf = 0;
      common_->ordering = 1;  // COLAMD
    }
    symbolic_ = klu_analyze(n_, pointers(a), indices(a), common_);
    if (!symbolic_) return false;  // structurally singular or out of memory
    column_parity_ = parity(as_symbolic(symbolic_)->Q, n_, visited_);
  }
  bool ok = false;
  if (numeric_) {
    ok = klu_refactor(pointers(a), indices(a), values(a), as_symbolic(symbolic_), as_numeric(numeric_), common_) &&
         common_->status == KLU_OK;
    if (ok) {
      rcond_ = pivot_ratio();
      ok = rcond_ >= kPivotDecay * rcond_at_pivoting_;
    }
  }
  if (!ok) {
    if (!factor_from_scratch(a)) return false;
    rcond_ = rcond_at_pivoting_;
  }
  finish(a);
  return !singular_;
}

void JacobianLU::finish(const Eigen::SparseMatrix<double>& a) {
  if (!(rcond_ >= kCheapRcondLimit)) {
    if (klu_condest(pointers(a), values(a), as_symbolic(symbolic_), as_numeric(numeric_), common_) &&
        common_->condest > 0.0)
      rcond_ = 1.0 / common_->condest;
    else
      rcond_ = 0.0;
  }
  if (!std::isfinite(rcond_) || rcond_ <= kSingularRcond) {
    rcond_ = std::isfinite(rcond_) ? rcond_ : 0.0;
    return;
  }
  // P R A Q = L U with R > 0 (row scaling) and L unit lower triangular, block by block of the
  // block triangular form: det A has the sign of prod diag(U) times the permutations' signs.
  const double* u = static_cast<const double*>(as_numeric(numeric_)->Udiag);
  int sign = row_parity_ * column_parity_;
  for (int k = 0; k < n_; ++k)
    if (u[k] < 0.0) sign = -sign;
  determinant_sign_ = sign;
  singular_ = false;
}

void JacobianLU::solve(double* b, int columns) {
  if (n_ == 0) return;
  klu_solve(as_symbolic(symbolic_), as_numeric(numeric_), n_, columns, b, common_);
}

void JacobianLU::solve_transpose(double* b) {
  if (n_ == 0) return;
  klu_tsolve(as_symbolic(symbolic_), as_numeric(numeric_), n_, 1, b, common_);
}

}  // namespace gearkit::kin
