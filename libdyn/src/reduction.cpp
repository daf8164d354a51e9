#include <gearkit/dyn/reduction.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "number_text.hpp"

namespace gearkit::dyn {

namespace {

using detail::num;

void check_bodies(std::span<const BodyMass> bodies, std::span<const VelocityCoefficients> k) {
  if (bodies.size() != k.size())
    throw std::invalid_argument("reduction: " + std::to_string(bodies.size()) + " bodies but " +
                                std::to_string(k.size()) + " sets of velocity coefficients");
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (!(bodies[i].mass >= 0) || !(bodies[i].inertia_G >= 0) || !std::isfinite(bodies[i].mass) ||
        !std::isfinite(bodies[i].inertia_G))
      throw std::invalid_argument("reduction: body " + std::to_string(i + 1) +
                                  " needs mass >= 0 kg and inertia >= 0 kg*m^2, found " + num(bodies[i].mass) +
                                  " kg and " + num(bodies[i].inertia_G) + " kg*m^2");
}

}  // namespace

double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
double norm(Vec2 a) { return std::hypot(a.x, a.y); }

double virtual_power(std::span<const ForceAtPoint> forces, std::span<const TorqueOnBody> torques) {
  double p = 0;
  for (const auto& f : forces) p += dot(f.force, f.velocity);
  for (const auto& m : torques) p += m.torque * m.omega;
  return p;
}

double reduced_force(double power, Vec2 velocity_at_reduction_point) {
  const double v = norm(velocity_at_reduction_point);
  if (!(v > 0))
    throw std::invalid_argument("reduced force: the reduction point does not move (dead point), no finite force");
  return power / v;
}

double reduced_torque_at(double power, double omega) {
  if (omega == 0 || !std::isfinite(omega))
    throw std::invalid_argument("reduced torque: the reduction shaft does not turn (dead point), no finite torque");
  return power / omega;
}

Vec2 inertia_force(double mass, Vec2 acceleration) { return {-mass * acceleration.x, -mass * acceleration.y}; }

Vec2 weight(double mass, double gravity) { return {0, -mass * gravity}; }

double reduced_inertia(std::span<const BodyMass> bodies, std::span<const VelocityCoefficients> k) {
  check_bodies(bodies, k);
  double sum = 0;
  for (std::size_t i = 0; i < bodies.size(); ++i)
    sum += bodies[i].mass * dot(k[i].k_G, k[i].k_G) + bodies[i].inertia_G * k[i].k_omega * k[i].k_omega;
  return sum;
}

double reduced_inertia_derivative(std::span<const BodyMass> bodies, std::span<const VelocityCoefficients> k) {
  check_bodies(bodies, k);
  double sum = 0;
  for (std::size_t i = 0; i < bodies.size(); ++i)
    sum += 2 * (bodies[i].mass * dot(k[i].k_G, k[i].dk_G) + bodies[i].inertia_G * k[i].k_omega * k[i].dk_omega);
  return sum;
}

double reduced_weight_torque(std::span<const BodyMass> bodies, std::span<const VelocityCoefficients> k,
                             double gravity) {
  check_bodies(bodies, k);
  double sum = 0;
  for (std::size_t i = 0; i < bodies.size(); ++i) sum += dot(weight(bodies[i].mass, gravity), k[i].k_G);
  return sum;
}

double reduced_torque_of_force(Vec2 force, Vec2 k_P) { return dot(force, k_P); }

Vec2 spring_force_on(Vec2 p, Vec2 q, double stiffness, double free_length) {
  const Vec2 d{p.x - q.x, p.y - q.y};
  const double length = norm(d);
  if (!(length > 0)) throw std::invalid_argument("spring: its two ends coincide, the force has no direction");
  const double magnitude = -stiffness * (length - free_length);
  return {magnitude * d.x / length, magnitude * d.y / length};
}

double reduced_spring_torque(Vec2 p, Vec2 q, Vec2 k_P, Vec2 k_Q, double stiffness, double free_length) {
  // Equal and opposite forces on the two ends: their power is F_P . (v_P - v_Q).
  return dot(spring_force_on(p, q, stiffness, free_length), {k_P.x - k_Q.x, k_P.y - k_Q.y});
}

InertiaTable::InertiaTable(std::vector<double> theta, std::vector<double> inertia, std::vector<double> derivative,
                           bool periodic)
    : theta_(std::move(theta)), inertia_(std::move(inertia)), derivative_(std::move(derivative)), periodic_(periodic) {
  const std::size_t n = theta_.size();
  if (inertia_.size() != n || (!derivative_.empty() && derivative_.size() != n))
    throw std::invalid_argument("inertia table: angles, inertias and derivatives differ in number");
  if (n < 3) throw std::invalid_argument("inertia table: expected at least 3 nodes, found " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(theta_[i]) || !std::isfinite(inertia_[i]) ||
        (!derivative_.empty() && !std::isfinite(derivative_[i])))
      throw std::invalid_argument("inertia table: node " + std::to_string(i + 1) + " is not finite");
    if (i > 0 && !(theta_[i] > theta_[i - 1]))
      throw std::invalid_argument("inertia table: angles must increase, found " + num(theta_[i]) + " after " +
                                  num(theta_[i - 1]));
    if (!(inertia_[i] > 0))
      throw std::invalid_argument("inertia table: reduced inertia must be > 0 kg*m^2, found " + num(inertia_[i]) +
                                  " at theta = " + num(theta_[i]) + " rad");
  }
  if (periodic_ && std::abs(inertia_.front() - inertia_.back()) > 1e-9 * max_inertia())
    throw std::invalid_argument("inertia table is not periodic: " + num(inertia_.front()) + " kg*m^2 at the start, " +
                                num(inertia_.back()) + " kg*m^2 at the end");
  if (derivative_.empty()) {
    derivative_.resize(n);
    const double period = theta_.back() - theta_.front();
    for (std::size_t i = 0; i < n; ++i) {
      if (i > 0 && i + 1 < n) {
        derivative_[i] = (inertia_[i + 1] - inertia_[i - 1]) / (theta_[i + 1] - theta_[i - 1]);
      } else if (periodic_) {
        derivative_[i] = (inertia_[1] - inertia_[n - 2]) / (theta_[1] - theta_[n - 2] + period);
      } else if (i == 0) {
        derivative_[i] = (inertia_[1] - inertia_[0]) / (theta_[1] - theta_[0]);
      } else {
        derivative_[i] = (inertia_[n - 1] - inertia_[n - 2]) / (theta_[n - 1] - theta_[n - 2]);
      }
    }
  }
}

std::size_t InertiaTable::locate(double& theta) const {
  if (periodic_) {
    const double period = theta_.back() - theta_.front();
    double r = theta - theta_.front();
    r -= period * std::floor(r / period);
    if (r >= period || r < 0) r = 0;
    theta = theta_.front() + r;
  } else {
    theta = std::clamp(theta, theta_.front(), theta_.back());
  }
  const auto it = std::upper_bound(theta_.begin(), theta_.end(), theta);
  const auto i = static_cast<std::size_t>(it - theta_.begin());
  return std::min(i == 0 ? 0 : i - 1, theta_.size() - 2);
}

double InertiaTable::inertia(double theta) const {
  const std::size_t i = locate(theta);
  const double h = theta_[i + 1] - theta_[i];
  const double t = (theta - theta_[i]) / h;
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * inertia_[i] + (t3 - 2 * t2 + t) * h * derivative_[i] +
         (-2 * t3 + 3 * t2) * inertia_[i + 1] + (t3 - t2) * h * derivative_[i + 1];
}

double InertiaTable::derivative(double theta) const {
  const std::size_t i = locate(theta);
  const double h = theta_[i + 1] - theta_[i];
  const double t = (theta - theta_[i]) / h;
  const double t2 = t * t;
  return ((6 * t2 - 6 * t) * inertia_[i] + (-6 * t2 + 6 * t) * inertia_[i + 1]) / h +
         (3 * t2 - 4 * t + 1) * derivative_[i] + (3 * t2 - 2 * t) * derivative_[i + 1];
}

double InertiaTable::min_inertia() const { return *std::min_element(inertia_.begin(), inertia_.end()); }
double InertiaTable::max_inertia() const { return *std::max_element(inertia_.begin(), inertia_.end()); }

double InertiaTable::mean_inertia() const {
  double sum = 0;
  for (std::size_t i = 0; i + 1 < theta_.size(); ++i) {
    const double h = theta_[i + 1] - theta_[i];
    sum += h * (inertia_[i] + inertia_[i + 1]) / 2 + h * h * (derivative_[i] - derivative_[i + 1]) / 12;
  }
  return sum / period();
}

InertiaTable tabulate_inertia(std::span<const BodyMass> bodies,
                              const std::function<std::vector<VelocityCoefficients>(double)>& coefficients,
                              double theta0, double theta1, int n, bool periodic) {
  if (n < 2 || !(theta1 > theta0))
    throw std::invalid_argument("inertia table: expected at least 2 intervals over a non-empty range");
  std::vector<double> th, in, di;
  for (int i = 0; i <= n; ++i) {
    const double t = i == n ? theta1 : theta0 + (theta1 - theta0) * i / n;
    const auto k = coefficients(t);
    th.push_back(t);
    in.push_back(reduced_inertia(bodies, k));
    di.push_back(reduced_inertia_derivative(bodies, k));
  }
  return InertiaTable(std::move(th), std::move(in), std::move(di), periodic);
}

}  // namespace gearkit::dyn
