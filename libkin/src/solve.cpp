#include <gearkit/kin/solve.hpp>

#include "jacobian_lu.hpp"
#include "tolerances.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace gearkit::kin {

namespace {

// Above this many coordinates rank tests use a sparse QR (dof.cpp); the LU is sparse always.
constexpr int kDenseLimit = 64;

bool is_square(const Model& model) { return model.equations() == model.coordinates(); }

}  // namespace

void throw_data_mismatch(const Model& model, const Data& data) {
  const Data::Shape& s = data.shape;
  const int bodies = static_cast<int>(model.bodies().size()), constraints = static_cast<int>(model.constraints().size());
  const int drivers = static_cast<int>(model.drivers().size());
  throw DataMismatch("kin: the Data was made for a model with " + std::to_string(s.bodies) + " bodies, " +
                     std::to_string(s.constraints) + " constraints, " + std::to_string(s.equations) + " equations and " +
                     std::to_string(s.drivers) + " drivers (revision " + std::to_string(s.revision) +
                     "); this model has " + std::to_string(bodies) + ", " + std::to_string(constraints) + ", " +
                     std::to_string(model.equations()) + " and " + std::to_string(drivers) + " (revision " +
                     std::to_string(model.revision()) + "): make a new Data after changing the model");
}

Data::Data(const Model& model) {
  const int n = model.coordinates();
  const int m = model.equations();
  shape = {static_cast<int>(model.bodies().size()), static_cast<int>(model.constraints().size()), m,
           static_cast<int>(model.drivers().size()), model.revision()};
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
  sparse = n > kDenseLimit;
  body_states.assign(model.bodies().size(), BodyState{});
  if (is_square(model)) lu = std::make_unique<JacobianLU>();

  // Each constraint's slice of the flat workspace, and the pattern of Phi_q: every entry of
  // every constraint's block on a moving body.
  local.resize(model.constraints().size());
  std::vector<Eigen::Triplet<double>> pattern;
  int slots = 0, entries = 0;
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    const Constraint& c = *model.constraints()[k].constraint;
    const std::vector<int> bodies = c.bodies();
    Local& l = local[k];
    l.rows = c.equations();
    l.first_slot = slots;
    l.slots = static_cast<int>(bodies.size());
    l.first_entry = entries;
    slots += l.slots;
    entries += l.rows * 3 * l.slots;
    local_bodies.insert(local_bodies.end(), bodies.begin(), bodies.end());
    const int r0 = model.constraints()[k].first_row;
    for (int r = 0; r < l.rows; ++r)
      for (int body : bodies)
        if (body != kGround)
          for (int c3 = 0; c3 < 3; ++c3) pattern.emplace_back(r0 + r, 3 * body + c3, 0.0);
  }
  for (std::size_t d = 0; d < model.drivers().size(); ++d)
    local[static_cast<std::size_t>(model.drivers()[d].constraint)].driver = static_cast<int>(d);
  local_states.assign(static_cast<std::size_t>(slots), BodyState{});
  local_phi_q.assign(static_cast<std::size_t>(entries), 0.0);
  phi_q.resize(m, n);
  phi_q.setFromTriplets(pattern.begin(), pattern.end());
  phi_q.makeCompressed();
  // Where each entry of a block on a moving body goes in Phi_q's values. Rows of different
  // constraints never meet, so an entry is written by one block entry only, unless a
  // constraint lists the same body twice: then entries are summed into a zeroed Phi_q.
  std::vector<char> written(static_cast<std::size_t>(phi_q.nonZeros()), 0);
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    Local& l = local[k];
    l.first_scatter = static_cast<int>(scatter.size());
    const int r0 = model.constraints()[k].first_row;
    for (int c = 0; c < 3 * l.slots; ++c) {
      const int body = local_bodies[static_cast<std::size_t>(l.first_slot + c / 3)];
      if (body == kGround) continue;
      for (int r = 0; r < l.rows; ++r) {
        const int at = static_cast<int>(&phi_q.coeffRef(r0 + r, 3 * body + c % 3) - phi_q.valuePtr());
        if (written[static_cast<std::size_t>(at)]++) sum_jacobian_entries = true;
        scatter.push_back({c * l.rows + r, at});
      }
    }
    l.scatter_count = static_cast<int>(scatter.size()) - l.first_scatter;
  }
}

Data::~Data() = default;

Eigen::MatrixXd Data::jacobian() const { return Eigen::MatrixXd(phi_q); }

namespace {

// What evaluate_rows refreshes.
enum class Refresh {
  all,             // Phi, Phi_q, Phi_t, gamma at a new q
  after_velocity,  // Phi_t and gamma for a new qd at the same q (gamma depends on qd)
};

// Evaluates every constraint at (data.q, data.qd, t).
void evaluate_rows(const Model& model, Data& data, double t, Refresh refresh) {
  data.t = t;
  const bool jacobian = refresh == Refresh::all;
  // Each body's pose, with the cosine and sine of its angle computed once for all its joints.
  for (std::size_t b = 0; b < data.body_states.size(); ++b) {
    BodyState& s = data.body_states[b];
    const int i = 3 * static_cast<int>(b);
    if (refresh != Refresh::after_velocity) {
      s.r = data.q.segment<2>(i);
      s.set_theta(data.q(i + 2));
    }
    s.r_dot = data.qd.segment<2>(i);
    s.omega = data.qd(i + 2);
  }
  double* values = data.phi_q.valuePtr();
  if (jacobian && data.sum_jacobian_entries) std::fill(values, values + data.phi_q.nonZeros(), 0.0);
  static const BodyState ground{};
  const auto& constraints = model.constraints();
  for (std::size_t k = 0; k < constraints.size(); ++k) {
    const Data::Local& l = data.local[k];
    BodyState* states = data.local_states.data() + l.first_slot;
    const int* bodies = data.local_bodies.data() + l.first_slot;
    for (int b = 0; b < l.slots; ++b) states[b] = bodies[b] == kGround ? ground : data.body_states[static_cast<std::size_t>(bodies[b])];
    const ConstraintInput in{std::span<const BodyState>(states, static_cast<std::size_t>(l.slots)), t,
                             l.driver >= 0 ? data.inputs(l.driver) : 0.0};
    const int r0 = constraints[k].first_row;
    double* block = data.local_phi_q.data() + l.first_entry;
    ConstraintOutput out{data.phi.segment(r0, l.rows), Eigen::Map<Eigen::MatrixXd>(block, l.rows, 3 * l.slots),
                         data.phi_t.segment(r0, l.rows), data.gamma.segment(r0, l.rows)};
    constraints[k].constraint->evaluate(in, out);
    if (!jacobian) continue;
    const Data::Scatter* to = data.scatter.data() + l.first_scatter;
    if (data.sum_jacobian_entries)
      for (int e = 0; e < l.scatter_count; ++e) values[to[e].value] += block[to[e].entry];
    else
      for (int e = 0; e < l.scatter_count; ++e) values[to[e].value] = block[to[e].entry];
  }
  if (jacobian) data.factored = false;
}

}  // namespace

void evaluate_constraints(const Model& model, Data& data, double t) {
  check_data(model, data);
  evaluate_rows(model, data, t, Refresh::all);
}

bool factorize(const Model& model, Data& data) {
  check_data(model, data);
  data.factored = true;
  data.singular = false;
  data.determinant_sign = 0;
  data.rcond = 1.0;
  if (data.lu) {
    const bool ok = data.lu->factorize(data.phi_q);
    data.rcond = data.lu->rcond();
    data.determinant_sign = data.lu->determinant_sign();
    data.singular = !ok;
    return ok;
  }
  // Redundant (more equations than coordinates) or under-driven: least squares via QR.
  data.dense_qr.setThreshold(tolerance::kQrRankThreshold);
  data.dense_qr.compute(data.jacobian());
  if (data.dense_qr.rank() < model.coordinates()) {
    data.singular = true;
    return false;
  }
  // The same crude estimate KLU gives for the square case: the spread of the pivots.
  const auto pivots = data.dense_qr.matrixR().diagonal().head(model.coordinates()).cwiseAbs();
  data.rcond = pivots.minCoeff() / pivots.maxCoeff();
  return true;
}

namespace {

// Solves Phi_q x = b in place with the current factorisation (least squares when redundant).
void solve_in_place(Data& data, Eigen::VectorXd& b) {
  if (data.lu) data.lu->solve(b.data());
  else b = data.dense_qr.solve(b).eval();
}

}  // namespace

double residual(const Data& data) { return data.phi.size() ? data.phi.cwiseAbs().maxCoeff() : 0.0; }

Eigen::VectorXd solve_with_jacobian(Data& data, const Eigen::VectorXd& rhs) {
  Eigen::VectorXd x = rhs;
  solve_in_place(data, x);
  return x;
}

Eigen::VectorXd solve_with_jacobian_transpose(Data& data, const Eigen::VectorXd& rhs) {
  Eigen::VectorXd y = rhs;
  if (data.lu) data.lu->solve_transpose(y.data());
  else y = data.dense_qr.transpose().solve(rhs);
  return y;
}

namespace {

double largest_angle(const Eigen::VectorXd& step) {
  double largest = 0.0;
  for (int i = 2; i < step.size(); i += 3) largest = std::max(largest, std::abs(step(i)));
  return largest;
}

// The chord step of SolverOptions::reuse_factorization: one Newton step from the guess with
// the factorisation still held by data.lu (from a nearby converged position; evaluating Phi_q
// does not touch it). Expects Phi evaluated at the guess (residual `before`). Leaves Phi and
// Phi_q evaluated at the new q and @returns true if the step reduced the residual; otherwise
// data.q is back at the guess, nothing is evaluated there, and @returns false.
bool chord_step(const Model& model, Data& data, double t, const SolverOptions& options, double before) {
  data.step = data.phi;
  data.lu->solve(data.step.data());
  if (!data.step.allFinite() || largest_angle(data.step) > options.max_angle_step) return false;
  data.q -= data.step;
  evaluate_constraints(model, data, t);
  if (residual(data) < before) return true;
  data.q = data.work;
  return false;
}

}  // namespace

PositionReport solve_position(const Model& model, Data& data, double t, const SolverOptions& options) {
  check_data(model, data);
  PositionReport report;
  if (model.equations() < model.coordinates()) {
    report.message = "under-driven: " + std::to_string(model.coordinates()) + " coordinates but only " +
                     std::to_string(model.equations()) + " equations (joints, elements and drivers)";
    return report;
  }
  data.work = data.q;  // the guess, restored on failure
  int iteration = 0;
  bool evaluated = false;
  if (options.reuse_factorization && data.lu && data.factored && !data.singular) {
    evaluate_constraints(model, data, t);
    const double before = residual(data);
    evaluated = true;
    if (std::isfinite(before) && before > options.tolerance && options.max_iterations > 0) {
      evaluated = chord_step(model, data, t, options, before);
      if (evaluated) iteration = 1;
    }
  }
  for (; iteration <= options.max_iterations; ++iteration) {
    if (!evaluated) evaluate_constraints(model, data, t);
    evaluated = false;
    report.residual = residual(data);
    report.iterations = iteration;
    if (!std::isfinite(report.residual)) break;
    const bool done = report.residual <= options.tolerance;
    const bool ok = factorize(model, data);
    if (done) {
      report.converged = true;
      report.singular = !ok;
      return report;
    }
    if (!ok) {
      report.singular = true;
      break;
    }
    data.step = data.phi;
    solve_in_place(data, data.step);
    const double largest = largest_angle(data.step);
    if (largest > options.max_angle_step) data.step *= options.max_angle_step / largest;
    if (!data.step.allFinite()) break;
    data.q -= data.step;
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
  check_data(model, data);
  if (!data.factored && !factorize(model, data)) return false;
  if (data.singular) return false;
  data.qd = -data.phi_t;
  solve_in_place(data, data.qd);
  // gamma depends on qd; Phi_q and its factorisation stay (q did not change).
  evaluate_rows(model, data, data.t, Refresh::after_velocity);
  return true;
}

bool solve_velocity_along(const Model& model, Data& data, const Eigen::VectorXd& dq, double input_speed) {
  check_data(model, data);
  if (!data.factored && !factorize(model, data)) return false;
  if (data.singular) return false;
  data.qd = input_speed * dq;
  evaluate_rows(model, data, data.t, Refresh::after_velocity);
  return true;
}

bool solve_acceleration(const Model& model, Data& data) {
  check_data(model, data);
  if (!data.factored && !factorize(model, data)) return false;
  if (data.singular) return false;
  data.qdd = data.gamma;
  solve_in_place(data, data.qdd);
  return true;
}

bool input_sensitivity(const Model& model, Data& data, int driver, Eigen::VectorXd& dq) {
  check_data(model, data);
  if (!data.factored && !factorize(model, data)) return false;
  if (data.singular) return false;
  // d Phi / d f0 is -1 on the driver's row, so Phi_q dq/df0 = e_row.
  dq.setZero(model.equations());
  const Driver& d = model.drivers().at(static_cast<std::size_t>(driver));
  dq(model.constraints()[static_cast<std::size_t>(d.constraint)].first_row) = 1.0;
  solve_in_place(data, dq);
  return true;
}

Eigen::VectorXd input_sensitivity(const Model& model, Data& data, int driver) {
  Eigen::VectorXd dq;
  if (!input_sensitivity(model, data, driver, dq)) return {};
  return dq;
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

namespace {

// Sum of the link-angle changes between two configurations, each wrapped to (-pi, pi].
double angle_distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  double d = 0.0;
  for (int i = 2; i < a.size(); i += 3) d += std::abs(std::remainder(a(i) - b(i), 2.0 * std::numbers::pi));
  return d;
}

}  // namespace

PositionReport assemble(const Model& model, Data& data, double t, const SolverOptions& options) {
  const Eigen::VectorXd drawn = data.q;
  const PositionReport first = solve_position(model, data, t, options);
  if ((first.converged && !first.singular) || model.equations() < model.coordinates()) return first;
  // Deterministic restarts: each link's angle moved by +-amplitude, the signs taken from the bits
  // of the restart's number so that neighbouring links turn differently.
  static constexpr double kAmplitudes[] = {0.1, 0.3, 0.6, 1.0};
  std::optional<PositionReport> best;
  Eigen::VectorXd best_q;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const double amplitude : kAmplitudes) {
    for (unsigned pattern = 1; pattern <= 12; ++pattern) {
      data.q = drawn;
      for (int i = 2, link = 0; i < data.q.size(); i += 3, ++link) {
        const unsigned bit = (pattern * 2654435761u >> (link % 16)) & 1u;
        data.q(i) += bit ? amplitude : -amplitude * 0.7;
      }
      const PositionReport r = solve_position(model, data, t, options);
      if (!r.converged || r.singular) continue;
      const double distance = angle_distance(data.q, drawn);
      if (distance < best_distance) {
        best_distance = distance;
        best = r;
        best_q = data.q;
      }
    }
  }
  if (!best) {
    data.q = drawn;
    solve_position(model, data, t, options);  // leaves data as the drawing's own attempt left it
    return first;
  }
  data.q = best_q;
  return solve_position(model, data, t, options);  // factorised at the kept solution
}

}  // namespace gearkit::kin
