#pragma once
// What the typed element builders share (gearkit/elements/*.hpp and plugins' own elements): the
// error for impossible parameters. An element is a Constraint (constraint.hpp) built from a
// typed parameter struct by a C++ function; reading it from a mechanism file is the business of
// the reader layer (gearkit::mechanism), never of the solver.
#include <stdexcept>
#include <string>

namespace gearkit::kin {

/// Parameters that make no element: a body index out of range or repeated where bodies must
/// differ, a tooth number below 1, an angle outside its range... field() names the parameter
/// with the spelling of its key in mechanism files ("z1", "gear2", "pressure_angle"), so a reader
/// can point at the offending key.
class ElementError : public std::invalid_argument {
 public:
  /// @param field  the parameter's key in mechanism files ("z1")
  /// @param message  one line saying what was expected and what was found
  ElementError(std::string field, const std::string& message);
  ~ElementError() override;
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

}  // namespace gearkit::kin
