#include <gearkit/kin/sweep.hpp>

#include "tolerances.hpp"

#include <algorithm>
#include <array>
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
  double rcond = 1.0;            // of Phi_q there (Data::rcond)
  double rcond_scale = 0.0;      // the largest rcond on the branch so far
  bool on_change_point = false;  // interpolated on one (interpolate())
  Eigen::VectorXd dq_predicted;  // scratch of advance(): the tangent the branch should have
};

// The continuation's tolerances, each with its trade-off: tolerances.hpp.
using tolerance::kBranchSingularFraction;
using tolerance::kConditioningDrop;
using tolerance::kMaxAngleFromPrediction;
using tolerance::kRegularRcond;
using tolerance::kStartConditioningDrop;
using tolerance::kTangentJump;
using tolerance::kTangentJumpWithoutHistory;

// What advance() did with a step: took it, or the one reason it refused it. Every refusal is
// answered the same way (the step is halved; at min_step cross() decides what lies there); the
// reasons are named so that a reader, a debugger or a test can tell the seven tests apart.
enum class Step {
  taken,
  not_converged,        // Newton did not converge, or met a singular Jacobian
  near_singular,        // rcond below kBranchSingularFraction of the branch's best (or kRegularRcond)
  conditioning_drop,    // rcond fell by more than kConditioningDrop over the step: landed on a point
  determinant_flip,     // det(Phi_q) changed sign: a singular position lies inside the step
  far_from_prediction,  // an angle moved more than kMaxAngleFromPrediction from the prediction
  no_tangent,           // dq/d(input) could not be solved or is not finite
  tangent_jump,         // dq/d(input) departs from its prediction: another branch
};

// Tries to move from `from` to `target`: predicts, solves, and checks that the branch is kept.
// The prediction integrates the quadratic through the last three sensitivities dq/d(input)
// (`from`, `previous`, `before`; fewer when absent): its error is O(h^4), so at fine steps the
// predicted pose usually meets the tolerance without a Newton step. Writes into `to`, whose
// vectors are reused from one position to the next (a sweep does not allocate per position).
[[nodiscard]] Step advance(const Model& model, Data& data, int driver, const Anchor& from, const Anchor* previous,
                           const Anchor* before, double target, const SolverOptions& options, bool velocities,
                           Anchor& to, int& iterations) {
  const double h = target - from.input;
  to.q = from.q + from.dq * h;  // the prediction, kept until the branch check
  to.dq_predicted = from.dq;
  const auto usable = [&](const Anchor* a, const Anchor& later) {
    return a && a->input != later.input && a->dq.size() == from.dq.size();
  };
  const bool history = usable(previous, from);
  if (history) {
    // Newton form of the interpolant: dq(s) = d0 + d01 (s - s0) + d012 (s - s0)(s - s1).
    const double s0 = from.input, s1 = previous->input;
    to.q += (0.5 * h * h / (s0 - s1)) * (from.dq - previous->dq);
    to.dq_predicted += (h / (s0 - s1)) * (from.dq - previous->dq);
    if (usable(before, *previous) && before->input != s0) {
      const double s2 = before->input;
      const double c = (h * h * h / 3.0 + 0.5 * (s0 - s1) * h * h) / (s0 - s2);
      to.q += (c / (s0 - s1)) * (from.dq - previous->dq) - (c / (s1 - s2)) * (previous->dq - before->dq);
      const double e = h * (h + s0 - s1) / (s0 - s2);
      to.dq_predicted += (e / (s0 - s1)) * (from.dq - previous->dq) - (e / (s1 - s2)) * (previous->dq - before->dq);
    }
  }
  data.q = to.q;
  data.inputs(driver) = target;
  const PositionReport report = solve_position(model, data, data.t, options);
  iterations = report.iterations;
  if (!report.converged || report.singular) return Step::not_converged;
  // Too close to a singular configuration to know which branch continues (a toggle, or a
  // bifurcation such as a flattened parallelogram): treat as the dead point.
  if (data.rcond < std::max(kRegularRcond, kBranchSingularFraction * from.rcond_scale)) return Step::near_singular;
  // A sudden fall of the conditioning is a landing on or next to a singular configuration (a
  // change point the step ends on), where dq is any solution of a nearly singular system and
  // cannot tell the branch: approached by halving instead, so that cross() takes over there.
  if (data.rcond < kConditioningDrop * from.rcond) return Step::conditioning_drop;
  if (from.determinant_sign != 0 && data.determinant_sign != from.determinant_sign) return Step::determinant_flip;
  if (largest_angle_change(data.q, to.q) > kMaxAngleFromPrediction) return Step::far_from_prediction;
  to.input = target;
  to.q = data.q;
  to.determinant_sign = data.determinant_sign;
  to.rcond = data.rcond;
  to.rcond_scale = std::max(from.rcond_scale, data.rcond);
  if (!input_sensitivity(model, data, driver, to.dq) || !to.dq.allFinite()) return Step::no_tangent;
  const double jump = (to.dq - to.dq_predicted).lpNorm<Eigen::Infinity>();
  const double scale = std::max(to.dq.lpNorm<Eigen::Infinity>(), to.dq_predicted.lpNorm<Eigen::Infinity>());
  if (jump > (history ? kTangentJump : kTangentJumpWithoutHistory) * scale) return Step::tangent_jump;
  if (!velocities) return Step::taken;
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
  return Step::taken;
}

// The cubic Hermite curve through the anchors' q with their tangents dq, evaluated (or
// extrapolated) at `input`: q and its derivative. Error O(|b - a|^4) on a smooth branch.
void hermite(const Anchor& a, const Anchor& b, double input, Eigen::VectorXd& q, Eigen::VectorXd& dq) {
  const double h = b.input - a.input, t = (input - a.input) / h;
  const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t), h01 = t * t * (3 - 2 * t),
               h11 = t * t * (t - 1);
  q = h00 * a.q + (h10 * h) * a.dq + h01 * b.q + (h11 * h) * b.dq;
  const double d00 = 6 * t * (t - 1) / h, d10 = (1 - t) * (1 - 3 * t), d01 = -d00, d11 = t * (3 * t - 2);
  dq = d00 * a.q + d10 * a.dq + d01 * b.q + d11 * b.dq;
}

// A sample at `input` between two anchors of one branch: q and dq by the Hermite curve, the
// velocities and accelerations linearly (O(h^2): the samples this serves lie on a change point,
// where the Jacobian cannot give them).
void interpolate(const Anchor& a, const Anchor& b, double input, Anchor& to) {
  hermite(a, b, input, to.q, to.dq);
  to.input = input;
  to.determinant_sign = 0;
  to.on_change_point = true;
  const double t = (input - a.input) / (b.input - a.input);
  if (a.qd.size() == b.qd.size()) to.qd = (1 - t) * a.qd + t * b.qd;
  if (a.qdd.size() == b.qdd.size()) to.qdd = (1 - t) * a.qdd + t * b.qdd;
}

// Completes an anchor at the solved data.q: tangent, and velocities when the sweep has them.
bool settle_anchor(const Model& model, Data& data, const SweepOptions& options, double input, Anchor& to) {
  to.input = input;
  to.q = data.q;
  to.determinant_sign = data.determinant_sign;
  to.rcond = data.rcond;
  to.rcond_scale = std::max(to.rcond_scale, data.rcond);
  if (!input_sensitivity(model, data, options.driver, to.dq) || !to.dq.allFinite()) return false;
  if (options.velocities && solve_velocity(model, data) && solve_acceleration(model, data)) {
    to.qd = data.qd;
    to.qdd = data.qdd;
  }
  return true;
}

// Distances from a change point at which the branch is taken up again, tried in turn (see
// change_point_offset()).
std::array<double, 3> crossing_steps(const SweepOptions& options) {
  const double base = change_point_offset(options);
  return {base, 0.125 * base, std::min(0.25 * options.step, 4.0 * base)};
}

// Near a change point Newton's residual test (max |Phi| <= tolerance) leaves an error of about
// tolerance / sigma_min in q, sigma_min ~ the distance to the point: the anchors around one are
// solved a thousand times tighter, so that the extrapolations through them stay exact.
SolverOptions tight(const SolverOptions& options) {
  SolverOptions o = options;
  o.tolerance *= tolerance::kTightFactor;
  o.max_iterations = std::max(o.max_iterations, 50);
  return o;
}

// The sweep's start is singular (it lies on a change point, e.g. a parallelogram's flat
// position): the mechanism is assembled just past it in the sweep's direction from `guess`
// (nearest the drawing, kin::assemble), a second anchor a step further, and the start sample
// extrapolated back from them; kept only if the extrapolation closes the constraints (at a
// fold, a limit the sweep starts on, the branch is not smooth there and this fails).
bool start_beside_change_point(const Model& model, Data& data, const SweepOptions& options, const Eigen::VectorXd& guess,
                               Anchor& start_sample, Anchor& first) {
  first.rcond_scale = 0.0;
  const double direction = options.end >= options.start ? 1.0 : -1.0;
  for (const double delta : crossing_steps(options)) {
    if (!(delta > 100.0 * options.min_step)) continue;
    data.q = guess;
    data.inputs(options.driver) = options.start + 2.0 * direction * delta;
    const PositionReport r = assemble(model, data, data.t, tight(options.solver));
    if (!r.converged || r.singular || data.rcond < kRegularRcond) continue;
    Anchor far;
    far.rcond_scale = 0.0;
    int iterations = 0;
    if (!settle_anchor(model, data, options, data.inputs(options.driver), far) ||
        advance(model, data, options.driver, far, nullptr, nullptr, options.start + direction * delta,
                tight(options.solver), options.velocities, first, iterations) != Step::taken)
      continue;
    interpolate(far, first, options.start, start_sample);
    data.q = start_sample.q;
    data.inputs(options.driver) = options.start;
    evaluate_constraints(model, data, data.t);
    if (data.phi.lpNorm<Eigen::Infinity>() > 10.0 * options.solver.tolerance) continue;
    data.q = first.q;  // the continuation goes on from `first`, factorised there
    data.inputs(options.driver) = first.input;
    solve_position(model, data, data.t, options.solver);
    return true;
  }
  return false;
}

enum class Start { failed, regular, change_point };

// The first sample, assembled at options.start from data.q. Newton started on a change point
// may "converge" there to within sqrt(tolerance) of the singular configuration with a usable
// residual: a start whose Jacobian is much worse conditioned than the branch just past it
// (kConditioningDrop) is taken as one and left as start_beside_change_point() does.
Start start_sweep(const Model& model, Data& data, const SweepOptions& options, PositionReport& report,
                  Anchor& start_sample, Anchor& first) {
  const Eigen::VectorXd guess = data.q;
  report = solve_at(model, data, options.driver, options.start, options.solver);
  const bool converged = report.converged && !report.singular;
  if (converged) {
    first = Anchor{options.start, data.q, input_sensitivity(model, data, options.driver), data.qd, data.qdd,
                   data.determinant_sign, data.rcond, data.rcond, false, {}};
    // Compared with the conditioning a sweep step further on (from the guess: the branch does
    // not matter for its order of magnitude), which grows linearly with the distance from a
    // change point: a start within a hundredth of the step of one is taken as on it.
    const double direction = options.end >= options.start ? 1.0 : -1.0;
    data.q = guess;
    data.inputs(options.driver) = options.start + direction * options.step;
    const PositionReport probe = solve_position(model, data, data.t, options.solver);
    if (!probe.converged || probe.singular || first.rcond >= kStartConditioningDrop * data.rcond) {
      start_sample = first;
      data.q = first.q;  // factorised at the start again for the continuation
      solve_at(model, data, options.driver, options.start, options.solver);
      return Start::regular;
    }
  }
  Anchor beside_sample, beside_first;
  const bool beside = start_beside_change_point(model, data, options, guess, beside_sample, beside_first);
  if (converged && !beside) {
    start_sample = first;
    data.q = first.q;  // factorised at the start again for the continuation
    solve_at(model, data, options.driver, options.start, options.solver);
    return Start::regular;
  }
  if (!beside) return Start::failed;
  start_sample = std::move(beside_sample);
  first = std::move(beside_first);
  return Start::change_point;
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
    if (advance(model, data, options.driver, a, nullptr, nullptr, x, options.solver, false, mid, iterations) != Step::taken)
      break;
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
    kept.on_change_point = s.on_change_point;
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

  /// The sample reached by the last reach(): the continuation's anchor, or the configuration
  /// interpolated on a change point the sweep crossed (the anchor is then just past it).
  const Anchor& current() const { return current_; }

  /// The workspace holds the sample's factorisation and state (not after a change point or the
  /// location of an extreme), with the sample's velocities.
  bool factorised_at_sample() const {
    return !interpolated_ && factorised_at_current_ && data_.factored && !data_.singular && options_.velocities;
  }

  /// The sweep starts on a change point (start_beside_change_point()): tells whether another
  /// branch passes there and, with options.switch_branch, takes it.
  ChangePoint start_on_change_point(const Anchor& start_sample) {
    ChangePoint cp;
    cp.input = start_sample.input;
    cp.q = start_sample.q;
    Anchor other;
    int iterations = 0;
    cp.bifurcation = other_branch(start_sample.q, start_sample.input, current_, current_, other, iterations);
    if (cp.bifurcation && options_.switch_branch) {
      current_ = std::move(other);
      previous_ = before_ = current_;
      cp.switched = true;
    }
    factorised_at_current_ = false;
    return cp;
  }

  const Anchor& sample() const { return interpolated_ ? interpolated_sample_ : current_; }

  /// Continuation with step halving from the current anchor to `target`, crossing change points
  /// on the way (cross()). @returns false at a dead point (the step fell below options.min_step
  /// and nothing lies beyond); `iterations` of the last solve.
  bool reach(double target, int& iterations) {
    interpolated_ = false;
    double h = target - current_.input;
    while (current_.input != target) {
      const double remaining = target - current_.input;
      if (std::abs(h) > std::abs(remaining)) h = remaining;
      if (advance(model_, data_, options_.driver, current_, &previous_, &before_, current_.input + h,
                  factorised_at_current_ ? chord_ : options_.solver, options_.velocities, next_, iterations) ==
          Step::taken) {
        factorised_at_current_ = true;
        note_extremes();
        std::swap(before_, previous_);
        std::swap(previous_, current_);
        std::swap(current_, next_);
        h *= 2.0;
      } else {
        factorised_at_current_ = false;
        h *= 0.5;
        if (std::abs(h) >= options_.min_step) continue;
        if (!cross(target, iterations)) return false;
        if (interpolated_) return true;  // the target lay on the change point
        h = target - current_.input;
      }
    }
    return true;
  }

 private:
  // The step cannot shrink further: the current anchor is within ~2 min_step of a singular
  // configuration. At a fold (a toggle or limit position of the input) nothing lies beyond and
  // this fails: a dead point. At a bifurcation (a change point: a flattened parallelogram may
  // go on as a parallelogram or fold into an anti-parallelogram) the branch goes on: it is
  // left behind at two regular anchors, extrapolated past the point (Hermite, O(delta^4)),
  // re-solved there and kept if its tangent continues the one before (jump_past()); with
  // options.switch_branch the other branch through the point is taken instead.
  bool cross(double target, int& iterations) {
    const double s = current_.input, direction = options_.end >= options_.start ? 1.0 : -1.0;
      for (const double delta : crossing_steps(options_)) {
      if (!(delta > 100.0 * options_.min_step)) continue;
      Anchor r1, r2, c;
      if (advance(model_, data_, options_.driver, current_, nullptr, nullptr, s - direction * delta, tight(options_.solver),
                  options_.velocities, r1, iterations) != Step::taken ||
          advance(model_, data_, options_.driver, r1, nullptr, nullptr, s - 2.0 * direction * delta, tight(options_.solver),
                  options_.velocities, r2, iterations) != Step::taken ||
          !jump_past(r2, r1, s + direction * delta, c, iterations))
        continue;
      ChangePoint cp;
      cp.input = locate_singular_point(r1, c);
      Eigen::VectorXd unused;
      hermite(r1, c, cp.input, cp.q, unused);
      if (direction * (target - c.input) <= 0.0) {
        // The target lies on the change point (within delta): interpolated between the regular
        // anchors either side of it on the continuing branch.
        interpolate(r1, c, target, interpolated_sample_);
        interpolated_ = true;
      }
      Anchor other;
      cp.bifurcation = other_branch(cp.q, cp.input, r1, c, other, iterations);
      if (cp.bifurcation && options_.switch_branch) {
        c = std::move(other);
        cp.switched = true;
      }
      result_.change_points.push_back(std::move(cp));
      current_ = std::move(c);
      previous_ = current_;  // the predictor's history does not reach across the point
      before_ = current_;
      factorised_at_current_ = false;
      last_derivative_.assign(last_derivative_.size(), 0.0);  // extremes are not bracketed across it
      return true;
    }
    return false;
  }

  // The input of the singular configuration between the regular anchors a and b of one branch
  // (the continuation stops within ~1e-6 rad of it, where rcond reaches kBranchSingularFraction): by
  // bisection on the sign of det(Phi_q) along their Hermite curve when it changes, else by
  // golden-section search for the least singular value (a redundant model's QR has no sign).
  double locate_singular_point(const Anchor& a, const Anchor& b) {
    Eigen::VectorXd dq;  // unused: hermite() gives it with q
    const auto factorised_at = [&](double input) {
      hermite(a, b, input, data_.q, dq);
      data_.inputs(options_.driver) = input;
      evaluate_constraints(model_, data_, data_.t);
      factorize(model_, data_);
    };
    double lo = a.input, hi = b.input;
    if (a.determinant_sign * b.determinant_sign < 0) {
      for (int k = 0; k < 60 && lo != hi; ++k) {
        const double mid = 0.5 * (lo + hi);
        factorised_at(mid);
        if (data_.determinant_sign == 0) return mid;
        (data_.determinant_sign == a.determinant_sign ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
    }
    // Smallest singular value, to a constant factor, by one step of inverse iteration: V-shaped
    // in the input about the point (rcond's pivot ratio is too coarse to locate it).
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(data_.phi.size());
    const auto sigma_at = [&](double input) {
      factorised_at(input);
      return data_.singular ? 0.0 : 1.0 / solve_with_jacobian(data_, ones).norm();
    };
    constexpr double kGolden = 0.3819660112501051;  // (3 - sqrt 5) / 2
    for (int k = 0; k < 80 && std::abs(hi - lo) > 1e-15 * std::max(1.0, std::abs(lo)); ++k) {
      const double x1 = lo + kGolden * (hi - lo), x2 = hi - kGolden * (hi - lo);
      const double s1 = sigma_at(x1), s2 = sigma_at(x2);
      (s1 < s2 ? hi : lo) = s1 < s2 ? x2 : x1;
    }
    return 0.5 * (lo + hi);
  }

  // Solves at `input` past a singular point from the Hermite extrapolation of the branch through
  // the regular anchors a (farther) and b (nearer), and keeps the solution only if it continues
  // that branch: within a tenth of the step of the prediction and with the tangent it predicts.
  bool jump_past(const Anchor& a, const Anchor& b, double input, Anchor& to, int& iterations) {
    Eigen::VectorXd predicted_dq;
    hermite(a, b, input, to.q, predicted_dq);
    const Eigen::VectorXd predicted = to.q;
    data_.q = to.q;
    data_.inputs(options_.driver) = input;
    const PositionReport r = solve_position(model_, data_, data_.t, tight(options_.solver));
    iterations = r.iterations;
    if (!r.converged || r.singular || data_.rcond < kRegularRcond) return false;
    const double h = std::abs(input - b.input), scale = std::max(1.0, predicted_dq.lpNorm<Eigen::Infinity>());
    if ((data_.q - predicted).lpNorm<Eigen::Infinity>() > 0.1 * h * scale) return false;
    to.rcond_scale = b.rcond_scale;
    return settle(input, to) && (to.dq - predicted_dq).lpNorm<Eigen::Infinity>() <= kTangentJump * scale;
  }

  bool settle(double input, Anchor& to) { return settle_anchor(model_, data_, options_, input, to); }

  // The other branch through the change point, at the input of `c` (on the continuing branch):
  // it leaves the point along t + beta n, n the Jacobian's null direction there (by inverse
  // iteration at the nearly singular anchor r1), for some beta the first-order analysis cannot
  // tell; Newton is tried from a ladder of beta and the first solution that is a distinct
  // branch through the point (its chord from the point matches its own tangent) is `other`.
  // None is found where only one branch passes a singular position (a triple parallelogram).
  bool other_branch(const Eigen::VectorXd& point, double point_input, const Anchor& near, const Anchor& c, Anchor& other,
                    int& iterations) {
    data_.q = near.q;
    data_.inputs(options_.driver) = near.input;
    evaluate_constraints(model_, data_, data_.t);
    if (!factorize(model_, data_)) return false;
    // Inverse iteration on Phi_q^T Phi_q and Phi_q Phi_q^T (n coordinates, m >= n equations:
    // a redundant model's least-squares solves ignore its exactly redundant rows).
    Eigen::VectorXd n = Eigen::VectorXd::LinSpaced(near.q.size(), 1.0, 2.0);
    Eigen::VectorXd psi = Eigen::VectorXd::LinSpaced(data_.phi.size(), 1.0, 2.0);
    for (int k = 0; k < 3; ++k) {
      n = solve_with_jacobian(data_, solve_with_jacobian_transpose(data_, n)).normalized();
      psi = solve_with_jacobian_transpose(data_, solve_with_jacobian(data_, psi)).normalized();  // left null direction
    }
    const double delta = c.input - point_input, scale = std::max(1.0, c.dq.lpNorm<Eigen::Infinity>());
    const Eigen::VectorXd continuing = c.q, w = (scale * std::abs(delta)) * n;
    // Along q(beta) = c.q + beta w the residual's singular component psi . Phi is, to leading
    // order, a beta^2 + b beta (zero on the continuing branch, beta = 0): the other branch lies
    // near beta = -b / a. Then a ladder of beta in case the quadratic model is poor.
    const auto singular_residual = [&](double beta) {
      data_.q = continuing + beta * w;
      evaluate_constraints(model_, data_, data_.t);
      return psi.dot(data_.phi);
    };
    data_.inputs(options_.driver) = c.input;
    const double g0 = singular_residual(0.0), gp = singular_residual(1.0), gm = singular_residual(-1.0);
    const double a = 0.5 * (gp + gm) - g0, b = 0.5 * (gp - gm);
    std::vector<double> betas;
    if (a != 0.0 && std::isfinite(b / a)) betas.push_back(-b / a);
    for (const double magnitude : {0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0}) betas.insert(betas.end(), {magnitude, -magnitude});
    for (const double beta : betas) {
        data_.q = continuing + beta * w;
        data_.inputs(options_.driver) = c.input;
        const PositionReport r = solve_position(model_, data_, data_.t, tight(options_.solver));
        iterations = r.iterations;
        if (!r.converged || r.singular || data_.rcond < kRegularRcond) continue;
        if ((data_.q - continuing).lpNorm<Eigen::Infinity>() < 0.05 * std::abs(delta) * scale) continue;  // the same
        if (!settle(c.input, other)) continue;
        const Eigen::VectorXd chord = (other.q - point) / delta;
        if ((chord - other.dq).lpNorm<Eigen::Infinity>() <= 0.2 * std::max(1.0, other.dq.lpNorm<Eigen::Infinity>()))
          return true;
      }
    return false;
  }
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
  Anchor interpolated_sample_;
  bool interpolated_ = false;
};

// Hands an anchor to the visitor through one reused sample (no allocation per position);
// `data`: the sweep's workspace if factorised at the anchor.
void visit_anchor(const Anchor& a, int iterations, bool velocities, SweepSample& scratch, const SampleVisitor& visit,
                  Data* data = nullptr) {
  scratch.data = data;
  scratch.input = a.input;
  scratch.q = a.q;
  scratch.dq = a.dq;
  scratch.iterations = iterations;
  scratch.on_change_point = a.on_change_point;
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
  result.change_points.clear();
  result.extremes.clear();
  result.assembled = false;
  result.complete = false;
  result.message.clear();
  const double direction = options.end >= options.start ? 1.0 : -1.0;
  const double step = options.step * direction;
  const long count = sweep_sample_count(options);

  Anchor start_sample, first_anchor;
  PositionReport first;
  const Start start = start_sweep(model, data, options, first, start_sample, first_anchor);
  if (start == Start::failed) {
    result.message = first.message.empty() ? "singular Jacobian at the first input" : first.message;
    return;
  }
  result.assembled = true;
  SweepSample scratch;
  Continuation run(model, data, options, result, first_anchor);
  if (start == Start::change_point) result.change_points.push_back(run.start_on_change_point(start_sample));
  visit_anchor(start_sample, first.iterations, options.velocities, scratch, visit);
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
    visit_anchor(run.sample(), iterations, options.velocities, scratch, visit, run.factorised_at_sample() ? &data : nullptr);
    last_visited = target;
  }
  result.complete = result.dead_points.empty();
}

double change_point_offset(const SweepOptions& options) {
  return std::min(0.25 * options.step, std::max(1e-2 * options.step, 1e-5));
}

long sweep_sample_count(const SweepOptions& options) {
  return static_cast<long>(std::floor(std::abs(options.end - options.start) / options.step + 1e-9)) + 1;
}

}  // namespace gearkit::kin
