#pragma once
// Built-in constraints: revolute, prismatic, pin in slot, and the drivers (an angle or a
// slider displacement prescribed as f(t) = f0 + speed*t + acceleration*t^2/2).
//
// Contracts shared by every class here. Body indices are kGround or indices of the Model's
// bodies; Model::add_constraint checks them, the constructors do not. Points are local [m];
// an axis_local is any non-zero vector in the guide's (slot's, line's) frame, normalised by the
// constructor (a zero axis gives NaN rows and a singular Jacobian, not an exception). The
// constructors throw nothing but std::bad_alloc, except Contact's (below). evaluate() never
// throws and never allocates; reaction() throws std::bad_alloc only (constraint.hpp).
// All lengths in m, angles in rad, local point coordinates in the body's frame.
#include <gearkit/kin/constraint.hpp>

namespace gearkit::kin {

/// Revolute (pin) joint: point a of one body coincides with point b of another. 2 equations:
/// Phi = r_a - r_b. The multiplier is the force [N] that body b exerts on body a, with the
/// sign convention F_on_a = -lambda; reaction() gives that force at the joint point (a pin).
class Revolute final : public Constraint {
 public:
  /// @param a, b  the coinciding points of two bodies, local [m]
  Revolute(BodyPoint a, BodyPoint b) : a_(a), b_(b) {}
  std::string kind() const override { return "revolute"; }
  int equations() const override { return 2; }
  std::vector<int> bodies() const override { return {a_.body, b_.body}; }
  void evaluate(const ConstraintInput& in, ConstraintOutput& out) const override;
  Reaction reaction(const ConstraintInput& in, std::span<const double> lambda) const override;
  const BodyPoint& a() const { return a_; }
  const BodyPoint& b() const { return b_; }

 private:
  BodyPoint a_, b_;
};

/// Prismatic joint: `slider` point P slides along the line through `guide` point Q of another
/// body, with the direction `axis_local` (a unit vector in the guide body's frame); the two
/// bodies keep the relative angle `relative_angle` [rad] = theta_slider - theta_guide.
/// 2 equations: theta_s - theta_g - relative_angle = 0 and n . (P - Q) = 0, n normal to the axis.
/// reaction(): the guide's normal force -lambda_2 n on the slider at P and its moment -lambda_1
/// about P.
class Prismatic final : public Constraint {
 public:
  /// @param slider, guide  P and Q, local [m]; @param axis_local  the guide's direction (guide
  /// frame, normalised here); @param relative_angle  theta_slider - theta_guide kept [rad]
  Prismatic(BodyPoint slider, BodyPoint guide, Eigen::Vector2d axis_local, double relative_angle);
  std::string kind() const override { return "prismatic"; }
  int equations() const override { return 2; }
  std::vector<int> bodies() const override { return {slider_.body, guide_.body}; }
  void evaluate(const ConstraintInput& in, ConstraintOutput& out) const override;
  Reaction reaction(const ConstraintInput& in, std::span<const double> lambda) const override;
  const BodyPoint& slider() const { return slider_; }
  const BodyPoint& guide() const { return guide_; }
  const Eigen::Vector2d& axis_local() const { return axis_; }

 private:
  BodyPoint slider_, guide_;
  Eigen::Vector2d axis_;
  double relative_angle_;
};

/// Pin in slot (the two-freedom half joint): point P of `pin` body stays on the line through
/// point Q of `slot` body with direction `axis_local` (slot body's frame). 1 equation.
/// reaction(): the slot's normal force -lambda n on the pin at P (a pin: no moment).
class PinInSlot final : public Constraint {
 public:
  /// @param pin, slot  P and Q, local [m]; @param axis_local  the slot's direction (slot frame)
  PinInSlot(BodyPoint pin, BodyPoint slot, Eigen::Vector2d axis_local);
  std::string kind() const override { return "pin_in_slot"; }
  int equations() const override { return 1; }
  std::vector<int> bodies() const override { return {pin_.body, slot_.body}; }
  void evaluate(const ConstraintInput& in, ConstraintOutput& out) const override;
  Reaction reaction(const ConstraintInput& in, std::span<const double> lambda) const override;
  const BodyPoint& pin() const { return pin_; }
  const BodyPoint& slot() const { return slot_; }
  const Eigen::Vector2d& axis_local() const { return axis_; }

 private:
  BodyPoint pin_, slot_;
  Eigen::Vector2d axis_;
};

/// Contact of a circle with a line (a roller, a drum or an edge on a flat face): the circle of
/// radius `radius` [m] centred at point C of `circle` body touches the line through point Q of
/// `line` body with direction `axis_local` (line body's frame), from the side `side` (+1: the
/// side perp(axis) points to, -1 the other). 1 equation: side n.(C - Q) - radius = 0,
/// n = perp(axis). A radius of 0 is a point or an edge on the line. The contact is kept closed
/// (bilateral): the normal force N = -lambda pushes the circle away from the line when it is
/// positive; a negative N means the contact would open (kinetostatics warns).
/// reaction(): the normal force N side n on the circle body at the contact point C - side r n.
class Contact final : public Constraint {
 public:
  /// @param circle  the circle's centre C, local [m]; @param radius  [m], >= 0
  /// @param line  Q on the line, local [m]; @param axis_local  its direction (line frame)
  /// @param side  +1 or -1, the side of the line the circle is on
  /// @throws std::invalid_argument if radius < 0 or side is not +1 or -1.
  Contact(BodyPoint circle, double radius, BodyPoint line, Eigen::Vector2d axis_local, int side);
  std::string kind() const override { return "contact"; }
  int equations() const override { return 1; }
  std::vector<int> bodies() const override { return {circle_.body, line_.body}; }
  void evaluate(const ConstraintInput& in, ConstraintOutput& out) const override;
  Reaction reaction(const ConstraintInput& in, std::span<const double> lambda) const override;
  const BodyPoint& circle() const { return circle_; }
  const BodyPoint& line() const { return line_; }
  const Eigen::Vector2d& axis_local() const { return axis_; }
  double radius() const { return radius_; }
  int side() const { return side_; }
  /// The contact point [m] and the unit normal (from the line towards the circle) in the ground
  /// frame for the states of the two bodies. Never throw.
  Eigen::Vector2d contact_point(const BodyState& circle, const BodyState& line) const;
  Eigen::Vector2d normal(const BodyState& line) const;

 private:
  BodyPoint circle_, line_;
  Eigen::Vector2d axis_;
  double radius_;
  int side_;
};

/// A prescribed motion f(t) = f0 + speed*t + acceleration*t^2/2, where f0 comes from the
/// analysis (ConstraintInput::input) so that one model can be solved at many input values.
struct Motion {
  double speed = 0.0;         ///< rad/s or m/s
  double acceleration = 0.0;  ///< rad/s^2 or m/s^2
};

/// Drives the angle of body `body` relative to body `reference`: theta_b - theta_ref - f(t) = 0.
/// The multiplier lambda gives the driving torque applied to `body` (reaction on `reference`):
/// T = -lambda [N m].
class AngleDriver final : public Constraint {
 public:
  /// @param body, reference  body indices (either may be kGround)
  /// @param motion  speed [rad/s] and acceleration [rad/s^2] of f(t); f0 is the analysis' input
  AngleDriver(int body, int reference, Motion motion) : body_(body), reference_(reference), motion_(motion) {}
  std::string kind() const override { return "angle_driver"; }
  int equations() const override { return 1; }
  std::vector<int> bodies() const override { return {body_, reference_}; }
  bool is_driver() const override { return true; }
  void evaluate(const ConstraintInput& in, ConstraintOutput& out) const override;
  const Motion& motion() const { return motion_; }

 private:
  int body_, reference_;
  Motion motion_;
};

/// Drives the displacement of a slider along a guide: u . (P - Q) - f(t) = 0, with u the axis
/// (guide body's frame) and P, Q as in Prismatic. The multiplier gives the driving force along
/// u applied to the slider: F = -lambda [N].
class DisplacementDriver final : public Constraint {
 public:
  /// @param slider, guide  P and Q, local [m]; @param axis_local  u (guide frame, normalised)
  /// @param motion  speed [m/s] and acceleration [m/s^2] of f(t)
  DisplacementDriver(BodyPoint slider, BodyPoint guide, Eigen::Vector2d axis_local, Motion motion);
  std::string kind() const override { return "displacement_driver"; }
  int equations() const override { return 1; }
  std::vector<int> bodies() const override { return {slider_.body, guide_.body}; }
  bool is_driver() const override { return true; }
  void evaluate(const ConstraintInput& in, ConstraintOutput& out) const override;
  const Motion& motion() const { return motion_; }

 private:
  BodyPoint slider_, guide_;
  Eigen::Vector2d axis_;
  Motion motion_;
};

/// One row v . (P - Q) of a projection constraint, where v = A(theta_guide) v_local, P is on body
/// 0 and Q on body 1 of the input. Writes phi (without any offset), the 6 Jacobian entries and
/// gamma into row `row` of `out`. Shared by prismatic, pin-in-slot, displacement drivers and
/// the cam follower element. Never throws, never allocates.
/// @param p_local, q_local  P and Q, local [m]; @param v_local  v in body 1's frame
/// @param row  the row of `out` written
void projection_row(const ConstraintInput& in, const Eigen::Vector2d& p_local, const Eigen::Vector2d& q_local,
                    const Eigen::Vector2d& v_local, int row, ConstraintOutput& out);

}  // namespace gearkit::kin
