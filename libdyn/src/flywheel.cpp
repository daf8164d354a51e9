#include <gearkit/dyn/flywheel.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "number_text.hpp"

namespace gearkit::dyn {

namespace {

using detail::num;

int sign_of(double v, double tol) { return v > tol ? 1 : (v < -tol ? -1 : 0); }

void require_finite(double v, const char* what) {
  if (!std::isfinite(v)) throw std::invalid_argument(std::string(what) + " is not finite");
}

}  // namespace

double energy_at(const PiecewiseLinear& drive, const PiecewiseLinear& resist, double theta) {
  return drive.integral(drive.x_front(), theta) - resist.integral(resist.x_front(), theta);
}

CycleEnergy analyse_cycle(const PiecewiseLinear& drive, const PiecewiseLinear& resist, double balance_tolerance) {
  if (!drive.periodic() || !resist.periodic())
    throw std::invalid_argument("flywheel: driving and resisting torques must both be periodic over the cycle");
  const PiecewiseLinear net = difference(drive, resist);

  CycleEnergy c;
  c.theta_start = net.x_front();
  c.period = net.range();
  c.drive_energy = drive.integral(c.theta_start, c.theta_start + c.period);
  c.resist_energy = resist.integral(c.theta_start, c.theta_start + c.period);
  c.mean_drive_torque = c.drive_energy / c.period;
  c.mean_resist_torque = c.resist_energy / c.period;
  const double scale = std::max(std::abs(c.drive_energy), std::abs(c.resist_energy));
  if (std::abs(c.drive_energy - c.resist_energy) > balance_tolerance * scale)
    throw std::invalid_argument("the cycle is not steady: the driving torque does " + num(c.drive_energy) +
                                " J per cycle but the resisting torque takes " + num(c.resist_energy) +
                                " J; scale one of them to balance the energy");

  const auto& x = net.x();
  const auto& y = net.y();
  double ymax = 0;
  for (double v : y) ymax = std::max(ymax, std::abs(v));
  const double tol = 1e-12 * ymax;

  // E is continuous and piecewise quadratic; it peaks where T_d - T_r changes sign, which is at
  // a breakpoint (possibly a step) or at a crossing inside a segment.
  double energy = 0;
  c.energy_max = c.energy_min = 0;
  c.theta_at_energy_max = c.theta_at_energy_min = x.front();
  const auto candidate = [&c](double theta, double e) {
    if (e > c.energy_max) { c.energy_max = e; c.theta_at_energy_max = theta; }
    if (e < c.energy_min) { c.energy_min = e; c.theta_at_energy_min = theta; }
  };
  // Pieces of constant sign, for the lobes.
  struct Piece { double a, b, e; int sign; };
  std::vector<Piece> pieces;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    const double x0 = x[i], x1 = x[i + 1], y0 = y[i], y1 = y[i + 1];
    if (x1 == x0) continue;  // a step: E does not change across it
    const int s0 = sign_of(y0, tol), s1 = sign_of(y1, tol);
    if (s0 * s1 < 0) {
      const double xc = x0 + y0 / (y0 - y1) * (x1 - x0);
      const double e0 = 0.5 * y0 * (xc - x0);
      const double e1 = 0.5 * y1 * (x1 - xc);
      pieces.push_back({x0, xc, e0, s0});
      pieces.push_back({xc, x1, e1, s1});
      candidate(xc, energy + e0);
      energy += e0 + e1;
    } else {
      const double e = 0.5 * (y0 + y1) * (x1 - x0);
      pieces.push_back({x0, x1, e, s0 != 0 ? s0 : s1});
      energy += e;
    }
    candidate(x1, energy);
  }
  c.energy_excursion = c.energy_max - c.energy_min;

  std::vector<int> lobe_sign;
  for (const Piece& p : pieces) {
    if (!c.lobes.empty() && (p.sign == 0 || lobe_sign.back() == 0 || p.sign == lobe_sign.back())) {
      c.lobes.back().theta_end = p.b;
      c.lobes.back().energy += p.e;
      if (lobe_sign.back() == 0) lobe_sign.back() = p.sign;
      continue;
    }
    c.lobes.push_back({p.a, p.b, p.e});
    lobe_sign.push_back(p.sign);
  }
  // The last lobe continues into the first when both have the same sign (the cycle is closed).
  if (c.lobes.size() > 1 && lobe_sign.front() == lobe_sign.back()) {
    c.lobes.back().theta_end = c.lobes.front().theta_end + c.period;
    c.lobes.back().energy += c.lobes.front().energy;
    c.lobes.erase(c.lobes.begin());
  }
  return c;
}

double balance_scale(const PiecewiseLinear& reference, const PiecewiseLinear& shape) {
  const double work_shape = shape.integral(shape.x_front(), shape.x_back());
  const double work_ref = reference.integral(shape.x_front(), shape.x_back());
  if (std::abs(work_shape) <= 1e-300 || !std::isfinite(work_shape))
    throw std::invalid_argument("cannot balance the cycle: the torque shape does no work over its cycle");
  return work_ref / work_shape;
}

FlywheelSizing size_flywheel(double energy_excursion, double omega_mean, double fluctuation, double inertia_machine) {
  require_finite(energy_excursion, "energy excursion");
  require_finite(omega_mean, "mean speed");
  require_finite(fluctuation, "coefficient of speed fluctuation");
  require_finite(inertia_machine, "machine inertia");
  if (energy_excursion < 0)
    throw std::invalid_argument("energy excursion must be >= 0 J, found " + num(energy_excursion));
  if (!(omega_mean > 0)) throw std::invalid_argument("mean speed must be > 0 rad/s, found " + num(omega_mean));
  if (!(fluctuation > 0 && fluctuation < 2))
    throw std::invalid_argument("coefficient of speed fluctuation must be in (0, 2), found " + num(fluctuation));
  if (inertia_machine < 0)
    throw std::invalid_argument("machine inertia must be >= 0 kg*m^2, found " + num(inertia_machine));
  FlywheelSizing s;
  s.omega_mean = omega_mean;
  s.fluctuation = fluctuation;
  s.omega_max = omega_mean * (1 + fluctuation / 2);
  s.omega_min = omega_mean * (1 - fluctuation / 2);
  s.energy_excursion = energy_excursion;
  s.inertia_total = energy_excursion / (fluctuation * omega_mean * omega_mean);
  s.inertia_machine = inertia_machine;
  s.flywheel_needed = s.inertia_total > inertia_machine;
  s.inertia_flywheel = s.flywheel_needed ? s.inertia_total - inertia_machine : 0.0;
  s.fluctuation_without_flywheel = inertia_machine > 0
                                       ? energy_excursion / (inertia_machine * omega_mean * omega_mean)
                                       : std::numeric_limits<double>::infinity();
  return s;
}

double fluctuation_for_inertia(double energy_excursion, double omega_mean, double inertia) {
  if (!(inertia > 0)) throw std::invalid_argument("inertia must be > 0 kg*m^2, found " + num(inertia));
  if (!(omega_mean > 0)) throw std::invalid_argument("mean speed must be > 0 rad/s, found " + num(omega_mean));
  return energy_excursion / (inertia * omega_mean * omega_mean);
}

}  // namespace gearkit::dyn
