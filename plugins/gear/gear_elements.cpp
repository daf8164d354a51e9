// The `gear_mesh` element: two gears on two links, pivoted on a common carrier (the ground or
// an arm), mesh with the tooth ratio. Relative to the carrier c, an external pair turns in
// opposite senses and an internal pair (pinion inside a ring) in the same sense:
//     (theta_2 - theta_c) - phase = -(+) z1/z2 (theta_1 - theta_c).
// The phase is taken from the drawn angles of the links, so the drawing is a meshing position.
#include "gear_elements.hpp"

#include <gearkit/io/yaml_model.hpp>
#include <gearkit/kin/angle_relation.hpp>

#include <fmt/format.h>

namespace gearkit::plugins::gear {

namespace {

std::unique_ptr<kin::Constraint> create_gear_mesh(const kin::ElementRequest& request) {
  io::MapReader r(request.node, request.file, "gear_mesh");
  r.string("type");
  r.optional_string("name");
  const int g1 = request.body_index(r.string("gear1"));
  const int g2 = request.body_index(r.string("gear2"));
  const int carrier = r.has("carrier") ? request.body_index(r.string("carrier")) : kin::kGround;
  const long long z1 = r.integer("z1"), z2 = r.integer("z2");
  if (z1 < 1) io::fail_at(r.mark("z1"), fmt::format("expected a number of teeth >= 1, found {}", z1));
  if (z2 < 1) io::fail_at(r.mark("z2"), fmt::format("expected a number of teeth >= 1, found {}", z2));
  const bool internal = r.boolean_or("internal", false);
  if (g1 == g2 || g1 == carrier || g2 == carrier)
    io::fail_at(r.mark(), "expected gear1, gear2 and carrier to be three different links");
  r.finish();
  const double i = static_cast<double>(z1) / static_cast<double>(z2);
  const double k = internal ? -i : i;  // (theta2 - thetac) + k (theta1 - thetac) = phase
  const double phase = (request.angle_guess(g2) - request.angle_guess(carrier)) +
                       k * (request.angle_guess(g1) - request.angle_guess(carrier));
  return std::make_unique<kin::AngleRelation>(
      std::vector<std::pair<int, double>>{{g2, 1.0}, {g1, k}, {carrier, -1.0 - k}}, phase, "gear_mesh");
}

}  // namespace

void register_elements(kin::PluginRegistrar& registrar) {
  registrar.add_element_type({"gear_mesh",
                              "Two gears in mesh between two links on a common carrier: omega2/c = -z1/z2 omega1/c "
                              "(same sense if internal)",
                              &create_gear_mesh});
}

}  // namespace gearkit::plugins::gear
