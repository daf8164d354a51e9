#pragma once
// Mechanism model files (YAML) for the planar solver: ground points, links with named points
// and mass properties, joints, drivers, plugin elements, loads and named outputs. The format
// is documented in docs/kin.md. Bare numbers take mm for lengths and deg for angles.
#include <gearkit/io/yaml_model.hpp>
#include <gearkit/kin/element.hpp>
#include <gearkit/kin/model.hpp>
#include <gearkit/kin/output.hpp>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::io {

/// A driver's sweep range as written in the file: start, end, step in SI (rad or m).
struct DriverRange {
  double start = 0.0, end = 0.0, step = 0.0;
};

struct MechanismDriver {
  std::string name;
  kin::DriverQuantity quantity = kin::DriverQuantity::angle;
  std::optional<DriverRange> range;
};

struct Mechanism {
  std::string title;
  std::string file;
  kin::Model model;
  std::vector<MechanismDriver> drivers;  ///< in model.drivers() order
  std::vector<kin::Output> outputs;
};

/// Finds the element type a plugin registered for `type` (nullptr if none).
using ElementTypeLookup = std::function<const kin::ElementTypeSpec*(const std::string& type)>;

/// Reads a mechanism file.
/// @throws InputError with file:line:column for malformed YAML, unknown keys, bad quantities,
///         joints or drivers naming unknown links or points, duplicate names, an element type
///         no loaded plugin provides, or a model without links.
Mechanism load_mechanism(const std::string& path, const ElementTypeLookup& elements);
/// The same from an already loaded document.
Mechanism read_mechanism(const YamlDocument& document, const ElementTypeLookup& elements);

}  // namespace gearkit::io
