#include <gearkit/dyn/motion.hpp>

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

#include "number_text.hpp"

namespace gearkit::dyn {

namespace odeint = boost::numeric::odeint;

namespace {

using detail::num;

using State = std::array<double, 2>;  // theta, omega

// Bisection on a sign change of g over [a, b] (g(a) and g(b) of opposite sign or zero).
template <class G>
double bisect(G g, double a, double b) {
  double ga = g(a);
  for (int i = 0; i < 60 && b - a > 1e-15 * std::max(1.0, std::abs(b)); ++i) {
    const double m = 0.5 * (a + b);
    const double gm = g(m);
    if ((gm > 0) == (ga > 0) && gm != 0) {
      a = m;
      ga = gm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

// Steady when the last change of the cycle mean speed is small and so is what is left of the
// approach, estimated from the ratio q of the last two changes as a geometric series
// (change * q / (1 - q)). A change that does not decay (q near 1: a machine that keeps speeding
// up slowly) counts as a thousand more cycles of it, so a slow drift is never called steady.
bool settled(const std::vector<double>& mean, double tolerance) {
  if (mean.size() < 3) return false;
  const std::size_t k = mean.size() - 1;
  const double scale = tolerance * std::abs(mean[k]);
  const double last = mean[k] - mean[k - 1], before = mean[k - 1] - mean[k - 2];
  if (std::abs(last) > scale) return false;
  const double q = before != 0 ? last / before : 0.0;
  double remaining = std::abs(last);
  if (q >= 1 - 1e-3) remaining *= 1000;
  else if (q > 0) remaining *= q / (1 - q);
  return remaining <= scale;
}

}  // namespace

AccelerationLaw acceleration_law(ReducedSystem system) {
  if (!system.inertia) throw std::invalid_argument("equation of motion: the reduced inertia I(theta) is missing");
  return [s = std::move(system)](double, double theta, double omega) {
    const double inertia = s.inertia(theta);
    if (!std::isfinite(inertia) || !(inertia > 0))
      throw std::domain_error("reduced inertia must be > 0 kg*m^2, found " + num(inertia) + " at theta = " +
                              num(theta) + " rad");
    const double d_inertia = s.inertia_derivative ? s.inertia_derivative(theta) : 0.0;
    const double drive = s.drive_torque ? s.drive_torque(theta, omega) : 0.0;
    const double resist = s.resisting_torque ? s.resisting_torque(theta, omega) : 0.0;
    return (drive - resist - 0.5 * d_inertia * omega * omega) / inertia;
  };
}

namespace {

void check_motion_options(const MotionOptions& options, double theta0, double omega0) {
  if (!(options.t_end > 0) || !std::isfinite(options.t_end))
    throw std::invalid_argument("motion: end time must be > 0 s, found " + num(options.t_end));
  if (options.output_step < 0 || options.max_step < 0 || options.cycle < 0)
    throw std::invalid_argument("motion: output step, largest step and cycle must not be negative");
  if (!(options.abs_tolerance > 0) || !(options.rel_tolerance > 0) || !(options.steady_tolerance > 0))
    throw std::invalid_argument("motion: tolerances must be > 0");
  if (options.max_steps < 1) throw std::invalid_argument("motion: the step limit must be at least 1");
  if (!std::isfinite(theta0) || !std::isfinite(omega0))
    throw std::invalid_argument("motion: the initial state is not finite");
}

using Stepper = decltype(odeint::make_dense_output(1.0, 1.0, 1.0, odeint::runge_kutta_dopri5<State>()));

/// One integration in progress: the dense-output stepper, the cycle being measured and the
/// result so far. Each step() advances one adaptive step and handles what happened inside it,
/// in time order: a stall, speed extremes, cycle ends (steady state), output samples.
class Integration {
 public:
  Integration(const AccelerationLaw& law, const MotionOptions& options, double theta0, double omega0)
      : law_(law),
        options_(options),
        output_step_(options.output_step > 0 ? options.output_step : options.t_end / 2000),
        cycle_(options.cycle > 0 ? options.cycle : 2 * std::numbers::pi),
        stepper_(odeint::make_dense_output(options.abs_tolerance, options.rel_tolerance,
                                           options.max_step > 0 ? options.max_step : output_step_,
                                           odeint::runge_kutta_dopri5<State>())),
        next_cycle_theta_(theta0 + cycle_),
        cycle_max_(omega0),
        cycle_min_(omega0),
        started_(omega0 > 0) {
    const double max_step = options.max_step > 0 ? options.max_step : output_step_;
    stepper_.initialize(State{theta0, omega0}, 0.0, std::min(max_step, options.t_end) / 100);
  }

  /// Advances one step; returns true when the integration is over.
  bool step() {
    const auto system = [this](const State& x, State& dxdt, double t) {
      dxdt[0] = x[1];
      dxdt[1] = law_(t, x[0], x[1]);
    };
    stepper_.do_step(system);
    ++work_;
    const double t0 = stepper_.previous_time();
    double stop_time = stall(t0, std::min(stepper_.current_time(), options_.t_end));
    const double t_extreme = speed_extreme(t0, stop_time);
    const double t_cursor = cycle_ends(t0, t_extreme, stop_time);
    if (t_extreme >= t_cursor && t_extreme <= stop_time) note_speed(state_at(t_extreme)[1]);
    note_speed(state_at(stop_time)[1]);
    for (double t = static_cast<double>(output_index_) * output_step_; t < stop_time;
         t = static_cast<double>(++output_index_) * output_step_)
      result_.samples.push_back(sample_at(t, state_at(t)));
    if (stop_time >= options_.t_end) finished_ = true;
    if (!finished_ && work_ >= options_.max_steps) {
      result_.step_limit_reached = true;
      finished_ = true;
    }
    if (finished_) {
      State x = state_at(stop_time);
      if (result_.stalled) x[1] = 0;
      result_.samples.push_back(sample_at(stop_time, x));
    }
    return finished_;
  }

  MotionResult take_result() { return std::move(result_); }
  MotionResult& result() { return result_; }

  MotionSample sample_at(double t, const State& x) const { return MotionSample{t, x[0], x[1], law_(t, x[0], x[1])}; }

 private:
  State state_at(double t) {
    State s{};
    stepper_.calc_state(t, s);
    return s;
  }

  void note_speed(double w) {
    cycle_max_ = std::max(cycle_max_, w);
    cycle_min_ = std::min(cycle_min_, w);
  }

  /// The end of the step [t0, t1], earlier when the speed falls back to zero inside it: the
  /// machine stalls (it would not run backwards).
  double stall(double t0, double t1) {
    const State s1 = state_at(t1);
    double stop_time = t1;
    if (started_ && s1[1] <= 0) {
      stop_time = bisect([&](double t) { return state_at(t)[1]; }, t0, t1);
      result_.stalled = true;
      result_.stall_time = stop_time;
      finished_ = true;
    }
    if (s1[1] > 0) started_ = true;
    return stop_time;
  }

  /// The time of a speed extreme (alpha = 0) in [t0, t1], or -1.
  double speed_extreme(double t0, double t1) {
    const State s0 = state_at(t0), s1 = state_at(t1);
    const double alpha0 = law_(t0, s0[0], s0[1]);
    const double alpha1 = law_(t1, s1[0], s1[1]);
    if ((alpha0 > 0) == (alpha1 > 0)) return -1;
    return bisect([&](double t) { const State s = state_at(t); return law_(t, s[0], s[1]); }, t0, t1);
  }

  /// Closes every cycle that ends before stop_time (which a steady state or the step limit may
  /// bring forward); returns the end of the last one (t0 if none).
  double cycle_ends(double t0, double t_extreme, double& stop_time) {
    double t_cursor = t0;
    while (state_at(stop_time)[0] >= next_cycle_theta_) {
      if (++work_ > options_.max_steps) {
        result_.step_limit_reached = true;
        finished_ = true;
        stop_time = t_cursor;
        return t_cursor;
      }
      const double target = next_cycle_theta_;
      const double tc = bisect([&](double t) { return state_at(t)[0] - target; }, t_cursor, stop_time);
      if (t_extreme >= t_cursor && t_extreme <= tc) note_speed(state_at(t_extreme)[1]);
      close_cycle(tc);
      t_cursor = tc;
      if (!result_.steady && settled(result_.cycle_mean_speed, options_.steady_tolerance)) {
        result_.steady = true;
        result_.steady_time = tc;
        if (options_.stop_when_steady) {
          stop_time = tc;
          finished_ = true;
          return t_cursor;
        }
      }
    }
    return t_cursor;
  }

  /// Records the cycle that ends at tc and starts the next one.
  void close_cycle(double tc) {
    const double wc = state_at(tc)[1];
    note_speed(wc);
    result_.cycle_end_times.push_back(tc);
    result_.cycle_mean_speed.push_back(cycle_ / (tc - last_cycle_time_));
    result_.cycle_max_speed.push_back(cycle_max_);
    result_.cycle_min_speed.push_back(cycle_min_);
    cycle_max_ = cycle_min_ = wc;
    last_cycle_time_ = tc;
    next_cycle_theta_ += cycle_;
  }

  const AccelerationLaw& law_;
  const MotionOptions& options_;
  const double output_step_;
  const double cycle_;
  Stepper stepper_;
  MotionResult result_;
  long output_index_ = 1;
  long work_ = 0;  // steps plus completed cycles, bounded by options.max_steps
  double next_cycle_theta_;
  double last_cycle_time_ = 0;
  double cycle_max_, cycle_min_;
  bool started_;
  bool finished_ = false;
};

}  // namespace

MotionResult integrate_motion(const AccelerationLaw& law, double theta0, double omega0, const MotionOptions& options) {
  check_motion_options(options, theta0, omega0);
  Integration integration(law, options, theta0, omega0);
  MotionResult& result = integration.result();
  result.samples.push_back(integration.sample_at(0, State{theta0, omega0}));
  if (omega0 == 0 && !(result.samples.back().alpha > 0)) {
    result.cannot_start = true;
    return integration.take_result();
  }
  while (!integration.step()) {
  }
  return integration.take_result();
}

std::optional<double> time_to_reach(const MotionResult& result, double omega) {
  const auto& s = result.samples;
  for (std::size_t i = 1; i < s.size(); ++i) {
    const double w0 = s[i - 1].omega, w1 = s[i].omega;
    if ((w0 < omega && w1 >= omega) || (w0 > omega && w1 <= omega))
      return s[i - 1].t + (omega - w0) / (w1 - w0) * (s[i].t - s[i - 1].t);
  }
  if (!s.empty() && s.front().omega == omega) return s.front().t;
  return std::nullopt;
}

}  // namespace gearkit::dyn
