#include <gearkit/kin/joints.hpp>

#include <stdexcept>

namespace gearkit::kin {

Constraint::~Constraint() = default;

void Revolute::evaluate(const ConstraintInput& in, ConstraintOutput& out) const {
  const BodyState& i = in.bodies[0];
  const BodyState& j = in.bodies[1];
  const Eigen::Vector2d si = i.rotated(a_.local);
  const Eigen::Vector2d sj = j.rotated(b_.local);
  out.phi(0) = i.r.x() + si.x() - j.r.x() - sj.x();
  out.phi(1) = i.r.y() + si.y() - j.r.y() - sj.y();
  // Columns (x_i, y_i, theta_i, x_j, y_j, theta_j); d(A s)/d theta = perp(A s) = (-s_y, s_x).
  auto& J = out.phi_q;
  J(0, 0) = 1.0, J(1, 0) = 0.0;
  J(0, 1) = 0.0, J(1, 1) = 1.0;
  J(0, 2) = -si.y(), J(1, 2) = si.x();
  J(0, 3) = -1.0, J(1, 3) = 0.0;
  J(0, 4) = 0.0, J(1, 4) = -1.0;
  J(0, 5) = sj.y(), J(1, 5) = -sj.x();
  out.phi_t(0) = 0.0, out.phi_t(1) = 0.0;
  // d2/dt2 (A s) = theta_dd perp(A s) - omega^2 A s: the omega^2 terms move to gamma.
  const double wi2 = i.omega * i.omega, wj2 = j.omega * j.omega;
  out.gamma(0) = wi2 * si.x() - wj2 * sj.x();
  out.gamma(1) = wi2 * si.y() - wj2 * sj.y();
}

void projection_row(const ConstraintInput& in, const Eigen::Vector2d& p_local, const Eigen::Vector2d& q_local,
                    const Eigen::Vector2d& v_local, int row, ConstraintOutput& out) {
  const BodyState& j = in.bodies[0];  // carries P
  const BodyState& i = in.bodies[1];  // carries Q and the direction v
  const Eigen::Vector2d sj = j.rotated(p_local);
  const Eigen::Vector2d si = i.rotated(q_local);
  const Eigen::Vector2d n = i.rotated(v_local);
  const Eigen::Vector2d d = j.r + sj - i.r - si;
  const Eigen::Vector2d d_dot = j.r_dot + j.omega * perp(sj) - i.r_dot - i.omega * perp(si);
  out.phi(row) = n.dot(d);
  out.phi_q(row, 0) = n.x();
  out.phi_q(row, 1) = n.y();
  out.phi_q(row, 2) = n.dot(perp(sj));
  out.phi_q(row, 3) = -n.x();
  out.phi_q(row, 4) = -n.y();
  out.phi_q(row, 5) = perp(n).dot(d) - n.dot(perp(si));
  out.phi_t(row) = 0.0;
  // Second derivative of n.d without the qdd terms (those are Phi_q qdd):
  // -omega_i^2 n.d + 2 omega_i perp(n).d_dot + n.(omega_i^2 s_i - omega_j^2 s_j).
  const double rest = -i.omega * i.omega * n.dot(d) + 2.0 * i.omega * perp(n).dot(d_dot) +
                      n.dot(i.omega * i.omega * si - j.omega * j.omega * sj);
  out.gamma(row) = -rest;
}

Prismatic::Prismatic(BodyPoint slider, BodyPoint guide, Eigen::Vector2d axis_local, double relative_angle)
    : slider_(slider), guide_(guide), axis_(axis_local.normalized()), relative_angle_(relative_angle) {}

void Prismatic::evaluate(const ConstraintInput& in, ConstraintOutput& out) const {
  const BodyState& s = in.bodies[0];
  const BodyState& g = in.bodies[1];
  out.phi(0) = s.theta - g.theta - relative_angle_;
  auto& J = out.phi_q;
  J(0, 0) = 0.0, J(0, 1) = 0.0, J(0, 2) = 1.0;
  J(0, 3) = 0.0, J(0, 4) = 0.0, J(0, 5) = -1.0;
  out.phi_t(0) = 0.0;
  out.gamma(0) = 0.0;
  projection_row(in, slider_.local, guide_.local, perp(axis_), 1, out);
}

PinInSlot::PinInSlot(BodyPoint pin, BodyPoint slot, Eigen::Vector2d axis_local)
    : pin_(pin), slot_(slot), axis_(axis_local.normalized()) {}

void PinInSlot::evaluate(const ConstraintInput& in, ConstraintOutput& out) const {
  projection_row(in, pin_.local, slot_.local, perp(axis_), 0, out);
}

Contact::Contact(BodyPoint circle, double radius, BodyPoint line, Eigen::Vector2d axis_local, int side)
    : circle_(circle), line_(line), axis_(axis_local.normalized()), radius_(radius), side_(side) {
  if (!(radius >= 0.0)) throw std::invalid_argument("contact radius must be >= 0");
  if (side != 1 && side != -1) throw std::invalid_argument("contact side must be +1 or -1");
}

void Contact::evaluate(const ConstraintInput& in, ConstraintOutput& out) const {
  // side n.(C - Q) - r: the projection row with the normal turned to the circle's side.
  projection_row(in, circle_.local, line_.local, static_cast<double>(side_) * perp(axis_), 0, out);
  out.phi(0) -= radius_;
}

Eigen::Vector2d Contact::normal(const BodyState& line) const {
  return static_cast<double>(side_) * line.rotated(perp(axis_));
}

Eigen::Vector2d Contact::contact_point(const BodyState& circle, const BodyState& line) const {
  return circle.r + circle.rotated(circle_.local) - radius_ * normal(line);
}

void AngleDriver::evaluate(const ConstraintInput& in, ConstraintOutput& out) const {
  const double t = in.t;
  out.phi(0) = in.bodies[0].theta - in.bodies[1].theta -
               (in.input + motion_.speed * t + 0.5 * motion_.acceleration * t * t);
  auto& J = out.phi_q;
  J(0, 0) = 0.0, J(0, 1) = 0.0, J(0, 2) = 1.0;
  J(0, 3) = 0.0, J(0, 4) = 0.0, J(0, 5) = -1.0;
  out.phi_t(0) = -(motion_.speed + motion_.acceleration * t);
  out.gamma(0) = motion_.acceleration;
}

DisplacementDriver::DisplacementDriver(BodyPoint slider, BodyPoint guide, Eigen::Vector2d axis_local, Motion motion)
    : slider_(slider), guide_(guide), axis_(axis_local.normalized()), motion_(motion) {}

void DisplacementDriver::evaluate(const ConstraintInput& in, ConstraintOutput& out) const {
  projection_row(in, slider_.local, guide_.local, axis_, 0, out);
  const double t = in.t;
  out.phi(0) -= in.input + motion_.speed * t + 0.5 * motion_.acceleration * t * t;
  out.phi_t(0) = -(motion_.speed + motion_.acceleration * t);
  out.gamma(0) += motion_.acceleration;
}

}  // namespace gearkit::kin
