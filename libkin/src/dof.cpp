#include <gearkit/kin/dof.hpp>

#include <gearkit/kin/solve.hpp>

#include "sparse_rank.hpp"
#include "tolerances.hpp"

#include <map>

namespace gearkit::kin {

namespace {

using tolerance::kRankTolerance;  // relative threshold of the rank tests: tolerances.hpp

// The rows of Phi_q the mobility counts (joints and elements; drivers are left out), with the
// constraint each belongs to; fills the counts and the written-out Gruebler-Kutzbach sum.
struct CountedRows {
  std::vector<int> rows;
  std::vector<int> constraint;  ///< index in Model::constraints() of each row
};

CountedRows count_rows(const Model& model, DofReport& r) {
  CountedRows counted;
  std::map<std::string, std::pair<int, int>> by_kind;  // kind -> (equations each, how many)
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    const ModelConstraint& mc = model.constraints()[k];
    const int m = mc.constraint->equations();
    if (mc.constraint->is_driver()) {
      r.drivers += m;
      continue;
    }
    auto& entry = by_kind[mc.constraint->kind()];
    entry.first = m;
    entry.second += 1;
    for (int i = 0; i < m; ++i) {
      counted.rows.push_back(mc.first_row + i);
      counted.constraint.push_back(static_cast<int>(k));
    }
  }
  r.moving_bodies = static_cast<int>(model.bodies().size());
  r.constraint_equations = static_cast<int>(counted.rows.size());
  r.gruebler = 3 * r.moving_bodies - r.constraint_equations;
  r.gruebler_count = "3*" + std::to_string(r.moving_bodies);
  for (const auto& [kind, count] : by_kind)
    r.gruebler_count += " - " + std::to_string(count.first) + "*" + std::to_string(count.second) + " (" + kind + ")";
  r.gruebler_count += " = " + std::to_string(r.gruebler);
  return counted;
}

// "'R2' (revolute) row 1": names only the rows reported, so that large models do not build a
// string per row.
std::string row_name(const Model& model, const CountedRows& counted, int k) {
  const ModelConstraint& mc = model.constraints()[static_cast<std::size_t>(counted.constraint[static_cast<std::size_t>(k)])];
  const int m = mc.constraint->equations();
  const int within = counted.rows[static_cast<std::size_t>(k)] - mc.first_row;
  return "'" + mc.name + "' (" + mc.constraint->kind() + ")" + (m > 1 ? " row " + std::to_string(within + 1) : "");
}

// Phi_q^T restricted to the counted rows (coordinates x counted rows), so that dependent rows
// of Phi_q are dependent columns here.
Eigen::SparseMatrix<double> counted_rows_transposed(const Data& data, const std::vector<int>& rows) {
  const Eigen::SparseMatrix<double> all = data.phi_q.transpose();  // column j = row j of Phi_q
  Eigen::SparseMatrix<double> jt(all.rows(), static_cast<int>(rows.size()));
  std::vector<int> sizes(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) sizes[i] = static_cast<int>(all.col(rows[i]).nonZeros());
  jt.reserve(sizes);
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (Eigen::SparseMatrix<double>::InnerIterator it(all, rows[i]); it; ++it) jt.insert(it.row(), static_cast<int>(i)) = it.value();
  jt.makeCompressed();
  return jt;
}

// Small models: column-pivoting Householder QR of the dense Phi_q^T; the columns the pivoting
// leaves beyond the rank are the dependent rows.
SparseRank dense_rank(const Eigen::SparseMatrix<double>& jt) {
  const Eigen::MatrixXd dense = jt;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(dense);
  qr.setThreshold(kRankTolerance);
  SparseRank r;
  r.rank = static_cast<int>(qr.rank());
  const auto& perm = qr.colsPermutation().indices();
  for (int k = r.rank; k < perm.size(); ++k) r.dependent_columns.push_back(perm(k));
  return r;
}

}  // namespace

DofReport dof(const Model& model, Data& data) {
  check_data(model, data);
  DofReport r;
  const CountedRows counted = count_rows(model, r);
  evaluate_constraints(model, data, data.t);
  const int n = model.coordinates();
  if (!counted.rows.empty() && n > 0) {
    const Eigen::SparseMatrix<double> jt = counted_rows_transposed(data, counted.rows);
    const SparseRank rank = data.sparse ? sparse_rank(jt, kRankTolerance) : dense_rank(jt);
    r.rank = rank.rank;
    for (int k : rank.dependent_columns) r.redundant_rows.push_back(row_name(model, counted, k));
  }
  r.dof = n - r.rank;
  r.redundant = r.constraint_equations - r.rank;
  return r;
}

}  // namespace gearkit::kin
