#pragma once
// Mechanism files (YAML) for the planar solver: ground points, links with named points and
// mass properties, joints, drivers, elements of the loaded plugins, loads and named outputs.
// The format is documented in docs/kin.md. Bare numbers take mm for lengths and deg for angles.
#include <gearkit/io/yaml_model.hpp>
#include <gearkit/mechanism/element_type.hpp>
#include <gearkit/mechanism/mechanism.hpp>

#include <string>
#include <vector>

namespace gearkit::mechanism {

/// The joint types mechanism files build in (`revolute`, `prismatic`, `pin_in_slot`): no plugin
/// may register an element type of these names.
const std::vector<std::string>& builtin_joint_types();

/// Reads a mechanism file. `elements` finds the element types of `elements:` entries (the
/// plugin host's find_element_type; nullptr or a lookup that finds nothing for none).
/// @throws io::InputError with file:line:column for malformed YAML, unknown keys, bad quantities,
///         joints or drivers naming unknown links or points, duplicate names, an element type
///         the lookup does not know, bad element keys or parameters (kin::ElementError, placed at
///         the key it names), or a model without links.
Mechanism load_mechanism(const std::string& path, const ElementTypeLookup& elements);
/// The same from an already loaded document.
Mechanism read_mechanism(const io::YamlDocument& document, const ElementTypeLookup& elements);

}  // namespace gearkit::mechanism
