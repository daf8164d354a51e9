#pragma once
// Element types that plugins contribute to the solver (gear mesh, epicyclic train, cam
// follower). The solver sees an element only through the constraint interface: its rows of
// Phi, Phi_q, Phi_t and gamma (see constraint.hpp). The element's own description in a
// mechanism file is read by the plugin that owns the type.
#include <gearkit/kin/joints.hpp>
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
  /// Index of a body by name (kGround for "ground"); throws gearkit::io::InputError for an
  /// unknown name.
  std::function<int(const std::string& body_name)> body_index;
  /// Resolves a "link.point" scalar node to the body and the point's local coordinates [m];
  /// throws gearkit::io::InputError (with the node's file:line:column) if either is unknown.
  std::function<BodyPoint(const YAML::Node& reference)> body_point;
  /// The drawn (initial guess) angle of a body [rad]; 0 for the ground. Elements whose
  /// equations hold up to a constant (a gear mesh's phase) take it from the drawing.
  std::function<double(int body)> angle_guess;
};

using ElementFactory = std::function<std::unique_ptr<Constraint>(const ElementRequest&)>;

struct ElementTypeSpec {
  std::string name;        ///< the `type:` word in a mechanism file, e.g. "gear_mesh"
  std::string summary;     ///< one line for `gearkit plugins`
  ElementFactory create;   ///< builds the element's constraint
};

}  // namespace gearkit::kin
