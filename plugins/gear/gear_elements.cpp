// The `gear_mesh` entry of mechanism files (docs/kin.md), read into
// gearkit::elements::GearMeshParameters and built by make_gear_mesh.
#include "gear_elements.hpp"

#include <gearkit/elements/gear_mesh.hpp>
#include <gearkit/mechanism/element_type.hpp>

#include <fmt/format.h>

namespace gearkit::plugins::gear {

namespace {

int teeth(io::MapReader& keys, const std::string& key) {
  const long long z = keys.integer(key);
  if (z < 1 || z > 1000000)
    io::fail_at(keys.mark(key), fmt::format("'{}': expected a number of teeth from 1 to 1000000, found {}", key, z));
  return static_cast<int>(z);
}

std::unique_ptr<kin::Constraint> read_gear_mesh(mechanism::ElementReader& reader) {
  io::MapReader& keys = reader.keys();
  elements::GearMeshParameters p;
  p.gear1 = reader.link("gear1");
  p.gear2 = reader.link("gear2");
  p.carrier = reader.link_or("carrier", kin::kGround);
  p.z1 = teeth(keys, "z1");
  p.z2 = teeth(keys, "z2");
  p.internal = keys.boolean_or("internal", false);
  p.module = keys.optional_quantity("module", io::Quantity::length, "mm");
  p.pressure_angle = keys.quantity_or("pressure_angle", io::Quantity::angle, "deg", p.pressure_angle);
  p.helix_angle = keys.quantity_or("helix_angle", io::Quantity::angle, "deg", p.helix_angle);
  return elements::make_gear_mesh(reader.model(), p);
}

}  // namespace

void register_elements(plugin::PluginRegistrar& registrar) {
  registrar.add_element_type({"gear_mesh",
                              "Two gears in mesh between two links on a common carrier: omega2/c = -z1/z2 omega1/c "
                              "(same sense if internal); tooth forces with a module",
                              &read_gear_mesh});
}

}  // namespace gearkit::plugins::gear
