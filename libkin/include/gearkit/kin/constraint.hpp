#pragma once
// The one interface every constraint of a planar mechanism implements, built in (revolute,
// prismatic, pin in slot, drivers) or contributed by a plugin (gear mesh, epicyclic train, cam
// follower).
//
// Coordinates. Every moving body i carries three absolute coordinates q_i = (x_i, y_i, theta_i):
// the position of its frame origin in the ground frame [m] and the angle of its local x axis
// [rad], counter-clockwise positive. A point with local coordinates s' (m) is at
//     r = r_i + A(theta_i) s'.
// Ground has index kGround and is never a coordinate.
//
// A constraint contributes m = equations() rows of the system
//     Phi(q, t) = 0,   Phi_q qd = -Phi_t,   Phi_q qdd = gamma,
// where gamma = -(Phi_q qd)_q qd - 2 Phi_qt qd - Phi_tt. It touches only the bodies listed by
// bodies(); its Jacobian block has 3 columns per listed body (x, y, theta), in that order.
// Columns of a kGround entry are ignored by the assembler.
#include <Eigen/Core>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace gearkit::kin {

/// The index used for the ground (fixed frame) wherever a body index is expected.
inline constexpr int kGround = -1;

/// A point of a body: the body index (or kGround) and its local coordinates [m].
struct BodyPoint {
  int body = kGround;
  Eigen::Vector2d local = Eigen::Vector2d::Zero();
};

/// Pose and velocity of one body, all SI: r [m], theta [rad], r_dot [m/s], omega [rad/s].
/// The cosine and sine of theta are kept with it because every joint on the body needs them:
/// the solver computes them once per body and evaluation. Change theta through set_theta().
struct BodyState {
  Eigen::Vector2d r = Eigen::Vector2d::Zero();
  double theta = 0.0;
  Eigen::Vector2d r_dot = Eigen::Vector2d::Zero();
  double omega = 0.0;
  double cos_theta = 1.0;  ///< cos(theta), kept by set_theta()
  double sin_theta = 0.0;  ///< sin(theta), kept by set_theta()

  /// Sets theta [rad] and its cached cosine and sine. Never throws.
  void set_theta(double angle) {
    theta = angle;
    cos_theta = std::cos(angle);
    sin_theta = std::sin(angle);
  }
  /// A(theta) s: the body-fixed vector s' [m] expressed in the ground frame [m]. Never throws.
  Eigen::Vector2d rotated(const Eigen::Vector2d& s) const {
    return {cos_theta * s.x() - sin_theta * s.y(), sin_theta * s.x() + cos_theta * s.y()};
  }
};

/// What a constraint is evaluated at.
struct ConstraintInput {
  std::span<const BodyState> bodies;  ///< one per entry of Constraint::bodies(); ground is all zero
  double t = 0.0;                     ///< time [s]
  double input = 0.0;                 ///< drivers only: the base value f0 of the driven coordinate
};

/// Where a constraint writes its rows. Sizes: equations() rows; phi_q has 3*bodies().size()
/// columns. The caller zeroes nothing: a constraint must write every entry of its rows.
struct ConstraintOutput {
  Eigen::Ref<Eigen::VectorXd> phi;
  Eigen::Ref<Eigen::MatrixXd> phi_q;
  Eigen::Ref<Eigen::VectorXd> phi_t;
  Eigen::Ref<Eigen::VectorXd> gamma;
};

/// One quantity a constraint reports with its reaction, e.g. a gear mesh's normal tooth force.
struct ReactionValue {
  std::string symbol;       ///< as in the standards and textbooks, e.g. "F_n", "T_2"
  std::string unit;         ///< SI: "N", "N m"
  double value = 0.0;       ///< [unit]
  std::string description;  ///< one line: "normal tooth force (ISO 6336-1)"
};

/// What a constraint transmits at a solved configuration, worked out from its multipliers.
struct Reaction {
  /// Force on the constraint's first body from the others [N], ground frame.
  Eigen::Vector2d force = Eigen::Vector2d::Zero();
  /// Moment on the first body [N m], counter-clockwise positive: about `at` when it is set,
  /// else about the body's frame origin.
  double moment = 0.0;
  /// Where `force` acts and `moment` is taken [m], ground frame, when the constraint joins its
  /// bodies at a point (revolute, pin in slot, prismatic).
  std::optional<Eigen::Vector2d> at;
  /// True when the constraint transmits only a force through `at`, never a moment (a pin): the
  /// kinetostatics then knows the line of the force (two-force members).
  bool pin = false;
  /// The quantities the element names (tooth forces, contact forces...), SI.
  std::vector<ReactionValue> values;
};

/// What an element shows in pictures beyond the points of its bodies (the animation of `gearkit
/// kin`): read-only geometry the solver never uses. Empty for the built-in joints, which the
/// pictures know by their type.
struct ConstraintDrawing {
  /// A cam on body `cam` touching a follower at `contact`: the roller centre (or knife tip) on the
  /// follower's body. The path of `contact` in the cam's frame is the pitch curve; the profile is
  /// its inner envelope offset by `roller_radius` [m] (0: a knife edge, profile = pitch curve).
  /// With `face`, the follower is flat-faced: its face is the line through `contact` along the
  /// unit vector `direction`, fixed in the frame of body `frame` (the guide's for a translating
  /// follower, the follower's for an oscillating one); the profile is the envelope of that line
  /// seen from the cam, and `roller_radius` is 0.
  struct Cam {
    struct Face {
      int frame = kGround;
      Eigen::Vector2d direction = Eigen::Vector2d::UnitX();
    };
    int cam = kGround;
    BodyPoint contact;
    double roller_radius = 0.0;
    std::optional<Face> face;
  };
  /// A member of a gear train turning about the train's central axis, with its number of teeth.
  struct Wheel {
    int body = kGround;
    int teeth = 0;
  };
  std::optional<Cam> cam;
  /// The central members of an epicyclic train (input first), coaxial; with `arm`, the carrier.
  std::vector<Wheel> central;
  std::optional<int> arm;
};

/// A set of scleronomic or rheonomic equations between the coordinates of a few bodies.
/// kin::testing::check_derivatives (testing.hpp) checks an implementation's Phi_q, Phi_t and
/// gamma against finite differences of its Phi; every built-in and plugin element passes it.
class Constraint {
 public:
  virtual ~Constraint();

  /// Short kind, e.g. "revolute", "gear_mesh", "angle_driver". @throws std::bad_alloc only.
  virtual std::string kind() const = 0;
  /// Number of equations (rows). Also what the constraint subtracts in the Gruebler-Kutzbach
  /// count (a revolute removes 2 freedoms, a pin in slot 1, a gear mesh 1). Must not throw.
  virtual int equations() const = 0;
  /// Bodies whose coordinates appear in the equations (kGround allowed); Model::add_constraint
  /// checks them. @throws std::bad_alloc only.
  virtual std::vector<int> bodies() const = 0;
  /// True for drivers (prescribed motions). Drivers are left out of the Gruebler count and of
  /// the rank test; their Lagrange multiplier is the driving force or torque.
  virtual bool is_driver() const { return false; }
  /// Evaluates the rows at `in`: Phi [m or rad per row], Phi_q [per m, per rad], Phi_t [per s]
  /// and gamma [per s^2], in the row's unit. Must not throw and must not allocate on the heap
  /// (the solver calls it at every Newton iteration).
  /// @param in  the states of bodies() in that order, the time [s] and a driver's input f0
  /// @param out  views of exactly equations() rows; every entry must be written
  virtual void evaluate(const ConstraintInput& in, ConstraintOutput& out) const = 0;
  /// The reaction for the multipliers `lambda` (one per equation) at the solved state `in`. The
  /// constraint applies the generalised forces -Phi_q^T lambda to its bodies. The default gives
  /// that force and moment (about the frame origin) on the first body and names no values;
  /// elements override it to report what an engineer reads (tooth force, contact force).
  /// May allocate; called once per reported position, not in the solver loops.
  /// @param in  the solved state, as for evaluate()
  /// @param lambda  the constraint's multipliers, equations() of them [N or N m per row unit]
  /// @throws std::bad_alloc only.
  virtual Reaction reaction(const ConstraintInput& in, std::span<const double> lambda) const;
  /// What pictures draw of the constraint beyond its bodies' points (cams, train members); the
  /// default is nothing. Plugin API 4. @throws std::bad_alloc only.
  virtual ConstraintDrawing drawing() const { return {}; }
};

// Small helpers shared by the built-in constraints and the plugins' elements.

/// A(theta) s: a body-fixed vector s' [m] expressed in the ground frame, theta [rad]. Never throws.
inline Eigen::Vector2d rotate(double theta, const Eigen::Vector2d& s) {
  const double c = std::cos(theta), si = std::sin(theta);
  return {c * s.x() - si * s.y(), si * s.x() + c * s.y()};
}

/// The vector v turned by +90 deg (the derivative of A(theta) s with respect to theta is
/// perp(A s)). Never throws.
inline Eigen::Vector2d perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }

/// z component of the planar cross product a x b [product of the units]. Never throws.
inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

}  // namespace gearkit::kin
