#include <gearkit/kin/output.hpp>

#include <gearkit/kin/solve.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace gearkit::kin {

namespace {

BodyState state_of(const Data& data, int body) {
  BodyState s;
  if (body == kGround) return s;
  const int k = 3 * body;
  s.r = data.q.segment<2>(k);
  s.set_theta(data.q(k + 2));
  s.r_dot = data.qd.segment<2>(k);
  s.omega = data.qd(k + 2);
  return s;
}

const Prismatic& prismatic_of(const Model& model, const Output& output) {
  const auto* p = output.constraint >= 0 && output.constraint < static_cast<int>(model.constraints().size())
                      ? dynamic_cast<const Prismatic*>(model.constraints()[static_cast<std::size_t>(output.constraint)].constraint.get())
                      : nullptr;
  if (!p) throw std::invalid_argument("output '" + output.name + "' does not name a prismatic joint");
  return *p;
}

// The slider displacement as one projection row: value, its 6 Jacobian entries and gamma.
struct Projection {
  double value = 0.0, gamma = 0.0;
  Eigen::Matrix<double, 1, 6> jacobian;
  int slider = kGround, guide = kGround;
};

Projection project(const Model& model, const Data& data, const Output& output) {
  const Prismatic& p = prismatic_of(model, output);
  const std::array<BodyState, 2> states{state_of(data, p.slider().body), state_of(data, p.guide().body)};
  Eigen::VectorXd phi(1), phi_t(1), gamma(1);
  Eigen::MatrixXd jac(1, 6);
  ConstraintOutput out{phi, jac, phi_t, gamma};
  projection_row(ConstraintInput{states, data.t, 0.0}, p.slider().local, p.guide().local, p.axis_local(), 0, out);
  Projection r;
  r.value = phi(0);
  r.gamma = gamma(0);
  r.jacobian = jac;
  r.slider = p.slider().body;
  r.guide = p.guide().body;
  return r;
}

double dot_body(const Eigen::Matrix<double, 1, 6>& jac, int slot, int body, const Eigen::VectorXd& v) {
  if (body == kGround) return 0.0;
  return jac.segment<3>(3 * slot).dot(v.segment<3>(3 * body));
}

// The point's value, rate and acceleration minus those of `from` (when given).
struct PointMotion {
  Eigen::Vector2d r, v, a;
};
PointMotion relative_motion(const Data& data, const Output& output) {
  PointMotion m{point_position(data, output.point), point_velocity(data, output.point), point_acceleration(data, output.point)};
  if (output.from) {
    m.r -= point_position(data, *output.from);
    m.v -= point_velocity(data, *output.from);
    m.a -= point_acceleration(data, *output.from);
  }
  return m;
}

// dP/d(input) of a body point for the coordinate change dq.
Eigen::Vector2d point_derivative(const Data& data, const BodyPoint& p, const Eigen::VectorXd& dq) {
  if (p.body == kGround) return Eigen::Vector2d::Zero();
  const int k = 3 * p.body;
  return dq.segment<2>(k) + dq(k + 2) * perp(rotate(data.q(k + 2), p.local));
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

OutputUnits output_units(const Output& output) {
  switch (output.kind) {
    case OutputKind::body_angle: return {"deg", "rad_s", "rad_s2"};
    case OutputKind::point_speed: return {"mm_s", "mm_s2", ""};
    case OutputKind::point_acceleration: return {"mm_s2", "", ""};
    default: return {"mm", "mm_s", "mm_s2"};
  }
}

OutputValue evaluate_output(const Model& model, const Data& data, const Output& output) {
  check_data(model, data);
  OutputValue v;
  switch (output.kind) {
    case OutputKind::point_x:
    case OutputKind::point_y: {
      const int c = output.kind == OutputKind::point_x ? 0 : 1;
      const PointMotion m = relative_motion(data, output);
      v.value = m.r(c);
      v.rate = m.v(c);
      v.acceleration = m.a(c);
      break;
    }
    case OutputKind::point_speed: {
      const Eigen::Vector2d vel = point_velocity(data, output.point);
      v.value = vel.norm();
      // d|v|/dt = v.a/|v| (the tangential acceleration); undefined where the point stops.
      v.rate = v.value > 0.0 ? vel.dot(point_acceleration(data, output.point)) / v.value : kNaN;
      v.acceleration = kNaN;
      break;
    }
    case OutputKind::point_acceleration:
      v.value = point_acceleration(data, output.point).norm();
      v.rate = v.acceleration = kNaN;
      break;
    case OutputKind::body_angle: {
      auto angle = [&](const Eigen::VectorXd& x, int body) { return body == kGround ? 0.0 : x(3 * body + 2); };
      const double s = output.sense;
      v.value = s * (angle(data.q, output.body) - angle(data.q, output.reference) + output.offset - output.zero);
      v.rate = s * (angle(data.qd, output.body) - angle(data.qd, output.reference));
      v.acceleration = s * (angle(data.qdd, output.body) - angle(data.qdd, output.reference));
      break;
    }
    case OutputKind::slider_displacement: {
      const Projection p = project(model, data, output);
      v.value = p.value;
      v.rate = dot_body(p.jacobian, 0, p.slider, data.qd) + dot_body(p.jacobian, 1, p.guide, data.qd);
      v.acceleration = dot_body(p.jacobian, 0, p.slider, data.qdd) + dot_body(p.jacobian, 1, p.guide, data.qdd) - p.gamma;
      break;
    }
  }
  return v;
}

double output_derivative(const Model& model, const Data& data, const Output& output, const Eigen::VectorXd& dq) {
  check_data(model, data);
  switch (output.kind) {
    case OutputKind::point_x:
    case OutputKind::point_y: {
      Eigen::Vector2d d = point_derivative(data, output.point, dq);
      if (output.from) d -= point_derivative(data, *output.from, dq);
      return output.kind == OutputKind::point_x ? d.x() : d.y();
    }
    case OutputKind::point_speed: return point_derivative(data, output.point, dq).norm();
    case OutputKind::point_acceleration: return kNaN;
    case OutputKind::body_angle: {
      auto angle = [&](int body) { return body == kGround ? 0.0 : dq(3 * body + 2); };
      return output.sense * (angle(output.body) - angle(output.reference));
    }
    case OutputKind::slider_displacement: {
      const Projection p = project(model, data, output);
      return dot_body(p.jacobian, 0, p.slider, dq) + dot_body(p.jacobian, 1, p.guide, dq);
    }
  }
  return 0.0;
}

}  // namespace gearkit::kin
