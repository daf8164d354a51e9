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
  // The samples of `result` are overwritten in place (their vectors keep their storage), so a
  // repeated sweep does not allocate per position.
  std::size_t used = 0;
  sweep(model, data, options, result, [&](const SweepSample& s) {
    if (used == result.samples.size()) result.samples.emplace_back();
    SweepSample& kept = result.samples[used++];
    kept.input = s.input;
    kept.q = s.q;
    kept.qd = s.qd;
    kept.qdd = s.qdd;
    kept.dq = s.dq;
    kept.iterations = s.iterations;
  });
  result.samples.resize(used);
}

namespace {

// The state of one sweep between samples: the last three anchors on the branch (for the
// predictor), the chord-step bookkeeping and the output derivatives that bracket extremes.
class Continuation {
 public:
  Continuation(const Model& model, Data& data, const SweepOptions& options, SweepResult& result, const Anchor& first)
      : model_(model), data_(data), options_(options), result_(result), current_(first), previous_(first),
        before_(first), next_(first), chord_(options.solver), last_derivative_(options.outputs.size(), 0.0),
        derivative_(last_derivative_), last_significant_(options.outputs.size(), first) {
    // Continuation steps take their first Newton step with the factorisation of the position
    // they start from (SolverOptions::reuse_factorization), valid while nothing else has
    // factorised since (a rejected step or the location of an extreme).
    chord_.reuse_factorization = true;
    derivatives_at(current_, last_derivative_);
  }

  const Anchor& current() const { return current_; }

  /// Continuation with step halving from the current anchor to `target`. @returns false at a
  /// dead point (the step fell below options.min_step); `iterations` of the last solve.
  bool reach(double target, int& iterations) {
    double h = target - current_.input;
    while (current_.input != target) {
      const double remaining = target - current_.input;
      if (std::abs(h) > std::abs(remaining)) h = remaining;
      if (advance(model_, data_, options_.driver, current_, &previous_, &before_, current_.input + h,
                  factorised_at_current_ ? chord_ : options_.solver, options_.velocities, next_, iterations)) {
        factorised_at_current_ = true;
        note_extremes();
        std::swap(before_, previous_);
        std::swap(previous_, current_);
        std::swap(current_, next_);
        h *= 2.0;
      } else {
        factorised_at_current_ = false;
        h *= 0.5;
        if (std::abs(h) < options_.min_step) return false;
      }
    }
    return true;
  }

 private:
  void derivatives_at(const Anchor& a, std::vector<double>& d) {
    data_.q = a.q;
    for (std::size_t o = 0; o < options_.outputs.size(); ++o)
      d[o] = output_derivative(model_, data_, options_.outputs[o], a.dq);
  }

  // Extremes of outputs between current and next: a sign change of d(output)/d(input) since the
  // last sample where it was clearly non-zero brackets an extreme; derivatives below kFlat (1 nm
  // or 1 nrad per unit input) are round-off (a constant output, or an extreme on a sample).
  void note_extremes() {
    constexpr double kFlat = 1e-9;
    derivatives_at(next_, derivative_);
    for (std::size_t o = 0; o < derivative_.size(); ++o) {
      const double d = derivative_[o];
      if (std::abs(d) <= kFlat) continue;
      if (std::abs(last_derivative_[o]) > kFlat && (last_derivative_[o] > 0.0) != (d > 0.0)) {
        result_.extremes.push_back(locate_extreme(model_, data_, options_, static_cast<int>(o), last_significant_[o],
                                                  last_derivative_[o], next_, d));
        factorised_at_current_ = false;
      }
      last_derivative_[o] = d;
      last_significant_[o] = next_;
    }
  }

  const Model& model_;
  Data& data_;
  const SweepOptions& options_;
  SweepResult& result_;
  Anchor current_, previous_, before_, next_;
  SolverOptions chord_;
  bool factorised_at_current_ = true;
  std::vector<double> last_derivative_, derivative_;  // output derivatives, for the extremes
  std::vector<Anchor> last_significant_;
};

// Hands an anchor to the visitor through one reused sample (no allocation per position).
void visit_anchor(const Anchor& a, int iterations, bool velocities, SweepSample& scratch, const SampleVisitor& visit) {
  scratch.input = a.input;
  scratch.q = a.q;
  scratch.dq = a.dq;
  scratch.iterations = iterations;
  if (velocities) {
    scratch.qd = a.qd;
    scratch.qdd = a.qdd;
  } else {
    scratch.qd.resize(0);
    scratch.qdd.resize(0);
  }
  visit(scratch);
}

}  // namespace

void sweep(const Model& model, Data& data, const SweepOptions& options, SweepResult& result, const SampleVisitor& visit) {
  check_data(model, data);
  if (options.driver < 0 || options.driver >= static_cast<int>(model.drivers().size()))
    throw std::invalid_argument("sweep: driver index " + std::to_string(options.driver) + " out of range");
  if (!(options.step > 0.0)) throw std::invalid_argument("sweep: the step must be positive");
  result.dead_points.clear();
  result.extremes.clear();
  result.assembled = false;
  result.complete = false;
  result.message.clear();
  const double direction = options.end >= options.start ? 1.0 : -1.0;
  const double step = options.step * direction;
  const long count = sweep_sample_count(options);

  const PositionReport first = solve_at(model, data, options.driver, options.start, options.solver);
  if (!first.converged || first.singular) {
    result.message = first.message.empty() ? "singular Jacobian at the first input" : first.message;
    return;
  }
  result.assembled = true;
  SweepSample scratch;
  Continuation run(model, data, options,
                   result, Anchor{options.start, data.q, input_sensitivity(model, data, options.driver), data.qd, data.qdd,
                                  data.determinant_sign});
  visit_anchor(run.current(), first.iterations, options.velocities, scratch, visit);
  double last_visited = options.start;
  for (long k = 1; k < count; ++k) {
    const double planned = options.start + step * static_cast<double>(k);
    const double target = k == count - 1 && std::abs(planned - options.end) < 1e-9 * options.step ? options.end : planned;
    int iterations = 0;
    if (!run.reach(target, iterations)) {
      DeadPoint dp;
      dp.input = run.current().input;
      dp.q = run.current().q;
      dp.description = "dead point: the driver cannot move the mechanism beyond this input (singular dependent "
                       "Jacobian; toggle or limit position)";
      result.dead_points.push_back(dp);
      result.message = "sweep stopped at a dead point";
      if (last_visited != run.current().input) visit_anchor(run.current(), iterations, options.velocities, scratch, visit);
      break;
    }
    visit_anchor(run.current(), iterations, options.velocities, scratch, visit);
    last_visited = target;
  }
  result.complete = result.dead_points.empty();
}

long sweep_sample_count(const SweepOptions& options) {
  return static_cast<long>(std::floor(std::abs(options.end - options.start) / options.step + 1e-9)) + 1;
}

}  // namespace gearkit::kin
