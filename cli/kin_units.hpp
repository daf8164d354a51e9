#pragma once
// `gearkit kin`: how the solver's SI values are shown. Inputs and outputs in deg (angles) or mm
// (lengths), velocity ratios per unit of the input as shown.
#include <gearkit/kin/output.hpp>
#include <gearkit/mechanism/reader.hpp>

#include <cmath>
#include <numbers>
#include <string>

namespace gearkit::cli {

inline constexpr double kRadToDeg = 180.0 / std::numbers::pi;

inline bool angular(const mechanism::Mechanism& mech, int driver) {
  return mech.drivers[static_cast<std::size_t>(driver)].quantity == kin::DriverQuantity::angle;
}
inline double shown_input(const mechanism::Mechanism& mech, int driver, double v) {
  return angular(mech, driver) ? v * kRadToDeg : v * 1000.0;
}
inline std::string input_unit(const mechanism::Mechanism& mech, int driver) { return angular(mech, driver) ? "deg" : "mm"; }
inline std::string input_key(const mechanism::Mechanism& mech, int driver) { return "input_" + input_unit(mech, driver); }

inline double shown_output(const kin::Output& o, double v) { return o.angular() ? v * kRadToDeg : v * 1000.0; }
inline std::string output_unit(const kin::Output& o) { return kin::output_units(o).value; }

/// Velocity ratios are shown per rad or per mm of input, in rad or mm of output.
inline std::string ratio_unit(const mechanism::Mechanism& mech, int driver, const kin::Output& o) {
  const bool in_angle = angular(mech, driver);
  if (o.angular()) return in_angle ? "-" : "rad/mm";
  return in_angle ? "mm/rad" : "-";
}
/// A ratio d(output)/d(input) in SI converted to the units of ratio_unit().
inline double shown_ratio(const mechanism::Mechanism& mech, int driver, const kin::Output& o, double ratio) {
  return ratio * (o.angular() ? 1.0 : 1000.0) / (angular(mech, driver) ? 1.0 : 1000.0);
}

inline std::string effort_key(const mechanism::Mechanism& mech, int driver) {
  return angular(mech, driver) ? "driving_torque_Nm" : "driving_force_N";
}

}  // namespace gearkit::cli
