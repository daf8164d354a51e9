#pragma once
// Constraint equations of a planar mechanism in the generalised coordinates a course chooses
// (link angles phi_i measured as the course measures them, slider displacements s), written
// symbolically as the course writes them by hand: vector loop closure Phi(q) = 0, its Jacobian
// Phi_q, the velocity equations Phi_q q' = 0, the acceleration equations Phi_q q'' = gamma and
// the velocity ratios q_d'/q_i' = -(Phi_q^d)^-1 Phi_q^i. Symbols and simplification by GiNaC.
//
// Conventions: lengths in mm (as the course's figures), angles in rad. A loop is walked link by
// link; a prismatic joint whose displacement is not a coordinate is eliminated by projecting the
// loop on the normal of its axis (the course's "projection on the horizontal"). Expressions are
// given as text GiNaC's parser reads back ("-l1*cos(phi1)+d") and as LaTeX.
#include <gearkit/kin/joints.hpp>
#include <gearkit/kin/model.hpp>

#include <Eigen/Dense>

#include <memory>
#include <string>
#include <vector>

namespace gearkit::sym {

/// phi = sense * (direction of the segment from -> to, both points of one body) - zero.
/// zero = 0 measures from +x, pi/2 from the vertical; sense +1 counter-clockwise, -1 clockwise.
struct AngleCoordinate {
  kin::BodyPoint from, to;  ///< same body, distinct points [m]
  double zero = 0.0;        ///< [rad]
  int sense = +1;
};

/// s = sign * u . (P - O): the slider point P of prismatic joint `joint` (index in
/// Model::constraints()) measured along the joint's axis u from `origin`, a point of the guide body.
struct DisplacementCoordinate {
  int joint = 0;
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< guide body's local frame [m]
  int sign = +1;
};

struct Coordinate {
  std::string name;  ///< a GiNaC symbol name: letters and digits, e.g. phi1, s, x
  std::string tex;   ///< LaTeX, e.g. \varphi_{1}; empty: derived from the name
  bool is_angle = true;
  AngleCoordinate angle;
  DisplacementCoordinate displacement;
};

/// A dimension written as a symbol instead of its value.
struct Symbol {
  enum class Kind {
    length,  ///< distance between a and b (same body)
    dx,      ///< x component of b - a (ground or a translating body), mm
    dy,      ///< y component of b - a
    angle,   ///< angle from segment a->b to segment c->d (same body), rad
  };
  std::string name, tex;
  Kind kind = Kind::length;
  kin::BodyPoint a, b, c, d;
};

struct EquationsInput {
  std::vector<Coordinate> coordinates;
  std::vector<Symbol> symbols;
  /// Coordinates taken as independent for the velocity ratios (indices into coordinates);
  /// empty: chosen from the model's drivers, else the first ones.
  std::vector<int> independent;
};

/// One expression, as text (GiNaC syntax) and LaTeX.
struct Expression {
  std::string text, latex;
};

/// A velocity ratio q_d' / q_i' as a formula (dof 1).
struct VelocityRatio {
  int dependent = 0, independent = 0;  ///< coordinate indices
  Expression formula;
};

class SymbolicSystem;  // GiNaC expressions, private to the library

struct Equations {
  std::vector<std::string> loops;       ///< each loop used, "O1 - P - Q - O2 - O1 (x, y)"
  std::vector<Expression> phi;          ///< m rows, Phi(q) = 0
  std::vector<std::vector<Expression>> phi_q;  ///< m x n
  std::vector<Expression> velocity;     ///< row i of Phi_q q' (= 0)
  std::vector<Expression> gamma;        ///< Phi_q q'' = gamma
  std::vector<VelocityRatio> ratios;    ///< for dof 1
  std::vector<int> independent;         ///< coordinate indices used for the ratios
  std::vector<std::pair<std::string, double>> symbol_values;  ///< name, value (mm or rad)
  std::shared_ptr<const SymbolicSystem> system;
};

/// The coordinates' values at a pose of the model, lengths in mm, angles in rad.
struct CoordinateState {
  Eigen::VectorXd q, qd, qdd;
};

/// Writes the constraint equations of `model` in the coordinates of `input`, choosing loops
/// of the joint graph (revolute, prismatic, pin-in-slot) whose links all have their angle
/// given by a coordinate or fixed; rows are kept while they are independent at `pose`.
/// @param pose body coordinates (x, y, theta per body, SI) of an assembled position; it fixes
///        the constant angles between links joined by prismatic joints and the rank test.
/// @param dof the mechanism's mobility: the system stops at n - dof rows.
/// @throws std::invalid_argument if a coordinate is malformed (points of different bodies,
///         coincident points, a joint that is not prismatic), a name repeats or is not a valid
///         symbol name, or the model has more than 60 links or 80 joints (the loop search is
///         exponential in the worst case).
Equations loop_equations(const kin::Model& model, const EquationsInput& input, const Eigen::VectorXd& pose, int dof);

/// The user coordinates at a pose: q from the body coordinates, qd and qdd from the body
/// velocities and accelerations (SI body coordinates in, mm and rad out).
CoordinateState coordinate_state(const kin::Model& model, const EquationsInput& input, const Eigen::VectorXd& q,
                                 const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd);

/// Numbers of Equations at a state: Phi (m), Phi_q (m x n), gamma (m), ratios (NaN where
/// Phi_q^d is singular there).
struct Evaluated {
  Eigen::VectorXd phi, gamma, ratios;
  Eigen::MatrixXd phi_q;
};
Evaluated evaluate(const Equations& equations, const CoordinateState& state);

}  // namespace gearkit::sym
