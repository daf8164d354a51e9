#include <gearkit/kin/sweep.hpp>

#include <cmath>
#include <stdexcept>

namespace gearkit::kin {

namespace {

// Largest change of an angle coordinate between two coordinate vectors.
double largest_angle_change(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  double m = 0.0;
  for (int i = 2; i < a.size(); i += 3) m = std::max(m, std::abs(a(i) - b(i)));
  return m;
}

// A converged, regular configuration on the sweep's branch, with its input sensitivity.
struct Anchor {
  double input = 0.0;
  Eigen::VectorXd q, dq, qd, qdd;
  int determinant_sign = 0;
};

// Tries to move from `from` to `target`: predicts with the sensitivity (and its change since
// `previous` when given), solves, and checks that the branch is kept.
bool advance(const Model& model, Data& data, int driver, const Anchor& from, const Anchor* previous, double target,
             const SolverOptions& options, Anchor& to, int& iterations) {
  const double h = target - from.input;
  data.q = from.q + from.dq * h;
  if (previous && previous->input != from.input && previous->dq.size() == from.dq.size()) {
    const Eigen::VectorXd curvature = (from.dq - previous->dq) / (from.input - previous->input);
    data.q += 0.5 * curvature * h * h;
  }
  const Eigen::VectorXd predicted = data.q;
  data.inputs(driver) = target;
  const PositionReport report = solve_position(model, data, data.t, options);
  iterations = report.iterations;
  if (!report.converged || report.singular) return false;
  // Too close to a singular configuration to know which branch continues (a toggle, or a
  // bifurcation such as a flattened parallelogram): treat as the dead point.
  if (data.rcond < 1e-10) return false;
  if (from.determinant_sign != 0 && data.determinant_sign != from.determinant_sign) return false;
  if (largest_angle_change(data.q, predicted) > 0.1) return false;
  to.input = target;
  to.q = data.q;
  to.dq = input_sensitivity(model, data, driver);
  to.determinant_sign = data.determinant_sign;
  if (to.dq.size() != data.q.size() || !to.dq.allFinite()) return false;
  // Velocities and accelerations with the factorisation at hand (no second solve later).
  if (solve_velocity(model, data) && solve_acceleration(model, data)) {
    to.qd = data.qd;
    to.qdd = data.qdd;
  }
  return true;
}

// Input where d(output)/d(input) vanishes between a and b (derivatives da, db of opposite
// signs), by the Illinois variant of regula falsi, re-solving positions from the nearer anchor.
OutputExtreme locate_extreme(const Model& model, Data& data, const SweepOptions& options, int index, Anchor a,
                             double da, Anchor b, double db) {
  const Output& out = options.outputs[static_cast<std::size_t>(index)];
  OutputExtreme e;
  e.output = index;
  // Rising before the root along increasing input is a maximum.
  e.maximum = (da > 0.0) == (b.input > a.input);
  int side = 0;
  Anchor best = std::abs(da) < std::abs(db) ? a : b;
  for (int it = 0; it < 100 && std::abs(b.input - a.input) > 1e-13 * std::max(1.0, std::abs(a.input)); ++it) {
    double x = (a.input * db - b.input * da) / (db - da);
    if (!(x > std::min(a.input, b.input) && x < std::max(a.input, b.input))) x = 0.5 * (a.input + b.input);
    Anchor mid;
    int iterations = 0;
    if (!advance(model, data, options.driver, a, nullptr, x, options.solver, mid, iterations)) break;
    data.q = mid.q;
    const double dm = output_derivative(model, data, out, mid.dq);
    best = mid;
    if (dm == 0.0) break;
    if ((dm > 0.0) == (da > 0.0)) {
      a = mid;
      da = dm;
      if (side == -1) db *= 0.5;
      side = -1;
    } else {
      b = mid;
      db = dm;
      if (side == 1) da *= 0.5;
      side = 1;
    }
  }
  data.q = best.q;
  data.inputs(options.driver) = best.input;
  solve_position(model, data, data.t, options.solver);
  e.input = best.input;
  e.q = data.q;
  e.dq = input_sensitivity(model, data, options.driver);
  e.value = evaluate_output(model, data, out).value;
  return e;
}

}  // namespace

PositionReport solve_at(const Model& model, Data& data, int driver, double value, const SolverOptions& options) {
  if (driver < 0 || driver >= static_cast<int>(model.drivers().size()))
    throw std::invalid_argument("driver index " + std::to_string(driver) + " out of range");
  data.inputs(driver) = value;
  PositionReport report = solve_position(model, data, data.t, options);
  if (report.converged && !report.singular) {
    solve_velocity(model, data);
    solve_acceleration(model, data);
  }
  return report;
}

SweepResult sweep(const Model& model, Data& data, const SweepOptions& options) {
  if (options.driver < 0 || options.driver >= static_cast<int>(model.drivers().size()))
    throw std::invalid_argument("sweep: driver index " + std::to_string(options.driver) + " out of range");
  if (!(options.step > 0.0)) throw std::invalid_argument("sweep: the step must be positive");
  SweepResult result;
  const double direction = options.end >= options.start ? 1.0 : -1.0;
  const double step = options.step * direction;
  const long count = static_cast<long>(std::floor(std::abs(options.end - options.start) / options.step + 1e-9)) + 1;

  PositionReport first = solve_at(model, data, options.driver, options.start, options.solver);
  if (!first.converged || first.singular) {
    result.message = first.message.empty() ? "singular Jacobian at the first input" : first.message;
    return result;
  }
  result.assembled = true;
  Anchor current{options.start, data.q, input_sensitivity(model, data, options.driver), data.qd, data.qdd,
                 data.determinant_sign};
  Anchor previous = current;
  auto record = [&](const Anchor& a, int iterations) {
    if (options.velocities) result.samples.push_back({a.input, a.q, a.qd, a.qdd, iterations});
    else result.samples.push_back({a.input, a.q, {}, {}, iterations});
  };
  record(current, first.iterations);

  // Output derivatives at the last sample, for the extremes.
  std::vector<double> last_derivative;
  auto derivatives_at = [&](const Anchor& a) {
    std::vector<double> d;
    data.q = a.q;
    for (const Output& o : options.outputs) d.push_back(output_derivative(model, data, o, a.dq));
    return d;
  };
  last_derivative = derivatives_at(current);
  std::vector<Anchor> last_significant(options.outputs.size(), current);

  for (long k = 1; k < count; ++k) {
    const double target = (k == count - 1 && std::abs(options.start + step * static_cast<double>(k) - options.end) < 1e-9 * options.step)
                              ? options.end
                              : options.start + step * static_cast<double>(k);
    // Continuation with step halving: reach `target` from `current`.
    double h = target - current.input;
    int iterations = 0;
    bool dead = false;
    while (current.input != target) {
      const double remaining = target - current.input;
      if (std::abs(h) > std::abs(remaining)) h = remaining;
      Anchor next;
      if (advance(model, data, options.driver, current, &previous, current.input + h, options.solver, next, iterations)) {
        // Extremes of outputs between current and next.
        const std::vector<double> d = derivatives_at(next);
        // A sign change of d(output)/d(input) since the last sample where it was clearly
        // non-zero brackets an extreme; derivatives below kFlat (1 nm or 1 nrad per unit
        // input) are round-off (a constant output, or an extreme falling on a sample).
        constexpr double kFlat = 1e-9;
        for (std::size_t o = 0; o < d.size(); ++o) {
          if (std::abs(d[o]) <= kFlat) continue;
          if (std::abs(last_derivative[o]) > kFlat && (last_derivative[o] > 0.0) != (d[o] > 0.0))
            result.extremes.push_back(locate_extreme(model, data, options, static_cast<int>(o), last_significant[o],
                                                     last_derivative[o], next, d[o]));
          last_derivative[o] = d[o];
          last_significant[o] = next;
        }
        previous = current;
        current = next;
        h *= 2.0;
      } else {
        h *= 0.5;
        if (std::abs(h) < options.min_step) {
          dead = true;
          break;
        }
      }
    }
    if (dead) {
      DeadPoint dp;
      dp.input = current.input;
      dp.q = current.q;
      dp.description = "dead point: the driver cannot move the mechanism beyond this input (singular dependent Jacobian; "
                       "toggle or limit position)";
      result.dead_points.push_back(dp);
      result.message = "sweep stopped at a dead point";
      if (result.samples.back().input != current.input) record(current, iterations);
      break;
    }
    record(current, iterations);
  }
  result.complete = result.dead_points.empty();
  return result;
}

}  // namespace gearkit::kin
