#pragma once
// Quantities with units, as people type them in model files and options: "9 mm", "20 deg",
// "2950 rpm", "100 kW", "36.6 N*m", "0.1 kg*m^2". Parsing returns SI values checked against the
// dimension the field expects; a bare number takes the field's documented default unit.
//
// Grammar: NUMBER [UNIT], UNIT = FACTOR (('*' | '/') FACTOR)*, FACTOR = SYMBOL ['^' INTEGER].
// The number is a decimal with optional sign, fraction and exponent ("1.5e-3"); space between
// number and unit is optional ("9mm"). A decimal comma, hex, nan, inf and unknown symbols are
// rejected. Units are case-sensitive ("MM" is not a unit).
#include <boost/units/quantity.hpp>
#include <boost/units/systems/si.hpp>
#include <stdexcept>
#include <string>
#include <string_view>

namespace gearkit::io {

/// The physical quantity a field expects.
enum class Quantity {
  dimensionless,
  length,
  angle,
  time,
  mass,
  force,
  torque,
  energy,
  power,
  velocity,
  acceleration,
  angular_velocity,
  angular_acceleration,
  moment_of_inertia,
  stiffness,        ///< linear spring rate, N/m
  pressure,
  damping,              ///< viscous damping, N*s/m
  torsional_stiffness,  ///< torsion spring rate, N*m/rad
  torsional_damping,    ///< rotational viscous damping, N*m*s/rad
};

/// Human name of a quantity ("a length", "an angular velocity") for messages.
std::string_view describe(Quantity q);

/// Thrown for malformed or mismatched quantities. The message says what was expected and
/// what was found but not where: callers add the place (option or file:line:column).
class QuantityError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
  ~QuantityError() override;
};

/// The sizes a value of a quantity may have, in SI (docs/units.md, "Ranges"): 0 or between
/// `smallest` and `largest`. Bounds far beyond any machine keep every result finite.
struct MagnitudeRange {
  double smallest;
  double largest;
  std::string_view si_unit;  ///< "m", "rad/s"; empty for plain numbers
};
MagnitudeRange magnitude_range(Quantity q);

/// Parses `text` into the SI value of quantity `expected` (m, rad, s, kg, N, N*m, J, W, m/s,
/// m/s^2, rad/s, rad/s^2, kg*m^2, N/m, Pa; 1 for dimensionless).
/// @param default_unit unit symbol applied to a bare number (e.g. "mm", "deg"); must itself be
///        valid for `expected`. Empty means a bare number is already SI.
/// @throws QuantityError if the text is malformed, names an unknown unit, has the wrong
///         dimension (a length where an angle is expected), or its size is outside
///         magnitude_range(expected).
double parse_quantity_si(std::string_view text, Quantity expected, std::string_view default_unit);

/// As parse_quantity_si but without the check against magnitude_range (the value is still finite),
/// for a caller that checks a narrower range of its own first (io::quantity_option), so that the
/// message states that range. Anything else should call parse_quantity_si.
double parse_quantity_si_any_size(std::string_view text, Quantity expected, std::string_view default_unit);

/// The program's one rule for a bare number typed in an option (docs/cli.md, "Quantity options"):
/// true for the quantities whose unit is not obvious (power, torque, angular velocity, velocity:
/// `--power 7.5` was 7.5 W in one command and 7.5 kW in another), which an option takes only with
/// their unit. Model files keep their documented default units.
bool option_needs_unit(Quantity q);

/// Two accepted spellings of a quantity that option_needs_unit, for a message ("7.5kW, 7500 W");
/// empty for any other quantity.
std::string_view unit_examples(Quantity q);

/// As parse_quantity_si for the value of an option: a bare number of a quantity that
/// option_needs_unit is refused with "expected a power with its unit (7.5kW, 7500 W), found '7.5'";
/// any other bare number takes `default_unit`, which must be valid for `expected`. For a quantity
/// that needs its unit `default_unit` is not used. @throws QuantityError as parse_quantity_si.
double parse_option_quantity_si(std::string_view text, Quantity expected, std::string_view default_unit);

/// As parse_option_quantity_si without the check against magnitude_range (see
/// parse_quantity_si_any_size).
double parse_option_quantity_si_any_size(std::string_view text, Quantity expected, std::string_view default_unit);

/// The SI factor of a unit expression such as "mm", "rpm" or "kg*m^2", checked against
/// `expected`. @throws QuantityError as parse_quantity_si.
double unit_factor_si(std::string_view unit, Quantity expected);

// Typed front end on Boost.Units for code that wants dimensional safety at compile time:
// parse<Length>("9") is 0.009 m. Each type names its Quantity and the default unit of a bare number.
namespace si = boost::units::si;
using Length = boost::units::quantity<si::length>;
using Angle = boost::units::quantity<si::plane_angle>;
using AngularVelocity = boost::units::quantity<si::angular_velocity>;
using Power = boost::units::quantity<si::power>;
using Torque = boost::units::quantity<si::torque>;
using MomentOfInertia = boost::units::quantity<si::moment_of_inertia>;

template <class T>
struct QuantityTraits;  // kind: the Quantity of T; unit: the default unit of a bare number
#define GEARKIT_QUANTITY_TRAITS(Type, Kind, Unit)           \
  template <>                                             \
  struct QuantityTraits<Type> {                           \
    static constexpr Quantity kind = Quantity::Kind;      \
    static constexpr std::string_view unit = Unit;        \
  };
GEARKIT_QUANTITY_TRAITS(Length, length, "mm")
GEARKIT_QUANTITY_TRAITS(Angle, angle, "deg")
GEARKIT_QUANTITY_TRAITS(AngularVelocity, angular_velocity, "rpm")
GEARKIT_QUANTITY_TRAITS(Power, power, "W")
GEARKIT_QUANTITY_TRAITS(Torque, torque, "N*m")
GEARKIT_QUANTITY_TRAITS(MomentOfInertia, moment_of_inertia, "kg*m^2")
#undef GEARKIT_QUANTITY_TRAITS

/// `text` as a Boost.Units quantity T (Length, Angle, ...). @throws QuantityError as parse_quantity_si.
template <class T>
T parse(std::string_view text, std::string_view default_unit = QuantityTraits<T>::unit) {
  return T::from_value(parse_quantity_si(text, QuantityTraits<T>::kind, default_unit));
}

}  // namespace gearkit::io
