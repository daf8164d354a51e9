#pragma once
// Element types that plugins contribute to the solver (gear mesh, epicyclic train, cam
// follower). The solver sees an element only through the constraint interface: its rows of
// Phi, Phi_q, Phi_t and gamma (see constraint.hpp). The element's own description in a
// mechanism file is read by the plugin that owns the type.
#include <functional>
#include <memory>
#include <string>

namespace YAML {
class Node;
}

namespace gearkit::kin {

class Constraint;

/// What a plugin's element factory is given to build one element of a mechanism model.
struct ElementRequest {
  const YAML::Node& node;   ///< the element's mapping in the mechanism file
  const std::string& file;  ///< the file, for error marks
  /// Index of a body by name; throws gearkit::io::InputError for an unknown name.
  std::function<int(const std::string& body_name)> body_index;
};

using ElementFactory = std::function<std::unique_ptr<Constraint>(const ElementRequest&)>;

struct ElementTypeSpec {
  std::string name;        ///< the `type:` word in a mechanism file, e.g. "gear_mesh"
  std::string summary;     ///< one line for `gearkit plugins`
  ElementFactory create;   ///< builds the element's constraint
};

}  // namespace gearkit::kin
