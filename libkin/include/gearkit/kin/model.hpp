#pragma once
// The immutable description of a planar mechanism (Pinocchio's Model): bodies with named
// points and mass properties, constraints (joints, drivers, plugin elements) and loads.
// Build it once with the add_* functions; every analysis takes it as `const Model&` and keeps
// its per-analysis state in a Data (data.hpp). All quantities SI: m, rad, kg, kg m^2, N, N m.
#include <gearkit/kin/constraint.hpp>
#include <gearkit/kin/joints.hpp>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace gearkit::kin {

/// A rigid link. Its frame is where its local point coordinates are measured from; the angle
/// of the body is the angle of its local x axis.
struct Body {
  std::string name;
  std::vector<std::pair<std::string, Eigen::Vector2d>> points;  ///< named points, local [m]
  double mass = 0.0;                                           ///< [kg]
  Eigen::Vector2d centre_of_mass = Eigen::Vector2d::Zero();    ///< local [m]
  double inertia = 0.0;                                        ///< about the centre of mass [kg m^2]
  /// Starting pose for the first position analysis (the drawn configuration; selects the
  /// assembly branch). position in [m], angle in [rad].
  Eigen::Vector2d position_guess = Eigen::Vector2d::Zero();
  double angle_guess = 0.0;

  /// Local coordinates [m] of a named point, or nullopt. Never throws.
  std::optional<Eigen::Vector2d> point(const std::string& point_name) const;
};

/// A constraint with its name (for messages and reaction tables) and first row in Phi.
struct ModelConstraint {
  std::string name;
  std::shared_ptr<const Constraint> constraint;
  int first_row = 0;
  std::vector<int> bodies;  ///< constraint->bodies(), kept: analyses per position need them often
};

/// The coordinate a driver prescribes.
enum class DriverQuantity { angle, displacement };

struct Driver {
  int constraint = 0;           ///< index in Model::constraints()
  DriverQuantity quantity = DriverQuantity::angle;
  double value = 0.0;           ///< default f0 [rad or m]
  /// The driving effort when it is given rather than computed (inverse kinetostatics): torque
  /// [N m] or force [N] along the driven coordinate. Each given effort determines the magnitude
  /// of one unknown load (PointForce::unknown, BodyTorque::unknown).
  std::optional<double> effort;
};

/// A force [N] (ground frame) applied at a point of a body.
struct PointForce {
  BodyPoint at;
  /// The force [N]; for an unknown load the unit vector of its direction.
  Eigen::Vector2d force = Eigen::Vector2d::Zero();
  std::string name;
  /// The magnitude along `force` is solved from the drivers' given efforts.
  bool unknown = false;
};

/// A torque [N m] (counter-clockwise positive) applied to a body.
struct BodyTorque {
  int body = 0;
  double torque = 0.0;  ///< [N m]; 1 for an unknown load (the solved value is the torque)
  std::string name;
  bool unknown = false;  ///< solved from the drivers' given efforts
};

/// Coulomb friction in a joint (kinetostatics only: positions and velocities are unaffected).
/// The friction opposes the relative sliding or turning in the joint, with the magnitude
/// mu |N| (prismatic, contact, pin in slot) or the couple rho |F| of the friction circle
/// rho = radius sin(atan mu) (revolute), where N and F are the joint's reactions.
struct JointFriction {
  int constraint = 0;   ///< index in Model::constraints(): a Revolute, Prismatic, PinInSlot or Contact
  double mu = 0.0;      ///< coefficient of friction, >= 0
  double radius = 0.0;  ///< revolute: journal (pin) radius [m], > 0
  /// prismatic: length [m] of the slider's bearing, centred on the slider point. When the
  /// joint's moment M exceeds N length/2 the slider bears on both faces of the guide and the
  /// friction is mu 2|M|/length; 0 ignores the moment (friction mu |N|).
  double length = 0.0;
};

/// A linear spring between two points: tension F = stiffness * (L - free_length) + preload
/// pulls the points together (negative F pushes them apart).
struct Spring {
  BodyPoint a, b;
  double stiffness = 0.0;    ///< [N/m]
  double free_length = 0.0;  ///< [m]
  double preload = 0.0;      ///< [N], tension at L = free_length
  std::string name;
};

class Model {
 public:
  /// Adds a moving body (points, centre of mass [m], mass [kg], inertia [kg m^2], drawn pose [m,
  /// rad]). @returns its index. @throws std::invalid_argument on a duplicate name.
  int add_body(Body body);
  /// Adds a constraint. Drivers are also listed in drivers(). @returns its index.
  /// @throws std::invalid_argument if it is null, names a body index out of range or its name
  ///   repeats.
  int add_constraint(std::string name, std::shared_ptr<const Constraint> constraint);
  /// Marks constraint `constraint` (a driver) with what it drives and its default value.
  /// @param constraint  index in constraints() of a driver; @param value  default f0 [rad or m]
  /// @throws std::invalid_argument if that constraint is no driver.
  void set_driver(int constraint, DriverQuantity quantity, double value);

  /// Adds Coulomb friction to a joint. @throws std::invalid_argument if the constraint is not a
  /// revolute, prismatic, pin in slot or contact, already has friction, mu < 0, or a revolute's
  /// radius is not > 0 or a length is < 0.
  void add_friction(JointFriction friction);
  /// Gives driver `driver` (index in drivers()) a known effort [N m or N].
  /// @throws std::invalid_argument if the index is out of range.
  void set_driver_effort(int driver, double effort);

  /// Loads and gravity: forces [N] at body points [m], torques [N m], springs [N/m, m, N],
  /// gravity [m/s^2]. Not checked against the bodies when added; free to change after a Data is
  /// made. @throws std::bad_alloc only.
  void add_force(PointForce f) { forces_.push_back(std::move(f)); }
  void add_torque(BodyTorque t) { torques_.push_back(std::move(t)); }
  void add_spring(Spring s) { springs_.push_back(std::move(s)); }
  void set_gravity(const Eigen::Vector2d& g) { gravity_ = g; }  ///< [m/s^2], e.g. (0, -9.81)

  /// The ground's named points (local = global).
  Body& ground() { return ground_; }
  const Body& ground() const { return ground_; }

  const std::vector<Body>& bodies() const { return bodies_; }
  const std::vector<ModelConstraint>& constraints() const { return constraints_; }
  const std::vector<Driver>& drivers() const { return drivers_; }
  const std::vector<PointForce>& forces() const { return forces_; }
  const std::vector<BodyTorque>& torques() const { return torques_; }
  const std::vector<Spring>& springs() const { return springs_; }
  const std::vector<JointFriction>& frictions() const { return frictions_; }
  const Eigen::Vector2d& gravity() const { return gravity_; }

  int coordinates() const { return 3 * static_cast<int>(bodies_.size()); }
  int equations() const { return equations_; }
  /// Index of a body by name; kGround for "ground"; nullopt if unknown. Never throws.
  /// (body_name: the name of kGround or of an index of bodies(); @throws std::out_of_range for
  /// any other index.)
  std::optional<int> body_index(const std::string& name) const;
  const std::string& body_name(int index) const;
  /// Index of a constraint by name, or nullopt. Never throws.
  std::optional<int> constraint_index(const std::string& name) const;
  /// Global position [m] of the body's points in the pose q (any vector of coordinates [m, rad]
  /// with the body's entries). Never throws.
  static Eigen::Vector2d point_position(const Eigen::VectorXd& q, const BodyPoint& p);
  /// True if there are masses, forces, torques or springs to analyse.
  bool has_loads() const;

  /// Counts the changes that size a Data: add_body, add_constraint and set_driver each add one.
  /// A Data remembers the revision it was made for; check_data() refuses it after a change.
  /// (Loads, gravity and the ground's points may change freely: nothing in Data depends on them.)
  std::uint64_t revision() const { return revision_; }

 private:
  Body ground_ = named_ground();
  static Body named_ground() {
    Body g;
    g.name = "ground";
    return g;
  }
  std::vector<Body> bodies_;
  std::vector<ModelConstraint> constraints_;
  std::unordered_map<std::string, int> body_by_name_;        // name lookups stay O(1) for
  std::unordered_map<std::string, int> constraint_by_name_;  // models of thousands of links
  std::vector<Driver> drivers_;
  std::vector<PointForce> forces_;
  std::vector<BodyTorque> torques_;
  std::vector<Spring> springs_;
  std::vector<JointFriction> frictions_;
  Eigen::Vector2d gravity_ = Eigen::Vector2d::Zero();
  int equations_ = 0;
  std::uint64_t revision_ = 0;
};

}  // namespace gearkit::kin
