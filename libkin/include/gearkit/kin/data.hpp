#pragma once
// The per-analysis workspace of a Model (Pinocchio's Data): coordinates, velocities,
// accelerations, multipliers, the assembled Phi, Phi_q, Phi_t, gamma and the factorised
// Jacobian. One Data per thread; it is sized once from the model and reused for every position
// so that a sweep does not allocate.
#include <gearkit/kin/model.hpp>
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <memory>
#include <vector>

namespace gearkit::kin {

class Data {
 public:
  /// Sizes the workspace for `model` and starts from the model's guessed poses and the
  /// drivers' default values.
  explicit Data(const Model& model);
  Data(const Data&) = delete;
  Data& operator=(const Data&) = delete;
  ~Data();

  double t = 0.0;          ///< time of the last evaluation [s]
  Eigen::VectorXd q;       ///< coordinates (x, y, theta) per body [m, rad]
  Eigen::VectorXd qd;      ///< their time derivatives
  Eigen::VectorXd qdd;     ///< their second derivatives
  Eigen::VectorXd inputs;  ///< base value f0 of each driver [rad or m], in Model::drivers() order
  Eigen::VectorXd lambda;  ///< Lagrange multipliers, one per equation (after solve_forces)

  Eigen::VectorXd phi, phi_t, gamma;  ///< assembled at (q, qd, t) by evaluate_constraints

  /// True when the Jacobian is kept sparse (large models); otherwise dense.
  bool sparse = false;
  Eigen::MatrixXd phi_q_dense;                ///< valid when !sparse
  Eigen::SparseMatrix<double> phi_q_sparse;   ///< valid when sparse

  /// State of the last factorisation of Phi_q (see factorize()).
  bool factored = false;
  bool singular = false;
  int determinant_sign = 0;  ///< sign of det(Phi_q) for square systems (0 if singular/unknown)
  double rcond = 0.0;        ///< reciprocal condition estimate (dense square only; 1 otherwise)

  /// Phi_q as a dense matrix (a copy when sparse).
  Eigen::MatrixXd jacobian() const;

  // Workspace (read by the solver; not part of the results).
  struct Local {
    std::vector<int> bodies;
    std::vector<BodyState> states;
    Eigen::VectorXd phi, phi_t, gamma;
    Eigen::MatrixXd phi_q;
    std::vector<int> value_index;  ///< sparse: position in valuePtr per (row, column), -1 for ground
  };
  std::vector<Local> local;
  Eigen::PartialPivLU<Eigen::MatrixXd> dense_lu;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> dense_qr;  ///< for redundant (non-square) systems
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> sparse_lu;
  bool sparse_pattern_analysed = false;
  Eigen::VectorXd work;  ///< scratch of size coordinates()
  Eigen::VectorXd step;  ///< Newton step / right-hand side scratch
};

}  // namespace gearkit::kin
