#pragma once
// The `equations:` section of a mechanism file (docs/kin.md): the generalised coordinates the
// course uses and the dimensions it writes as symbols.
//
//   equations:
//     coordinates:
//       - {name: phi1, angle: [crank.O, crank.P]}                  # direction O->P, ccw from +x
//       - {name: phi2, angle: [coupler.P, coupler.Q], clockwise: true, zero: 90 deg}
//       - {name: s, slide: guide, from: ground.O}                  # along the joint's axis
//     symbols:
//       - {name: l1, length: [crank.O, crank.P]}
//       - {name: d, dx: [ground.O, ground.G]}                      # also dy
//       - {name: alpha, angle: [[lever.O2, lever.Q], [lever.O2, lever.R]]}
//     independent: phi1                                          # optional
#include <gearkit/io/yaml_model.hpp>
#include <gearkit/sym/loop_equations.hpp>

#include <string>

namespace gearkit::sym {

/// Reads the section. Points are written link.point (ground.O for the frame).
/// @throws io::InputError with file:line:column for unknown keys, links, points or joints, a
///         slide on a joint that is not prismatic, a repeated or malformed name.
EquationsInput read_equations_input(const YAML::Node& section, const std::string& file, const kin::Model& model);

}  // namespace gearkit::sym
