// The `epicyclic_train` element: Willis' equation between the two central members of a simple
// epicyclic train and its arm (carrier),
//     (theta_out - theta_arm) = tau0 (theta_in - theta_arm) + phase,
// where tau0 is the basic ratio omega_out/omega_in with the arm held, from the tooth numbers
// of the driving and driven gears along the chain and the number of external meshes:
//     tau0 = (-1)^externals * prod(z_driving) / prod(z_driven).
// The phase comes from the drawn link angles.
#include "train_elements.hpp"

#include <gearkit/io/yaml_model.hpp>
#include <gearkit/kin/angle_relation.hpp>

#include <fmt/format.h>

#include <cmath>

namespace gearkit::plugins::train {

namespace {

double tooth_product(io::MapReader& r, const std::string& key) {
  const std::vector<YAML::Node> teeth = r.sequence(key);
  if (teeth.empty()) io::fail_at(r.mark(key), "expected a list of tooth numbers, found an empty list");
  double p = 1.0;
  for (const YAML::Node& z : teeth) {
    const std::string text = io::scalar_text(z, r.file(), "a number of teeth");
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (end == text.c_str() || *end != '\0' || v < 1)
      io::fail_at(io::mark_of(z, r.file()), fmt::format("expected a number of teeth >= 1, found {}", io::quote(text)));
    p *= static_cast<double>(v);
  }
  return p;
}

std::unique_ptr<kin::Constraint> create_epicyclic_train(const kin::ElementRequest& request) {
  io::MapReader r(request.node, request.file, "epicyclic_train");
  r.string("type");
  r.optional_string("name");
  const int in = request.body_index(r.string("input"));
  const int out = request.body_index(r.string("output"));
  const int arm = request.body_index(r.string("arm"));
  if (in == out || in == arm || out == arm) io::fail_at(r.mark(), "expected input, output and arm to be three different links");
  const double driving = tooth_product(r, "driving");
  const double driven = tooth_product(r, "driven");
  const long long externals = r.integer("externals");
  if (externals < 0) io::fail_at(r.mark("externals"), "expected the number of external meshes >= 0");
  r.finish();
  const double tau0 = (externals % 2 ? -1.0 : 1.0) * driving / driven;
  auto angle = [&](int b) { return request.angle_guess(b); };
  const double phase = (angle(out) - angle(arm)) - tau0 * (angle(in) - angle(arm));
  return std::make_unique<kin::AngleRelation>(
      std::vector<std::pair<int, double>>{{out, 1.0}, {in, -tau0}, {arm, tau0 - 1.0}}, phase, "epicyclic_train");
}

}  // namespace

void register_elements(kin::PluginRegistrar& registrar) {
  registrar.add_element_type({"epicyclic_train",
                              "Willis' equation of a simple epicyclic train: (w_out - w_arm) = tau0 (w_in - w_arm)",
                              &create_epicyclic_train});
}

}  // namespace gearkit::plugins::train
