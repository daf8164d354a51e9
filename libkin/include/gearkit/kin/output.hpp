#pragma once
// Named outputs of an analysis: a point's x or y (from the ground origin or from another point),
// a body's angle (relative to another body, measured clockwise or from another zero, along a
// segment of the body), a slider's displacement along its guide, a point's speed or the
// magnitude of its acceleration. Each gives its value, its time rate and acceleration, and its
// derivative with respect to the input (the velocity ratio), all SI.
#include <gearkit/kin/data.hpp>
#include <optional>
#include <string>

namespace gearkit::kin {

enum class OutputKind {
  point_x,             ///< x of `point` [m]
  point_y,             ///< y of `point` [m]
  body_angle,          ///< theta of `body` minus theta of `reference` [rad]
  slider_displacement, ///< axis . (P - Q) of the prismatic joint `constraint` [m]
  point_speed,         ///< |v| of `point` [m/s]; rate d|v|/dt (tangential acceleration), no acceleration
  point_acceleration,  ///< |a| of `point` [m/s^2]; no rate, acceleration or ratio (NaN)
};

struct Output {
  std::string name;
  OutputKind kind = OutputKind::point_x;
  BodyPoint point;            ///< point_x / point_y / point_speed / point_acceleration
  int body = 0;               ///< body_angle
  int reference = kGround;    ///< body_angle
  int constraint = -1;        ///< slider_displacement: index of a Prismatic in the model
  /// point_x / point_y: the coordinate is measured from this point (any body) instead of the
  /// ground origin, still along the ground's axes.
  std::optional<BodyPoint> from = std::nullopt;
  /// body_angle = sense (theta_body - theta_reference + offset - zero): `offset` [rad] turns the
  /// body's x axis to the segment the angle is measured along, `zero` [rad] is the direction it
  /// is measured from (pi/2: from the vertical), sense -1 measures clockwise.
  double offset = 0.0;
  double zero = 0.0;
  int sense = 1;

  bool angular() const { return kind == OutputKind::body_angle; }
};

/// The unit suffixes reports use for an output's value, rate and acceleration (after converting
/// m to mm and rad to deg for values): angles deg, rad_s, rad_s2; lengths mm, mm_s, mm_s2;
/// speeds mm_s, mm_s2 and "" (no acceleration); accelerations mm_s2, "", "".
struct OutputUnits {
  const char* value;
  const char* rate;
  const char* acceleration;
};
/// Never throws (the suffixes are string literals).
OutputUnits output_units(const Output& output);

struct OutputValue {
  double value = 0.0;         ///< [m or rad]
  double rate = 0.0;          ///< from data.qd [m/s or rad/s]
  double acceleration = 0.0;  ///< from data.qd, data.qdd [m/s^2 or rad/s^2]
};

/// Value, rate and acceleration at the current data.q, qd, qdd.
/// @param output  its bodies, points [m] and constraint index must be the model's (not checked
///   but for the prismatic joint below)
/// @throws DataMismatch if `data` was not made for `model` as it is now; std::invalid_argument
///   if a slider_displacement output names no prismatic joint.
OutputValue evaluate_output(const Model& model, const Data& data, const Output& output);

/// d(output)/d(input) for the coordinate change dq of a unit input change (input_sensitivity).
/// For a point_speed it is |dP/d(input)|, the speed per unit input speed; NaN for a
/// point_acceleration.
/// @param dq  coordinates per unit input [m or rad per rad or m] (input_sensitivity)
/// @throws DataMismatch, std::invalid_argument as evaluate_output.
double output_derivative(const Model& model, const Data& data, const Output& output, const Eigen::VectorXd& dq);

}  // namespace gearkit::kin
