#pragma once
// The per-analysis workspace of a Model (Pinocchio's Data): coordinates, velocities,
// accelerations, multipliers, the assembled Phi, Phi_q, Phi_t, gamma and the factorised
// Jacobian. One Data per thread; it is sized once from the model and reused for every position
// so that a sweep does not allocate.
#include <gearkit/kin/model.hpp>
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

namespace gearkit::kin {

class JacobianLU;  // the sparse LU of Phi_q (SuiteSparse KLU), private to libkin

class Data {
 public:
  /// Sizes the workspace for `model` and starts from the model's guessed poses and the
  /// drivers' default values. A Data stays valid for `model` until a body, constraint or
  /// driver is added to it (check_data). @throws std::bad_alloc only.
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

  /// Phi_q in compressed column storage. Its pattern is fixed by the model: every entry a
  /// constraint can write is stored, even when its value is zero, so that the symbolic
  /// analysis of the LU is done once.
  Eigen::SparseMatrix<double> phi_q;

  /// True for models above 64 coordinates, where rank tests (dof.hpp) use a sparse QR.
  bool sparse = false;

  /// State of the last factorisation of Phi_q (see factorize()).
  bool factored = false;
  bool singular = false;
  int determinant_sign = 0;  ///< sign of det(Phi_q) for square systems (0 if singular/unknown)
  /// Reciprocal condition estimate of Phi_q: the ratio of the smallest to the largest LU pivot,
  /// or below 1e-4 the reciprocal of the 1-norm condition estimate (square systems); the ratio
  /// of the smallest to the largest diagonal entry of the pivoted QR's R (redundant ones).
  /// Small values mean a dead point, toggle or change point is near.
  double rcond = 0.0;

  /// Phi_q as a dense matrix (a copy). @throws std::bad_alloc only.
  Eigen::MatrixXd jacobian() const;

  // Workspace (read by the solver; not part of the results).
  std::vector<BodyState> body_states;  ///< per moving body at (q, qd), cos/sin of theta cached
  /// Where one constraint's bodies, their states and its Jacobian block sit in the flat arrays
  /// below (one allocation each for the whole model, so that large models stay in cache).
  struct Local {
    int rows = 0;         ///< equations of the constraint
    int first_slot = 0;   ///< first entry in local_bodies and local_states
    int slots = 0;        ///< bodies listed by the constraint
    int first_entry = 0;  ///< first entry of its block (rows x 3*slots, column-major) in
                          ///< local_phi_q
    int driver = -1;      ///< index in Model::drivers() for a driver, else -1
    int first_scatter = 0;  ///< its first entry in `scatter`
    int scatter_count = 0;  ///< entries of its block on moving bodies
  };
  /// Where an entry of a constraint's block (index from its first_entry) goes among Phi_q's
  /// values.
  struct Scatter {
    int entry = 0;
    int value = 0;
  };
  std::vector<Local> local;
  std::vector<int> local_bodies;
  std::vector<BodyState> local_states;
  std::vector<double> local_phi_q;
  std::vector<Scatter> scatter;
  /// True when some constraint lists a body twice, so that two block entries meet in one entry
  /// of Phi_q: it is then zeroed and summed into; otherwise each entry is simply assigned.
  bool sum_jacobian_entries = false;
  std::unique_ptr<JacobianLU> lu;                        ///< for square systems
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> dense_qr;  ///< for redundant (non-square) systems
  Eigen::VectorXd work;  ///< scratch of size coordinates()
  Eigen::VectorXd step;  ///< Newton step / right-hand side scratch

  /// What the workspace was sized for (Pinocchio's checkData): see check_data().
  struct Shape {
    int bodies = 0, constraints = 0, equations = 0, drivers = 0;
    std::uint64_t revision = 0;  ///< Model::revision() when the Data was made
  };
  Shape shape;
};

/// A Data used with a model it was not made for, or with its model after a change that resizes
/// the workspace (a body, constraint or driver added): a programming error.
class DataMismatch : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// Throws the DataMismatch that check_data() found. @throws DataMismatch always.
[[noreturn]] void throw_data_mismatch(const Model& model, const Data& data);

/// Checks that `data` was made for `model` as it is now. Every algorithm of libkin calls it
/// first, so a mismatch is this error instead of reads and writes out of bounds. Inline: it runs
/// a dozen times per position of a sweep.
/// @throws DataMismatch naming what differs.
inline void check_data(const Model& model, const Data& data) {
  const Data::Shape& s = data.shape;
  if (s.revision != model.revision() || s.equations != model.equations() ||
      s.bodies != static_cast<int>(model.bodies().size()) || s.constraints != static_cast<int>(model.constraints().size()) ||
      s.drivers != static_cast<int>(model.drivers().size()))
    throw_data_mismatch(model, data);
}

}  // namespace gearkit::kin
