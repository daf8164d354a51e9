#include <gearkit/kin/sweep.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
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

// Tries to move from `from` to `target`: predicts, solves, and checks that the branch is kept.
// The prediction integrates the quadratic through the last three sensitivities dq/d(input)
// (`from`, `previous`, `before`; fewer when absent): its error is O(h^4), so at fine steps the
// predicted pose usually meets the tolerance without a Newton step. Writes into `to`, whose
// vectors are reused from one position to the next (a sweep does not allocate per position).
bool advance(const Model& model, Data& data, int driver, const Anchor& from, const Anchor* previous,
             const Anchor* before, double target, const SolverOptions& options, bool velocities, Anchor& to,
             int& iterations) {
  const double h = target - from.input;
  to.q = from.q + from.dq * h;  // the prediction, kept until the branch check
  const auto usable = [&](const Anchor* a, const Anchor& later) {
    return a && a->input != later.input && a->dq.size() == from.dq.size();
  };
  if (usable(previous, from)) {
    // Newton form of the interpolant: dq(s) = d0 + d01 (s - s0) + d012 (s - s0)(s - s1).
    const double s0 = from.input, s1 = previous->input;
    to.q += (0.5 * h * h / (s0 - s1)) * (from.dq - previous->dq);
    if (usable(before, *previous) && before->input != s0) {
      const double s2 = before->input;
      const double c = (h * h * h / 3.0 + 0.5 * (s0 - s1) * h * h) / (s0 - s2);
      to.q += (c / (s0 - s1)) * (from.dq - previous->dq) - (c / (s1 - s2)) * (previous->dq - before->dq);
    }
  }
  data.q = to.q;
  data.inputs(driver) = target;
  const PositionReport report = solve_position(model, data, data.t, options);
  iterations = report.iterations;
  if (!report.converged || report.singular) return false;
  // Too close to a singular configuration to know which branch continues (a toggle, or a
  // bifurcation such as a flattened parallelogram): treat as the dead point.
  if (data.rcond < 1e-10) return false;
  if (from.determinant_sign != 0 && data.determinant_sign != from.determinant_sign) return false;
  if (largest_angle_change(data.q, to.q) > 0.1) return false;
  to.input = target;
  to.q = data.q;
  to.determinant_sign = data.determinant_sign;
  if (!input_sensitivity(model, data, driver, to.dq) || !to.dq.allFinite()) return false;
  if (!velocities) return true;
  // Velocities and accelerations with the factorisation at hand. Phi_q qd = -Phi_t; when Phi_t
  // vanishes off the swept driver's row (no other driver moves: joints and elements do not
  // depend on time) the right-hand side is a multiple of that row's unit vector, so qd is the
  // same multiple of dq = Phi_q^-1 e_row and needs no solve of its own.
  const int row = model.constraints()[static_cast<std::size_t>(model.drivers()[static_cast<std::size_t>(driver)].constraint)].first_row;
  const double input_speed = -data.phi_t(row);
  const bool only_this_driver =
      data.phi_t.head(row).isZero(0.0) && data.phi_t.tail(data.phi_t.size() - row - 1).isZero(0.0);
  const bool solved = only_this_driver ? solve_velocity_along(model, data, to.dq, input_speed) : solve_velocity(model, data);
  if (solved && solve_acceleration(model, data)) {
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
    if (!advance(model, data, options.driver, a, nullptr, nullptr, x, options.solver, false, mid, iterations)) break;
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
  check_data(model, data);
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
  SweepResult result;
  sweep(model, data, options, result);
  return result;
}

void sweep(const Model& model, Data& data, const SweepOptions& options, SweepResult& result) {
  check_data(model, data);
  if (options.driver < 0 || options.driver >= static_cast<int>(model.drivers().size()))
    throw std::invalid_argument("sweep: driver index " + std::to_string(options.driver) + " out of range");
  if (!(options.step > 0.0)) throw std::invalid_argument("sweep: the step must be positive");
  // The samples of `result` are overwritten in place (their vectors keep their storage), so a
  // repeated sweep does not allocate per position.
  std::size_t used = 0;
  result.dead_points.clear();
  result.extremes.clear();
  result.assembled = false;
  result.complete = false;
  result.message.clear();
  const double direction = options.end >= options.start ? 1.0 : -1.0;
  const double step = options.step * direction;
  const long count = static_cast<long>(std::floor(std::abs(options.end - options.start) / options.step + 1e-9)) + 1;

  PositionReport first = solve_at(model, data, options.driver, options.start, options.solver);
  if (!first.converged || first.singular) {
    result.message = first.message.empty() ? "singular Jacobian at the first input" : first.message;
    result.samples.clear();
    return;
  }
  result.assembled = true;
  Anchor current{options.start, data.q, input_sensitivity(model, data, options.driver), data.qd, data.qdd,
                 data.determinant_sign};
  Anchor before = current, previous = current, next = current;
  result.samples.reserve(static_cast<std::size_t>(std::min<long>(count, 1L << 20)));
  auto record = [&](const Anchor& a, int iterations) {
    if (used == result.samples.size()) result.samples.emplace_back();
    SweepSample& s = result.samples[used++];
    s.input = a.input;
    s.q = a.q;
    s.iterations = iterations;
    if (options.velocities) {
      s.qd = a.qd;
      s.qdd = a.qdd;
    } else {
      s.qd.resize(0);
      s.qdd.resize(0);
    }
  };
  record(current, first.iterations);

  // Continuation steps take their first Newton step with the factorisation of the position
  // they start from (SolverOptions::reuse_factorization), valid while nothing else has
  // factorised since (a rejected step or the location of an extreme).
  SolverOptions chord = options.solver;
  chord.reuse_factorization = true;
  bool factorised_at_current = true;

  // Output derivatives at the last sample, for the extremes.
  std::vector<double> last_derivative(options.outputs.size(), 0.0), derivative = last_derivative;
  auto derivatives_at = [&](const Anchor& a, std::vector<double>& d) {
    data.q = a.q;
    for (std::size_t o = 0; o < options.outputs.size(); ++o) d[o] = output_derivative(model, data, options.outputs[o], a.dq);
  };
  derivatives_at(current, last_derivative);
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
      if (advance(model, data, options.driver, current, &previous, &before, current.input + h,
                  factorised_at_current ? chord : options.solver, options.velocities, next, iterations)) {
        factorised_at_current = true;
        // Extremes of outputs between current and next: a sign change of d(output)/d(input)
        // since the last sample where it was clearly non-zero brackets an extreme;
        // derivatives below kFlat (1 nm or 1 nrad per unit input) are round-off (a constant
        // output, or an extreme falling on a sample).
        constexpr double kFlat = 1e-9;
        derivatives_at(next, derivative);
        for (std::size_t o = 0; o < derivative.size(); ++o) {
          const double d = derivative[o];
          if (std::abs(d) <= kFlat) continue;
          if (std::abs(last_derivative[o]) > kFlat && (last_derivative[o] > 0.0) != (d > 0.0)) {
            result.extremes.push_back(locate_extreme(model, data, options, static_cast<int>(o), last_significant[o],
                                                     last_derivative[o], next, d));
            factorised_at_current = false;
          }
          last_derivative[o] = d;
          last_significant[o] = next;
        }
        std::swap(before, previous);
        std::swap(previous, current);
        std::swap(current, next);
        h *= 2.0;
      } else {
        factorised_at_current = false;
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
      if (result.samples[used - 1].input != current.input) record(current, iterations);
      break;
    }
    record(current, iterations);
  }
  result.samples.resize(used);
  result.complete = result.dead_points.empty();
}

}  // namespace gearkit::kin
