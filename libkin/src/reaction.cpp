// Reactions of the built-in joints, and the generic one of any constraint: the generalised
// force -Phi_q^T lambda on the first body's coordinates (x, y, theta).
#include <gearkit/kin/joints.hpp>

#include <Eigen/Dense>

namespace gearkit::kin {

Reaction Constraint::reaction(const ConstraintInput& in, std::span<const double> lambda) const {
  const int m = equations();
  const int columns = 3 * static_cast<int>(in.bodies.size());
  Eigen::VectorXd phi(m), phi_t(m), gamma(m);
  Eigen::MatrixXd phi_q(m, columns);
  ConstraintOutput out{phi, phi_q, phi_t, gamma};
  evaluate(in, out);
  const Eigen::Map<const Eigen::VectorXd> l(lambda.data(), m);
  const Eigen::Vector3d q = -phi_q.leftCols<3>().transpose() * l;
  Reaction r;
  r.force = q.head<2>();
  r.moment = q(2);
  return r;
}

namespace {

// The ground-frame position of a body point from the body's state.
Eigen::Vector2d position(const BodyState& s, const Eigen::Vector2d& local) { return s.r + s.rotated(local); }

}  // namespace

Reaction Revolute::reaction(const ConstraintInput& in, std::span<const double> lambda) const {
  Reaction r;
  r.force = {-lambda[0], -lambda[1]};
  r.at = position(in.bodies[0], a_.local);
  r.pin = true;
  return r;
}

Reaction Prismatic::reaction(const ConstraintInput& in, std::span<const double> lambda) const {
  const Eigen::Vector2d n = in.bodies[1].rotated(perp(axis_));
  Reaction r;
  r.force = -lambda[1] * n;
  r.moment = -lambda[0];  // the theta row's multiplier is the moment about the slider point
  r.at = position(in.bodies[0], slider_.local);
  return r;
}

Reaction PinInSlot::reaction(const ConstraintInput& in, std::span<const double> lambda) const {
  Reaction r;
  r.force = -lambda[0] * in.bodies[1].rotated(perp(axis_));
  r.at = position(in.bodies[0], pin_.local);
  r.pin = true;
  return r;
}

Reaction Contact::reaction(const ConstraintInput& in, std::span<const double> lambda) const {
  // The row is side n.(C - Q) - r, so -lambda side n is the force on the circle: N = -lambda.
  Reaction r;
  r.force = -lambda[0] * normal(in.bodies[1]);
  r.at = contact_point(in.bodies[0], in.bodies[1]);
  r.pin = true;  // a force along the normal through the contact point, no moment
  return r;
}

}  // namespace gearkit::kin
