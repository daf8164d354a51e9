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

MotionResult integrate_motion(const AccelerationLaw& law, double theta0, double omega0, const MotionOptions& options) {
  if (!(options.t_end > 0) || !std::isfinite(options.t_end))
    throw std::invalid_argument("motion: end time must be > 0 s, found " + num(options.t_end));
  if (options.output_step < 0 || options.max_step < 0 || options.cycle < 0)
    throw std::invalid_argument("motion: output step, largest step and cycle must not be negative");
  if (!(options.abs_tolerance > 0) || !(options.rel_tolerance > 0) || !(options.steady_tolerance > 0))
    throw std::invalid_argument("motion: tolerances must be > 0");
  if (options.max_steps < 1) throw std::invalid_argument("motion: the step limit must be at least 1");
  if (!std::isfinite(theta0) || !std::isfinite(omega0))
    throw std::invalid_argument("motion: the initial state is not finite");
  const double output_step = options.output_step > 0 ? options.output_step : options.t_end / 2000;
  const double max_step = options.max_step > 0 ? options.max_step : output_step;
  const double cycle = options.cycle > 0 ? options.cycle : 2 * std::numbers::pi;

  MotionResult result;
  const auto sample_at = [&law](double t, const State& x) { return MotionSample{t, x[0], x[1], law(t, x[0], x[1])}; };
  const State x0{theta0, omega0};
  result.samples.push_back(sample_at(0, x0));
  if (omega0 == 0 && !(result.samples.back().alpha > 0)) {
    result.cannot_start = true;
    return result;
  }

  const auto system = [&law](const State& x, State& dxdt, double t) {
    dxdt[0] = x[1];
    dxdt[1] = law(t, x[0], x[1]);
  };
  auto stepper = odeint::make_dense_output(options.abs_tolerance, options.rel_tolerance, max_step,
                                           odeint::runge_kutta_dopri5<State>());
  stepper.initialize(x0, 0.0, std::min(max_step, options.t_end) / 100);

  long output_index = 1;
  double next_cycle_theta = theta0 + cycle;
  double last_cycle_time = 0;
  double cycle_max = omega0, cycle_min = omega0;
  bool started = omega0 > 0;
  State x{};
  const auto state_at = [&stepper](double t) {
    State s{};
    stepper.calc_state(t, s);
    return s;
  };

  bool finished = false;
  long work = 0;  // steps plus completed cycles, bounded by options.max_steps
  while (!finished) {
    stepper.do_step(system);
    ++work;
    const double t0 = stepper.previous_time();
    const double t1 = std::min(stepper.current_time(), options.t_end);
    const State s0 = state_at(t0);
    const State s1 = state_at(t1);
    double stop_time = t1;

    // A speed that falls back to zero: the machine stalls (it would not run backwards).
    if (started && s1[1] <= 0) {
      stop_time = bisect([&](double t) { return state_at(t)[1]; }, t0, t1);
      result.stalled = true;
      result.stall_time = stop_time;
      finished = true;
    }
    if (s1[1] > 0) started = true;

    // Events inside the step, in time order: speed extremes (alpha = 0) and cycle ends.
    const double alpha0 = law(t0, s0[0], s0[1]);
    const double alpha1 = law(stop_time, state_at(stop_time)[0], state_at(stop_time)[1]);
    double t_extreme = -1;
    if ((alpha0 > 0) != (alpha1 > 0))
      t_extreme = bisect([&](double t) { const State s = state_at(t); return law(t, s[0], s[1]); }, t0, stop_time);
    const auto note_speed = [&](double w) {
      cycle_max = std::max(cycle_max, w);
      cycle_min = std::min(cycle_min, w);
    };
    double t_cursor = t0;
    bool stop_events = false;
    while (!stop_events && state_at(stop_time)[0] >= next_cycle_theta) {
      if (++work > options.max_steps) {
        result.step_limit_reached = true;
        finished = stop_events = true;
        stop_time = t_cursor;
        break;
      }
      const double target = next_cycle_theta;
      const double tc = bisect([&](double t) { return state_at(t)[0] - target; }, t_cursor, stop_time);
      if (t_extreme >= t_cursor && t_extreme <= tc) note_speed(state_at(t_extreme)[1]);
      const double wc = state_at(tc)[1];
      note_speed(wc);
      result.cycle_end_times.push_back(tc);
      result.cycle_mean_speed.push_back(cycle / (tc - last_cycle_time));
      result.cycle_max_speed.push_back(cycle_max);
      result.cycle_min_speed.push_back(cycle_min);
      cycle_max = cycle_min = wc;
      last_cycle_time = tc;
      next_cycle_theta += cycle;
      t_cursor = tc;
      if (!result.steady && settled(result.cycle_mean_speed, options.steady_tolerance)) {
        result.steady = true;
        result.steady_time = tc;
        if (options.stop_when_steady) {
          stop_time = tc;
          finished = stop_events = true;
        }
      }
    }
    if (t_extreme >= t_cursor && t_extreme <= stop_time) note_speed(state_at(t_extreme)[1]);
    note_speed(state_at(stop_time)[1]);

    for (double t = static_cast<double>(output_index) * output_step; t < stop_time;
         t = static_cast<double>(++output_index) * output_step)
      result.samples.push_back(sample_at(t, state_at(t)));
    if (stop_time >= options.t_end) finished = true;
    if (!finished && work >= options.max_steps) {
      result.step_limit_reached = true;
      finished = true;
    }
    if (finished) {
      x = state_at(stop_time);
      if (result.stalled) x[1] = 0;
      result.samples.push_back(sample_at(stop_time, x));
    }
  }
  return result;
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
