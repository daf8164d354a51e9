#include <gearkit/dyn/drive_line.hpp>

#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "number_text.hpp"

namespace gearkit::dyn {

namespace {

using detail::num;

std::string stage_name(const DriveLine& line, std::size_t i) {
  const std::string& n = line.stages[i].name;
  return n.empty() ? "stage " + std::to_string(i + 1) : "stage '" + n + "'";
}

std::string shaft_name(const DriveLine& line, std::size_t k) {
  if (k < line.shaft_names.size() && !line.shaft_names[k].empty()) return "shaft '" + line.shaft_names[k] + "'";
  return k == 0 ? std::string("the motor shaft") : "shaft " + std::to_string(k);
}

void check_efficiency(double eta, const std::string& what) {
  if (!std::isfinite(eta) || !(eta > 0) || eta > 1)
    throw std::invalid_argument("efficiency of " + what + " must be in (0, 1], found " + num(eta));
}

void check_shaft(const DriveLine& line, std::size_t k) {
  if (k >= shaft_count(line))
    throw std::out_of_range("shaft " + std::to_string(k) + " does not exist (the line has " +
                            std::to_string(shaft_count(line)) + " shafts)");
}

}  // namespace

std::size_t shaft_count(const DriveLine& line) { return line.stages.size() + 1; }

void validate(const DriveLine& line) {
  check_efficiency(line.motor_efficiency, "the motor");
  for (std::size_t i = 0; i < line.stages.size(); ++i) {
    const Stage& s = line.stages[i];
    if (!std::isfinite(s.ratio) || s.ratio == 0)
      throw std::invalid_argument("speed ratio of " + stage_name(line, i) + " must be finite and non-zero, found " +
                                  num(s.ratio));
    check_efficiency(s.efficiency, stage_name(line, i));
  }
  if (line.shaft_inertia.size() != shaft_count(line))
    throw std::invalid_argument("drive line: expected " + std::to_string(shaft_count(line)) +
                                " shaft inertias, found " + std::to_string(line.shaft_inertia.size()));
  for (std::size_t k = 0; k < line.shaft_inertia.size(); ++k)
    if (!std::isfinite(line.shaft_inertia[k]) || line.shaft_inertia[k] < 0)
      throw std::invalid_argument("inertia on " + shaft_name(line, k) + " must be >= 0 kg*m^2, found " +
                                  num(line.shaft_inertia[k]));
}

double speed_ratio(const DriveLine& line, std::size_t from, std::size_t to) {
  check_shaft(line, from);
  check_shaft(line, to);
  double r = 1;
  for (std::size_t i = std::min(from, to); i < std::max(from, to); ++i) r *= std::abs(line.stages[i].ratio);
  return to >= from ? r : 1 / r;
}

double efficiency_between(const DriveLine& line, std::size_t a, std::size_t b) {
  check_shaft(line, a);
  check_shaft(line, b);
  double eta = 1;
  for (std::size_t i = std::min(a, b); i < std::max(a, b); ++i) eta *= line.stages[i].efficiency;
  return eta;
}

double reduced_inertia(const DriveLine& line, std::size_t ref) {
  double sum = 0;
  for (std::size_t k = 0; k < shaft_count(line); ++k) {
    const double r = speed_ratio(line, ref, k);
    sum += line.shaft_inertia.at(k) * r * r;
  }
  return sum;
}

double power_at_input(double power_out, double efficiency) {
  return power_out > 0 ? power_out / efficiency : power_out * efficiency;
}

double reduced_torque(const DriveLine& line, double torque, std::size_t from, std::size_t to) {
  const double eta = efficiency_between(line, from, to);
  const double t = torque * speed_ratio(line, to, from);
  return torque > 0 ? t * eta : t / eta;
}

double drive_line_acceleration(const DriveLine& line, double motor_torque,
                               const std::vector<double>& resisting_torque, double omega_motor) {
  const std::size_t n = shaft_count(line);
  if (resisting_torque.size() != n)
    throw std::invalid_argument("drive line: expected " + std::to_string(n) + " resisting torques, found " +
                                std::to_string(resisting_torque.size()));
  const double inertia = reduced_inertia(line, 0);
  if (!(inertia > 0))
    throw std::invalid_argument("drive line: the reduced inertia must be > 0 kg*m^2, found " + num(inertia));
  std::vector<double> r(n);
  for (std::size_t k = 0; k < n; ++k) r[k] = speed_ratio(line, 0, k);
  const double sense = omega_motor < 0 ? -1.0 : 1.0;

  // Power the motor must deliver, per unit of |omega_motor|, for a motor-shaft acceleration
  // alpha: walk from the load end, each stage passing the net demand of everything after it.
  const auto demand = [&](double alpha) {
    double q = 0;
    for (std::size_t k = n; k-- > 0;) {
      const double torque_k = line.shaft_inertia[k] * r[k] * alpha + resisting_torque[k];
      const double own = sense * torque_k * r[k];
      q = k + 1 < n ? own + power_at_input(q, line.stages[k].efficiency) : own;
    }
    return q - sense * motor_torque;
  };

  double sum_resist = 0;
  for (std::size_t k = 0; k < n; ++k) sum_resist += resisting_torque[k] * r[k];
  const double guess = (motor_torque - sum_resist) / inertia;
  double step = 1 + std::abs(guess);
  double a = guess - step, b = guess + step;
  double fa = demand(a), fb = demand(b);
  for (int i = 0; i < 200 && fa * fb > 0; ++i) {
    step *= 4;
    a = guess - step;
    b = guess + step;
    fa = demand(a);
    fb = demand(b);
  }
  if (fa == 0) return a;
  if (fb == 0) return b;
  if (fa * fb > 0 || !std::isfinite(fa) || !std::isfinite(fb))
    throw std::invalid_argument("drive line: no finite acceleration balances the torques (motor torque " +
                                num(motor_torque) + " N*m)");
  std::uintmax_t iterations = 200;
  const auto root = boost::math::tools::toms748_solve(demand, a, b, fa, fb,
                                                       boost::math::tools::eps_tolerance<double>(52), iterations);
  return 0.5 * (root.first + root.second);
}

}  // namespace gearkit::dyn
