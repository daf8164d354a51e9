#pragma once
// Named outputs of an analysis: a point's x or y, a body's angle, a relative angle, a slider's
// displacement along its guide. Each gives its value, its time rate and acceleration, and its
// derivative with respect to the input (the velocity ratio), all SI.
#include <gearkit/kin/data.hpp>
#include <string>

namespace gearkit::kin {

enum class OutputKind {
  point_x,             ///< x of `point` [m]
  point_y,             ///< y of `point` [m]
  body_angle,          ///< theta of `body` minus theta of `reference` [rad]
  slider_displacement, ///< axis . (P - Q) of the prismatic joint `constraint` [m]
};

struct Output {
  std::string name;
  OutputKind kind = OutputKind::point_x;
  BodyPoint point;            ///< point_x / point_y
  int body = 0;               ///< body_angle
  int reference = kGround;    ///< body_angle
  int constraint = -1;        ///< slider_displacement: index of a Prismatic in the model

  bool angular() const { return kind == OutputKind::body_angle; }
};

struct OutputValue {
  double value = 0.0;         ///< [m or rad]
  double rate = 0.0;          ///< from data.qd [m/s or rad/s]
  double acceleration = 0.0;  ///< from data.qd, data.qdd [m/s^2 or rad/s^2]
};

/// Value, rate and acceleration at the current data.q, qd, qdd.
/// @throws std::invalid_argument if a slider_displacement output names no prismatic joint.
OutputValue evaluate_output(const Model& model, const Data& data, const Output& output);

/// d(output)/d(input) for the coordinate change dq of a unit input change (input_sensitivity).
double output_derivative(const Model& model, const Data& data, const Output& output, const Eigen::VectorXd& dq);

}  // namespace gearkit::kin
