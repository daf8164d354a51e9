#include <gearkit/mechanism/sweep_start.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gearkit::mechanism {

kin::SweepOptions sweep_options(int driver, double from, double to, double step, bool velocities, bool switch_branch) {
  kin::SweepOptions o;
  o.switch_branch = switch_branch;
  o.driver = driver;
  o.start = from;
  o.end = to;
  o.step = step;
  o.velocities = velocities;
  o.min_step = 1e-9 * std::max(1.0, std::abs(to - from));
  return o;
}

void approach_start(const Mechanism& mech, kin::Data& data, int driver, const kin::SweepOptions& sweep) {
  if (driver < 0 || static_cast<std::size_t>(driver) >= mech.drivers.size()) throw std::invalid_argument("approach_start: no such driver");
  const double drawn = data.inputs(driver), direction = sweep.end >= sweep.start ? 1.0 : -1.0;
  const double near = sweep.start + direction * 2.0 * kin::change_point_offset(sweep);
  const bool angular = mech.drivers[static_cast<std::size_t>(driver)].quantity == kin::DriverQuantity::angle;
  const double step = angular ? 2.0 * std::numbers::pi / 180.0 : 0.002;
  if (std::abs(near - drawn) <= 1e-12 * std::max(1.0, std::abs(drawn))) return;
  const Eigen::VectorXd drawn_q = data.q;
  const kin::SweepResult s = kin::sweep(mech.model, data, sweep_options(driver, drawn, near, std::min(step, std::abs(near - drawn)), false, false));
  if (s.complete) {
    data.q = s.samples.back().q;
    data.inputs(driver) = near;
    return;
  }
  data.q = drawn_q;
  data.inputs(driver) = drawn;
}

}  // namespace gearkit::mechanism
