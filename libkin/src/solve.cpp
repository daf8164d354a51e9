#include <gearkit/kin/solve.hpp>

#include <algorithm>
#include <cmath>

namespace gearkit::kin {

namespace {

// Below this many coordinates a dense LU beats the sparse one (no symbolic analysis, no
// indirection); above it the sparse LU keeps chains of loops near-linear.
constexpr int kDenseLimit = 64;

bool is_square(const Model& model) { return model.equations() == model.coordinates(); }

}  // namespace

Data::Data(const Model& model) {
  const int n = model.coordinates();
  const int m = model.equations();
  q = Eigen::VectorXd::Zero(n);
  for (std::size_t i = 0; i < model.bodies().size(); ++i) {
    const Body& b = model.bodies()[i];
    q.segment<2>(3 * static_cast<int>(i)) = b.position_guess;
    q(3 * static_cast<int>(i) + 2) = b.angle_guess;
  }
  qd = Eigen::VectorXd::Zero(n);
  qdd = Eigen::VectorXd::Zero(n);
  inputs.resize(static_cast<int>(model.drivers().size()));
  for (std::size_t k = 0; k < model.drivers().size(); ++k) inputs(static_cast<int>(k)) = model.drivers()[k].value;
  lambda = Eigen::VectorXd::Zero(m);
  phi = Eigen::VectorXd::Zero(m);
  phi_t = Eigen::VectorXd::Zero(m);
  gamma = Eigen::VectorXd::Zero(m);
  work = Eigen::VectorXd::Zero(n);
  step = Eigen::VectorXd::Zero(n);
  sparse = n > kDenseLimit && is_square(model);

  local.resize(model.constraints().size());
  std::vector<Eigen::Triplet<double>> pattern;
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    const Constraint& c = *model.constraints()[k].constraint;
    Local& l = local[k];
    l.bodies = c.bodies();
    l.states.assign(l.bodies.size(), BodyState{});
    const int rows = c.equations();
    const int cols = 3 * static_cast<int>(l.bodies.size());
    l.phi = Eigen::VectorXd::Zero(rows);
    l.phi_t = Eigen::VectorXd::Zero(rows);
    l.gamma = Eigen::VectorXd::Zero(rows);
    l.phi_q = Eigen::MatrixXd::Zero(rows, cols);
    if (sparse) {
      const int r0 = model.constraints()[k].first_row;
      for (int r = 0; r < rows; ++r)
        for (std::size_t b = 0; b < l.bodies.size(); ++b)
          if (l.bodies[b] != kGround)
            for (int c3 = 0; c3 < 3; ++c3) pattern.emplace_back(r0 + r, 3 * l.bodies[b] + c3, 0.0);
    }
  }
  if (sparse) {
    phi_q_sparse.resize(m, n);
    phi_q_sparse.setFromTriplets(pattern.begin(), pattern.end());
    phi_q_sparse.makeCompressed();
    for (std::size_t k = 0; k < model.constraints().size(); ++k) {
      Local& l = local[k];
      const int r0 = model.constraints()[k].first_row;
      const int rows = static_cast<int>(l.phi.size());
      const int cols = static_cast<int>(l.phi_q.cols());
      l.value_index.assign(static_cast<std::size_t>(rows * cols), -1);
      for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
          const int body = l.bodies[static_cast<std::size_t>(c / 3)];
          if (body == kGround) continue;
          const double* base = phi_q_sparse.valuePtr();
          l.value_index[static_cast<std::size_t>(r * cols + c)] =
              static_cast<int>(&phi_q_sparse.coeffRef(r0 + r, 3 * body + c % 3) - base);
        }
    }
  } else {
    phi_q_dense = Eigen::MatrixXd::Zero(m, n);
  }
}

Data::~Data() = default;

Eigen::MatrixXd Data::jacobian() const {
  if (sparse) return Eigen::MatrixXd(phi_q_sparse);
  return phi_q_dense;
}

namespace {

// Evaluates every constraint at (data.q, data.qd, t); with `jacobian` false only Phi, Phi_t
// and gamma are refreshed and the factorised Phi_q is kept (velocity changes gamma, not Phi_q).
void evaluate_rows(const Model& model, Data& data, double t, bool jacobian) {
  data.t = t;
  if (jacobian && data.sparse)
    std::fill(data.phi_q_sparse.valuePtr(), data.phi_q_sparse.valuePtr() + data.phi_q_sparse.nonZeros(), 0.0);
  else if (jacobian)
    data.phi_q_dense.setZero();
  int driver = 0;
  const auto& constraints = model.constraints();
  for (std::size_t k = 0; k < constraints.size(); ++k) {
    const Constraint& c = *constraints[k].constraint;
    Data::Local& l = data.local[k];
    for (std::size_t b = 0; b < l.bodies.size(); ++b) {
      BodyState& s = l.states[b];
      const int body = l.bodies[b];
      if (body == kGround) {
        s = BodyState{};
      } else {
        const int i = 3 * body;
        s.r = data.q.segment<2>(i);
        s.theta = data.q(i + 2);
        s.r_dot = data.qd.segment<2>(i);
        s.omega = data.qd(i + 2);
      }
    }
    ConstraintInput in{l.states, t, 0.0};
    if (c.is_driver()) in.input = data.inputs(driver++);
    ConstraintOutput out{l.phi, l.phi_q, l.phi_t, l.gamma};
    c.evaluate(in, out);
    const int r0 = constraints[k].first_row;
    const int rows = static_cast<int>(l.phi.size());
    data.phi.segment(r0, rows) = l.phi;
    data.phi_t.segment(r0, rows) = l.phi_t;
    data.gamma.segment(r0, rows) = l.gamma;
    if (!jacobian) continue;
    const int cols = static_cast<int>(l.phi_q.cols());
    if (data.sparse) {
      double* values = data.phi_q_sparse.valuePtr();
      for (int r = 0; r < rows; ++r)
        for (int col = 0; col < cols; ++col) {
          const int at = l.value_index[static_cast<std::size_t>(r * cols + col)];
          if (at >= 0) values[at] += l.phi_q(r, col);
        }
    } else {
      for (std::size_t b = 0; b < l.bodies.size(); ++b) {
        if (l.bodies[b] == kGround) continue;
        data.phi_q_dense.block(r0, 3 * l.bodies[b], rows, 3) += l.phi_q.block(0, 3 * static_cast<int>(b), rows, 3);
      }
    }
  }
  if (jacobian) data.factored = false;
}

}  // namespace

void evaluate_constraints(const Model& model, Data& data, double t) { evaluate_rows(model, data, t, true); }

namespace {
bool factorize_impl(const Model& model, Data& data, bool estimate_condition);
}

bool factorize(const Model& model, Data& data) { return factorize_impl(model, data, true); }

namespace {

bool factorize_impl(const Model& model, Data& data, bool estimate_condition) {
  data.factored = true;
  data.singular = false;
  data.determinant_sign = 0;
  data.rcond = 1.0;
  if (data.sparse) {
    if (!data.sparse_pattern_analysed) {
      data.sparse_lu.analyzePattern(data.phi_q_sparse);
      data.sparse_pattern_analysed = true;
    }
    data.sparse_lu.factorize(data.phi_q_sparse);
    if (data.sparse_lu.info() != Eigen::Success) {
      data.singular = true;
      return false;
    }
    data.determinant_sign = static_cast<int>(data.sparse_lu.signDeterminant());
    // SparseLU does not estimate the condition; a tiny pivot relative to the largest one is
    // the warning sign of a dead point.
    const double log_det = data.sparse_lu.logAbsDeterminant();
    if (!std::isfinite(log_det)) {
      data.singular = true;
      return false;
    }
    return true;
  }
  if (is_square(model)) {
    data.dense_lu.compute(data.phi_q_dense);
    const double det = data.dense_lu.determinant();
    // The condition estimate costs a few triangular solves; Newton iterations skip it (a
    // singular step shows up as non-finite) and the converged position gets it.
    data.rcond = estimate_condition ? data.dense_lu.rcond() : (det != 0.0 && std::isfinite(det) ? 1.0 : 0.0);
    if (!(data.rcond > 1e-13)) {
      data.singular = true;
      return false;
    }
    data.determinant_sign = det > 0 ? 1 : (det < 0 ? -1 : 0);
    return true;
  }
  // Redundant (more equations than coordinates) or under-driven: least squares via QR.
  data.dense_qr.setThreshold(1e-10);
  data.dense_qr.compute(data.phi_q_dense);
  if (data.dense_qr.rank() < model.coordinates()) {
    data.singular = true;
    return false;
  }
  return true;
}

}  // namespace

double residual(const Data& data) { return data.phi.size() ? data.phi.cwiseAbs().maxCoeff() : 0.0; }

Eigen::VectorXd solve_with_jacobian(Data& data, const Eigen::VectorXd& rhs) {
  if (data.sparse) return data.sparse_lu.solve(rhs);
  if (data.phi_q_dense.rows() == data.phi_q_dense.cols()) return data.dense_lu.solve(rhs);
  return data.dense_qr.solve(rhs);
}

Eigen::VectorXd solve_with_jacobian_transpose(Data& data, const Eigen::VectorXd& rhs) {
  if (data.sparse) return data.sparse_lu.transpose().solve(rhs);
  return data.dense_lu.transpose().solve(rhs);
}

PositionReport solve_position(const Model& model, Data& data, double t, const SolverOptions& options) {
  PositionReport report;
  if (model.equations() < model.coordinates()) {
    report.message = "under-driven: " + std::to_string(model.coordinates()) + " coordinates but only " +
                     std::to_string(model.equations()) + " equations (joints, elements and drivers)";
    return report;
  }
  data.work = data.q;  // the guess, restored on failure
  for (int iteration = 0; iteration <= options.max_iterations; ++iteration) {
    evaluate_constraints(model, data, t);
    report.residual = residual(data);
    report.iterations = iteration;
    if (!std::isfinite(report.residual)) break;
    const bool done = report.residual <= options.tolerance;
    const bool ok = factorize_impl(model, data, done);
    if (done) {
      report.converged = true;
      report.singular = !ok;
      return report;
    }
    if (!ok) {
      report.singular = true;
      break;
    }
    Eigen::VectorXd& step = data.step;
    if (data.sparse) step = data.sparse_lu.solve(data.phi);
    else if (model.equations() == model.coordinates()) step = data.dense_lu.solve(data.phi);
    else step = data.dense_qr.solve(data.phi);
    double largest_angle = 0.0;
    for (int i = 2; i < step.size(); i += 3) largest_angle = std::max(largest_angle, std::abs(step(i)));
    if (largest_angle > options.max_angle_step) step *= options.max_angle_step / largest_angle;
    if (!step.allFinite()) break;
    data.q -= step;
  }
  data.q = data.work;
  evaluate_constraints(model, data, t);
  report.converged = false;
  if (report.singular)
    report.message = "singular Jacobian: the mechanism is at or near a dead point, or its constraints are redundant";
  else
    report.message = "cannot assemble: Newton-Raphson did not converge in " + std::to_string(options.max_iterations) +
                     " iterations (residual " + std::to_string(report.residual) + ")";
  return report;
}

bool solve_velocity(const Model& model, Data& data) {
  if (!data.factored && !factorize(model, data)) return false;
  if (data.singular) return false;
  data.step = -data.phi_t;
  if (data.sparse) data.qd = data.sparse_lu.solve(data.step);
  else if (model.equations() == model.coordinates()) data.qd = data.dense_lu.solve(data.step);
  else data.qd = data.dense_qr.solve(data.step);
  // gamma depends on qd; Phi_q and its factorisation stay (q did not change).
  evaluate_rows(model, data, data.t, false);
  return true;
}

bool solve_acceleration(const Model& model, Data& data) {
  if (!data.factored && !factorize(model, data)) return false;
  if (data.singular) return false;
  if (data.sparse) data.qdd = data.sparse_lu.solve(data.gamma);
  else if (model.equations() == model.coordinates()) data.qdd = data.dense_lu.solve(data.gamma);
  else data.qdd = data.dense_qr.solve(data.gamma);
  return true;
}

Eigen::VectorXd input_sensitivity(const Model& model, Data& data, int driver) {
  if (!data.factored && !factorize(model, data)) return {};
  if (data.singular) return {};
  // d Phi / d f0 is -1 on the driver's row, so Phi_q dq/df0 = e_row.
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(model.equations());
  const Driver& d = model.drivers().at(static_cast<std::size_t>(driver));
  rhs(model.constraints()[static_cast<std::size_t>(d.constraint)].first_row) = 1.0;
  return solve_with_jacobian(data, rhs);
}

Eigen::Vector2d point_position(const Data& data, const BodyPoint& p) { return Model::point_position(data.q, p); }

Eigen::Vector2d point_velocity(const Data& data, const BodyPoint& p) {
  if (p.body == kGround) return Eigen::Vector2d::Zero();
  const int k = 3 * p.body;
  return data.qd.segment<2>(k) + data.qd(k + 2) * perp(rotate(data.q(k + 2), p.local));
}

Eigen::Vector2d point_acceleration(const Data& data, const BodyPoint& p) {
  if (p.body == kGround) return Eigen::Vector2d::Zero();
  const int k = 3 * p.body;
  const Eigen::Vector2d s = rotate(data.q(k + 2), p.local);
  const double w = data.qd(k + 2);
  return data.qdd.segment<2>(k) + data.qdd(k + 2) * perp(s) - w * w * s;
}

}  // namespace gearkit::kin
