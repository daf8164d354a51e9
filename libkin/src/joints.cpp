#include <gearkit/kin/joints.hpp>

namespace gearkit::kin {

Constraint::~Constraint() = default;

void Revolute::evaluate(const ConstraintInput& in, ConstraintOutput& out) const {
  const BodyState& i = in.bodies[0];
  const BodyState& j = in.bodies[1];
  const Eigen::Vector2d si = rotate(i.theta, a_.local);
  const Eigen::Vector2d sj = rotate(j.theta, b_.local);
  out.phi = i.r + si - j.r - sj;
  out.phi_q.setZero();
  out.phi_q(0, 0) = 1.0;
  out.phi_q(1, 1) = 1.0;
  out.phi_q.col(2) = perp(si);
  out.phi_q(0, 3) = -1.0;
  out.phi_q(1, 4) = -1.0;
  out.phi_q.col(5) = -perp(sj);
  out.phi_t.setZero();
  // d2/dt2 (A s) = theta_dd perp(A s) - omega^2 A s: the omega^2 terms move to gamma.
  out.gamma = i.omega * i.omega * si - j.omega * j.omega * sj;
}

void projection_row(const ConstraintInput& in, const Eigen::Vector2d& p_local, const Eigen::Vector2d& q_local,
                    const Eigen::Vector2d& v_local, int row, ConstraintOutput& out) {
  const BodyState& j = in.bodies[0];  // carries P
  const BodyState& i = in.bodies[1];  // carries Q and the direction v
  const Eigen::Vector2d sj = rotate(j.theta, p_local);
  const Eigen::Vector2d si = rotate(i.theta, q_local);
  const Eigen::Vector2d n = rotate(i.theta, v_local);
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
  out.phi_q.row(0).setZero();
  out.phi_q(0, 2) = 1.0;
  out.phi_q(0, 5) = -1.0;
  out.phi_t(0) = 0.0;
  out.gamma(0) = 0.0;
  projection_row(in, slider_.local, guide_.local, perp(axis_), 1, out);
}

PinInSlot::PinInSlot(BodyPoint pin, BodyPoint slot, Eigen::Vector2d axis_local)
    : pin_(pin), slot_(slot), axis_(axis_local.normalized()) {}

void PinInSlot::evaluate(const ConstraintInput& in, ConstraintOutput& out) const {
  projection_row(in, pin_.local, slot_.local, perp(axis_), 0, out);
}

void AngleDriver::evaluate(const ConstraintInput& in, ConstraintOutput& out) const {
  const double t = in.t;
  out.phi(0) = in.bodies[0].theta - in.bodies[1].theta -
               (in.input + motion_.speed * t + 0.5 * motion_.acceleration * t * t);
  out.phi_q.setZero();
  out.phi_q(0, 2) = 1.0;
  out.phi_q(0, 5) = -1.0;
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
