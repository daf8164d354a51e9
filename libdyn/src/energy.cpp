#include <gearkit/dyn/energy.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "number_text.hpp"

namespace gearkit::dyn {

namespace {

using detail::num;

// Positive and negative parts of the integral of the line through (u, fu) and (v, fv).
void add_segment(double u, double fu, double v, double fv, SignedIntegrals& s) {
  const double h = v - u;
  if (h <= 0) return;
  if (fu >= 0 && fv >= 0) {
    s.positive += 0.5 * (fu + fv) * h;
  } else if (fu <= 0 && fv <= 0) {
    s.negative += 0.5 * (fu + fv) * h;
  } else {
    const double xc = h * fu / (fu - fv);  // distance from u to the zero
    const double part_u = 0.5 * fu * xc, part_v = 0.5 * fv * (h - xc);
    (fu > 0 ? s.positive : s.negative) += part_u;
    (fv > 0 ? s.positive : s.negative) += part_v;
  }
}

}  // namespace

SignedIntegrals signed_integrals(const PiecewiseLinear& f, double a, double b) {
  SignedIntegrals s;
  if (!(b > a)) return s;
  std::vector<double> xs{a, b};
  if (f.periodic()) {
    const double period = f.range();
    const double k0 = std::floor((a - f.x_front()) / period), k1 = std::ceil((b - f.x_front()) / period);
    for (double k = k0; k <= k1; ++k)
      for (double x : f.x()) {
        const double xk = x + k * period;
        if (xk > a && xk < b) xs.push_back(xk);
      }
  } else {
    for (double x : f.x())
      if (x > a && x < b) xs.push_back(x);
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) add_segment(xs[i], f(xs[i]), xs[i + 1], f.left_value(xs[i + 1]), s);
  return s;
}

CycleEnergyBalance analyse_energy(const SteadyCycle& cycle) {
  validate(cycle.line);
  if (!(cycle.motor_speed > 0) || !std::isfinite(cycle.motor_speed))
    throw std::invalid_argument("energy: motor speed must be > 0 rad/s, found " + num(cycle.motor_speed));
  if (!(cycle.cycle_angle > 0) || !std::isfinite(cycle.cycle_angle))
    throw std::invalid_argument("energy: cycle angle must be > 0 rad, found " + num(cycle.cycle_angle));
  const std::size_t n = shaft_count(cycle.line);
  const std::size_t load = n - 1;

  CycleEnergyBalance b;
  for (std::size_t k = 0; k < n; ++k) b.shaft_speed.push_back(cycle.motor_speed * speed_ratio(cycle.line, 0, k));
  b.cycle_time = cycle.cycle_angle / b.shaft_speed[load];

  SignedIntegrals demand{};
  std::vector<PiecewiseLinear> curves;
  for (const LoadTorque& t : cycle.torques) {
    if (std::abs(t.torque.range() - cycle.cycle_angle) > 1e-9 * cycle.cycle_angle)
      throw std::invalid_argument("energy: load torque '" + t.name + "' covers " + num(t.torque.range()) +
                                  " rad but the cycle is " + num(cycle.cycle_angle) + " rad");
    curves.push_back(t.torque);
    const double e = t.torque.integral(t.torque.x_front(), t.torque.x_back());
    if (t.useful) b.useful_energy += e;
  }
  if (!curves.empty()) {
    PiecewiseLinear total = curves.front();
    for (std::size_t i = 1; i < curves.size(); ++i) total = difference(total, curves[i].scaled(-1));
    demand = signed_integrals(total, total.x_front(), total.x_back());
    for (const Phase& p : cycle.phases) {
      if (!(p.theta_to > p.theta_from) || p.theta_from < total.x_front() - 1e-9 * cycle.cycle_angle ||
          p.theta_to > total.x_back() + 1e-9 * cycle.cycle_angle)
        throw std::invalid_argument("energy: phase '" + p.name + "' [" + num(p.theta_from) + ", " + num(p.theta_to) +
                                    "] rad is empty or outside the cycle");
      PhaseEnergy pe;
      pe.name = p.name;
      pe.duration = (p.theta_to - p.theta_from) / b.shaft_speed[load];
      pe.energy = total.integral(p.theta_from, p.theta_to);
      pe.mean_power = pe.energy / pe.duration;
      b.phases.push_back(pe);
    }
  } else if (!cycle.phases.empty()) {
    throw std::invalid_argument("energy: phases need at least one load torque over the cycle");
  }
  for (const LoadEnergy& e : cycle.energies) {
    if (!(e.energy >= 0) || !std::isfinite(e.energy))
      throw std::invalid_argument("energy: '" + e.name + "' must take >= 0 J per cycle, found " + num(e.energy));
    demand.positive += e.energy;
    if (e.useful) b.useful_energy += e.energy;
  }
  b.load_energy = demand.positive + demand.negative;

  // Walk from the load to the motor, each stage passing absorbed energy divided by its
  // efficiency and returned energy multiplied by it.
  std::vector<SignedIntegrals> at(n);
  at[load] = demand;
  for (std::size_t k = load; k-- > 0;) {
    const double eta = cycle.line.stages[k].efficiency;
    at[k] = {at[k + 1].positive / eta, at[k + 1].negative * eta};
  }
  const double eta_m = cycle.line.motor_efficiency;
  b.electrical_energy = at[0].positive / eta_m + at[0].negative * eta_m;
  b.mean_electrical_power = b.electrical_energy / b.cycle_time;
  b.overall_efficiency = b.electrical_energy > 0 ? b.useful_energy / b.electrical_energy : 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    b.shaft_mean_power.push_back((at[k].positive + at[k].negative) / b.cycle_time);
    b.shaft_mean_torque.push_back(b.shaft_mean_power[k] / b.shaft_speed[k]);
  }
  b.elements.push_back({"motor", b.mean_electrical_power, b.shaft_mean_power[0],
                        b.mean_electrical_power - b.shaft_mean_power[0]});
  for (std::size_t i = 0; i < cycle.line.stages.size(); ++i) {
    const std::string name = cycle.line.stages[i].name.empty() ? "stage " + std::to_string(i + 1)
                                                                : cycle.line.stages[i].name;
    b.elements.push_back({name, b.shaft_mean_power[i], b.shaft_mean_power[i + 1],
                          b.shaft_mean_power[i] - b.shaft_mean_power[i + 1]});
  }
  return b;
}

}  // namespace gearkit::dyn
