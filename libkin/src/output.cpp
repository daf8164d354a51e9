#include <gearkit/kin/output.hpp>

#include <gearkit/kin/solve.hpp>

#include <array>
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

}  // namespace

OutputValue evaluate_output(const Model& model, const Data& data, const Output& output) {
  check_data(model, data);
  OutputValue v;
  switch (output.kind) {
    case OutputKind::point_x:
    case OutputKind::point_y: {
      const int c = output.kind == OutputKind::point_x ? 0 : 1;
      v.value = point_position(data, output.point)(c);
      v.rate = point_velocity(data, output.point)(c);
      v.acceleration = point_acceleration(data, output.point)(c);
      break;
    }
    case OutputKind::body_angle: {
      auto angle = [&](const Eigen::VectorXd& x, int body) { return body == kGround ? 0.0 : x(3 * body + 2); };
      v.value = angle(data.q, output.body) - angle(data.q, output.reference);
      v.rate = angle(data.qd, output.body) - angle(data.qd, output.reference);
      v.acceleration = angle(data.qdd, output.body) - angle(data.qdd, output.reference);
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
      if (output.point.body == kGround) return 0.0;
      const int k = 3 * output.point.body;
      const Eigen::Vector2d d = dq.segment<2>(k) + dq(k + 2) * perp(rotate(data.q(k + 2), output.point.local));
      return output.kind == OutputKind::point_x ? d.x() : d.y();
    }
    case OutputKind::body_angle: {
      auto angle = [&](int body) { return body == kGround ? 0.0 : dq(3 * body + 2); };
      return angle(output.body) - angle(output.reference);
    }
    case OutputKind::slider_displacement: {
      const Projection p = project(model, data, output);
      return dot_body(p.jacobian, 0, p.slider, dq) + dot_body(p.jacobian, 1, p.guide, dq);
    }
  }
  return 0.0;
}

}  // namespace gearkit::kin
