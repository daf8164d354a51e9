#include "sparse_rank.hpp"

#include <SuiteSparseQR.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gearkit::kin {

namespace {

// cholmod's workspace, started and finished with the scope.
struct Cholmod {
  cholmod_common common;
  Cholmod() { cholmod_l_start(&common); }
  ~Cholmod() { cholmod_l_finish(&common); }
  Cholmod(const Cholmod&) = delete;
  Cholmod& operator=(const Cholmod&) = delete;
};

// A copy of `a` in cholmod's compressed-column form (64-bit indices, as SuiteSparseQR wants).
cholmod_sparse* to_cholmod(const Eigen::SparseMatrix<double>& a, cholmod_common& common) {
  cholmod_sparse* c = cholmod_l_allocate_sparse(static_cast<std::size_t>(a.rows()), static_cast<std::size_t>(a.cols()),
                                                static_cast<std::size_t>(a.nonZeros()), 1, 1, 0, CHOLMOD_REAL, &common);
  if (!c) throw std::runtime_error("sparse_rank: out of memory");
  auto* p = static_cast<SuiteSparse_long*>(c->p);
  auto* i = static_cast<SuiteSparse_long*>(c->i);
  auto* x = static_cast<double*>(c->x);
  SuiteSparse_long k = 0;
  for (int j = 0; j < a.outerSize(); ++j) {
    p[j] = k;
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, j); it; ++it, ++k) {
      i[k] = it.row();
      x[k] = it.value();
    }
  }
  p[a.outerSize()] = k;
  return c;
}

double largest_column_norm(const Eigen::SparseMatrix<double>& a) {
  double largest = 0.0;
  for (int j = 0; j < a.outerSize(); ++j) {
    double s = 0.0;
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, j); it; ++it) s += it.value() * it.value();
    largest = std::max(largest, s);
  }
  return std::sqrt(largest);
}

}  // namespace

SparseRank sparse_rank(const Eigen::SparseMatrix<double>& a, double relative_tolerance) {
  SparseRank r;
  const double scale = largest_column_norm(a);
  if (a.cols() == 0 || scale == 0.0) {
    for (int j = 0; j < a.cols(); ++j) r.dependent_columns.push_back(j);
    return r;
  }
  Cholmod cm;
  cholmod_sparse* c = to_cholmod(a, cm.common);
  SuiteSparseQR_factorization<double>* qr =
      SuiteSparseQR_factorize<double>(SPQR_ORDERING_DEFAULT, relative_tolerance * scale, c, &cm.common);
  cholmod_l_free_sparse(&c, &cm.common);
  if (!qr) throw std::runtime_error("sparse_rank: SuiteSparseQR failed (out of memory)");
  r.rank = static_cast<int>(qr->rank);
  // Rmap[j] >= rank marks column j of R (column Q1fill[j] of a) as dead; no Rmap: none is.
  if (qr->Rmap)
    for (int j = 0; j < a.cols(); ++j)
      if (qr->Rmap[j] >= qr->rank) r.dependent_columns.push_back(static_cast<int>(qr->Q1fill ? qr->Q1fill[j] : j));
  std::sort(r.dependent_columns.begin(), r.dependent_columns.end());
  SuiteSparseQR_free(&qr, &cm.common);
  return r;
}

}  // namespace gearkit::kin
