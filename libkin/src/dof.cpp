#include <gearkit/kin/dof.hpp>

#include <gearkit/kin/solve.hpp>

#include <Eigen/SparseQR>

#include <map>

namespace gearkit::kin {

DofReport dof(const Model& model, Data& data) {
  DofReport r;
  r.moving_bodies = static_cast<int>(model.bodies().size());
  evaluate_constraints(model, data, data.t);

  // Rows of the non-driver constraints, and a Gruebler count grouped by kind.
  std::vector<int> rows;
  std::vector<std::string> row_names;
  std::map<std::string, std::pair<int, int>> by_kind;  // kind -> (equations each, how many)
  for (const ModelConstraint& mc : model.constraints()) {
    const int m = mc.constraint->equations();
    if (mc.constraint->is_driver()) {
      r.drivers += m;
      continue;
    }
    auto& entry = by_kind[mc.constraint->kind()];
    entry.first = m;
    entry.second += 1;
    for (int i = 0; i < m; ++i) {
      rows.push_back(mc.first_row + i);
      row_names.push_back("'" + mc.name + "' (" + mc.constraint->kind() + ")" + (m > 1 ? " row " + std::to_string(i + 1) : ""));
    }
  }
  r.constraint_equations = static_cast<int>(rows.size());
  r.gruebler = 3 * r.moving_bodies - r.constraint_equations;
  r.gruebler_count = "3*" + std::to_string(r.moving_bodies);
  for (const auto& [kind, count] : by_kind)
    r.gruebler_count += " - " + std::to_string(count.first) + "*" + std::to_string(count.second) + " (" + kind + ")";
  r.gruebler_count += " = " + std::to_string(r.gruebler);

  const int n = model.coordinates();
  if (rows.empty() || n == 0) {
    r.rank = 0;
  } else if (data.sparse) {
    // Large models: sparse QR of Phi_q^T keeps memory and time near-linear.
    Eigen::SparseMatrix<double> selected(static_cast<int>(rows.size()), model.equations());
    std::vector<Eigen::Triplet<double>> pick;
    for (std::size_t i = 0; i < rows.size(); ++i) pick.emplace_back(static_cast<int>(i), rows[i], 1.0);
    selected.setFromTriplets(pick.begin(), pick.end());
    Eigen::SparseMatrix<double> jt = (selected * data.phi_q).transpose();
    jt.makeCompressed();
    Eigen::SparseQR<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> qr;
    qr.setPivotThreshold(1e-9);
    qr.compute(jt);
    r.rank = static_cast<int>(qr.rank());
    const auto& perm = qr.colsPermutation().indices();
    for (int k = r.rank; k < perm.size(); ++k) r.redundant_rows.push_back(row_names[static_cast<std::size_t>(perm(k))]);
  } else {
    const Eigen::MatrixXd full = data.jacobian();
    Eigen::MatrixXd jt(n, static_cast<int>(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i) jt.col(static_cast<int>(i)) = full.row(rows[i]).transpose();
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(jt);
    qr.setThreshold(1e-9);
    r.rank = static_cast<int>(qr.rank());
    // Columns of Phi_q^T that the pivoting left beyond the rank are the dependent rows.
    const auto& perm = qr.colsPermutation().indices();
    for (int k = r.rank; k < perm.size(); ++k) r.redundant_rows.push_back(row_names[static_cast<std::size_t>(perm(k))]);
  }
  r.dof = n - r.rank;
  r.redundant = r.constraint_equations - r.rank;
  return r;
}

}  // namespace gearkit::kin
