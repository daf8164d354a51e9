#include "dyn_mechanism.hpp"

#include <gearkit/mechanism/reader.hpp>
#include <gearkit/kin/data.hpp>
#include <gearkit/kin/solve.hpp>
#include <gearkit/kin/sweep.hpp>

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace gearkit::plugins::dyn {

namespace gd = gearkit::dyn;

gd::InertiaTable mechanism_inertia_table(const std::string& path, int intervals, const io::SourceMark& where,
                                         const mechanism::ElementTypeLookup& elements) {
  const mechanism::Mechanism mech = mechanism::load_mechanism(path, elements);
  const kin::Model& model = mech.model;
  if (model.drivers().empty() || model.drivers().front().quantity != kin::DriverQuantity::angle)
    io::fail_at(where, fmt::format("mechanism {}: expected its first driver to be an angle (the load shaft)", io::quote(path)));

  std::vector<gd::BodyMass> bodies;
  bool any_mass = false;
  for (const kin::Body& b : model.bodies()) {
    bodies.push_back({b.mass, b.inertia});
    any_mass = any_mass || b.mass > 0 || b.inertia > 0;
  }
  if (!any_mass)
    io::fail_at(where, fmt::format("mechanism {}: expected links with 'mass' or 'inertia', found none", io::quote(path)));

  kin::Data data(model);
  kin::SweepOptions options;
  options.driver = 0;
  options.start = 0.0;
  options.end = 2 * std::numbers::pi;
  options.step = options.end / intervals;
  options.velocities = false;
  const kin::SweepResult sweep = kin::sweep(model, data, options);
  if (!sweep.assembled || !sweep.complete)
    io::fail_at(where, fmt::format("mechanism {} cannot turn its driver through a full revolution: {}", io::quote(path),
                                   sweep.message.empty() ? "dead point" : sweep.message));

  std::vector<double> theta, inertia;
  for (const kin::SweepSample& s : sweep.samples) {
    data.q = s.q;
    data.inputs(0) = s.input;
    kin::evaluate_constraints(model, data, 0.0);
    if (!kin::factorize(model, data))
      io::fail_at(where, fmt::format("mechanism '{}': singular position at {:.3f} deg", path, s.input * 180 / std::numbers::pi));
    // Velocity coefficients: the velocity field of a unit speed of the load shaft.
    const Eigen::VectorXd dq = kin::input_sensitivity(model, data, 0);
    std::vector<gd::VelocityCoefficients> k(model.bodies().size());
    for (std::size_t i = 0; i < model.bodies().size(); ++i) {
      const kin::Body& b = model.bodies()[i];
      const int c = 3 * static_cast<int>(i);
      const double phi = s.q(c + 2), omega = dq(c + 2);
      const Eigen::Vector2d g = Eigen::Rotation2Dd(phi) * b.centre_of_mass;
      k[i].k_G = {dq(c) - omega * g.y(), dq(c + 1) + omega * g.x()};
      k[i].k_omega = omega;
    }
    theta.push_back(s.input);
    inertia.push_back(gd::reduced_inertia(bodies, k));
  }
  try {
    // Derivatives by central differences of the periodic table (the table's own rule).
    return gd::InertiaTable(std::move(theta), std::move(inertia), {}, true);
  } catch (const std::invalid_argument& e) {
    io::fail_at(where, fmt::format("mechanism '{}': {}", path, e.what()));
  }
}

}  // namespace gearkit::plugins::dyn
