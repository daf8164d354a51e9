#pragma once
// Element types of mechanism files: how a `type: gear_mesh` entry becomes a constraint. An
// element type pairs a name with a read function, which turns the entry's keys into the
// element's typed parameters and builds the constraint with the element's C++ builder (for the
// shipped types, gearkit/elements/*.hpp). Plugins register element types through
// PluginRegistrar::add_element_type, defined here.
//
// The read function sees the entry as an io::MapReader: a key/value view with the source
// position of every value, typed accessors with units, and unknown-key rejection; no YAML type
// reaches the solver. A builder's kin::ElementError is reported at the key its field names.
#include <gearkit/io/yaml_model.hpp>
#include <gearkit/kin/constraint.hpp>
#include <gearkit/kin/element.hpp>
#include <gearkit/kin/model.hpp>
#include <gearkit/plugin/plugin.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

namespace gearkit::mechanism {

/// What an element type's read function works with: the entry's keys (`type` and `name` are
/// already read) and the model read so far, to resolve link and point names.
class ElementReader {
 public:
  ElementReader(io::MapReader& keys, const kin::Model& model) : keys_(keys), model_(model) {}

  io::MapReader& keys() { return keys_; }
  const kin::Model& model() const { return model_; }
  /// The body index of the link named at `key` (kin::kGround for "ground").
  /// @throws io::InputError at the key if it is missing or names no link.
  int link(const std::string& key);
  /// The same, or `default_body` when the entry has no `key`.
  int link_or(const std::string& key, int default_body);
  /// The point "link.point" named at `key`: its body and local coordinates [m].
  /// @throws io::InputError at the key if it is missing or names no point.
  kin::BodyPoint point(const std::string& key);

 private:
  io::MapReader& keys_;
  const kin::Model& model_;
};

/// Reads one element and builds its constraint. Bad input throws io::InputError (at a key of
/// the entry); a kin::ElementError from the builder is placed by the mechanism reader.
using ElementReadFunction = std::function<std::unique_ptr<kin::Constraint>(ElementReader& reader)>;

struct ElementTypeSpec {
  std::string name;          ///< the `type:` word in a mechanism file, e.g. "gear_mesh"
  std::string summary;       ///< one line for `gearkit plugins`
  ElementReadFunction read;  ///< not null
};

/// Finds the element type registered for a `type:` word (nullptr if none).
using ElementTypeLookup = std::function<const ElementTypeSpec*(std::string_view type)>;

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Winvalid-offsetof"
/// The layout of what crosses the boundary for element types, as the including compiler sees
/// it: what a read function receives and what the constraints it builds exchange with the
/// solver.
inline constexpr std::uint64_t kElementAbi = plugin::abi::fingerprint({
    plugin::kApiVersion, sizeof(ElementTypeSpec), offsetof(ElementTypeSpec, summary), offsetof(ElementTypeSpec, read),
    sizeof(ElementReadFunction), sizeof(ElementReader), sizeof(io::MapReader), sizeof(io::SourceMark),
    sizeof(kin::Model), sizeof(kin::Body), sizeof(kin::ModelConstraint), sizeof(kin::BodyPoint),
    offsetof(kin::BodyPoint, local), sizeof(kin::BodyState), offsetof(kin::BodyState, theta),
    offsetof(kin::BodyState, r_dot), offsetof(kin::BodyState, omega), offsetof(kin::BodyState, cos_theta),
    sizeof(kin::ConstraintInput), offsetof(kin::ConstraintInput, t), offsetof(kin::ConstraintInput, input),
    sizeof(kin::ConstraintOutput), offsetof(kin::ConstraintOutput, phi_q), offsetof(kin::ConstraintOutput, gamma),
    sizeof(kin::Reaction), offsetof(kin::Reaction, moment), offsetof(kin::Reaction, at), offsetof(kin::Reaction, values),
    sizeof(kin::ReactionValue), offsetof(kin::ReactionValue, value), sizeof(kin::Constraint),
    sizeof(kin::ElementError), sizeof(kin::ConstraintDrawing), offsetof(kin::ConstraintDrawing, central),
    offsetof(kin::ConstraintDrawing, arm), sizeof(kin::ConstraintDrawing::Cam),
    offsetof(kin::ConstraintDrawing::Cam, roller_radius), offsetof(kin::ConstraintDrawing::Cam, face),
    sizeof(kin::ConstraintDrawing::Cam::Face), sizeof(kin::ConstraintDrawing::Wheel)});
#pragma GCC diagnostic pop

}  // namespace gearkit::mechanism

/// Registers an element type, with the element ABI of the including plugin's build.
inline void gearkit::plugin::PluginRegistrar::add_element_type(mechanism::ElementTypeSpec element) {
  add_element_type_built_with(mechanism::kElementAbi, element);
}
