#pragma once
// Reduction of a one-degree-of-freedom mechanism to one coordinate by virtual power.
//
// At one instant, a force F applied at a point moving with velocity v, or a torque M on a body
// turning at omega, contributes F.v or M omega to the virtual power. The reduced force at a
// point A is the force along v_A with the same power, F_red = P / |v_A|; the reduced torque on a
// shaft turning at omega_ref is P / omega_ref (OTM 2015 problem 1 c).
//
// Over the cycle, the velocities are proportional to the coordinate's rate theta':
// v_G = k_G(theta) theta', omega_body = k_w(theta) theta' (velocity coefficients, what a
// kinematic solver's velocity analysis at theta' = 1 gives). Then
//   I(theta)  = sum m |k_G|^2 + J_G k_w^2            (kinetic energy 1/2 I theta'^2)
//   I'(theta) = 2 sum m k_G . dk_G/dtheta + J_G k_w dk_w/dtheta
//   T_weight  = sum m g . k_G                        (g pointing down: (0, -g))
// SI units: m, m/s, N, N*m, kg, kg*m^2, rad.
#include <functional>
#include <span>
#include <vector>

namespace gearkit::dyn {

struct Vec2 {
  double x = 0, y = 0;
};
double dot(Vec2 a, Vec2 b);
double norm(Vec2 a);

inline constexpr double standard_gravity = 9.80665;  ///< m/s^2 (ISO 80000-3)

/// A force and the velocity of its point of application at the same instant.
struct ForceAtPoint {
  Vec2 force;     ///< N
  Vec2 velocity;  ///< m/s
};

/// A torque on a body and the body's angular velocity (both counter-clockwise positive).
struct TorqueOnBody {
  double torque = 0;  ///< N*m
  double omega = 0;   ///< rad/s
};

/// sum F.v + sum M omega, W.
double virtual_power(std::span<const ForceAtPoint> forces, std::span<const TorqueOnBody> torques = {});

/// Force along v_A with the same power (N); negative when it opposes v_A.
/// @throws std::invalid_argument if |v_A| is 0 (a dead point: no finite reduced force).
double reduced_force(double power, Vec2 velocity_at_reduction_point);

/// Torque on a shaft turning at omega with the same power (N*m).
/// @throws std::invalid_argument if omega is 0.
double reduced_torque_at(double power, double omega);

/// d'Alembert inertia force -m a (N) of a body of mass m whose centre accelerates at a.
Vec2 inertia_force(double mass, Vec2 acceleration);

/// Weight (0, -m g), N.
Vec2 weight(double mass, double gravity = standard_gravity);

/// Mass and centroidal moment of inertia of one body.
struct BodyMass {
  double mass = 0;       ///< kg, >= 0
  double inertia_G = 0;  ///< kg*m^2 about the centre of mass, >= 0
};

/// Velocity coefficients of one body at one position, and their derivatives with respect to the
/// coordinate (zero for bodies in constant ratio, as in gear trains).
struct VelocityCoefficients {
  Vec2 k_G;            ///< v_G / theta', m/rad
  double k_omega = 0;  ///< omega / theta'
  Vec2 dk_G;           ///< d k_G / d theta, m/rad^2
  double dk_omega = 0; ///< d k_omega / d theta, 1/rad
};

/// Reduced inertia and its derivative, kg*m^2 and kg*m^2/rad.
/// @throws std::invalid_argument if the spans differ in size or a mass/inertia is negative.
double reduced_inertia(std::span<const BodyMass> bodies, std::span<const VelocityCoefficients> k);
double reduced_inertia_derivative(std::span<const BodyMass> bodies, std::span<const VelocityCoefficients> k);

/// Reduced torque of the weights, N*m (positive when gravity drives the coordinate forward).
double reduced_weight_torque(std::span<const BodyMass> bodies, std::span<const VelocityCoefficients> k,
                             double gravity = standard_gravity);

/// Reduced torque of a force F acting at a point whose velocity coefficient is k_P (F.k_P, N*m).
double reduced_torque_of_force(Vec2 force, Vec2 k_P);

/// Force of a linear spring (stiffness N/m, free length m) on its end P, the other end at Q:
/// -stiffness (|PQ| - free_length) along Q->P (pulls P towards Q when stretched).
/// @throws std::invalid_argument if P and Q coincide (no direction).
Vec2 spring_force_on(Vec2 p, Vec2 q, double stiffness, double free_length);

/// Reduced torque of a linear spring between points P and Q whose velocity coefficients are
/// k_P and k_Q: F_P . (k_P - k_Q), which is -dV/dtheta of its energy V = 1/2 k (L - L0)^2.
double reduced_spring_torque(Vec2 p, Vec2 q, Vec2 k_P, Vec2 k_Q, double stiffness, double free_length);

/// Reduced inertia of a mechanism tabulated over its coordinate, for the equation of motion.
/// Between the nodes it is the cubic Hermite interpolant of (I, dI/dtheta), and derivative()
/// is that interpolant's exact derivative, so that 1/2 I theta'^2 is consistent with the
/// 1/2 I' theta'^2 term (energy is conserved when no torque acts).
class InertiaTable {
 public:
  /// @param theta rad, strictly increasing; periodic tables repeat with period back - front
  /// @param inertia kg*m^2, > 0 at every node
  /// @param derivative kg*m^2/rad; empty = estimated by central differences (periodic) or
  ///        one-sided ones at the ends
  /// @throws std::invalid_argument if sizes differ, fewer than 3 nodes, theta not increasing,
  ///         an inertia not positive or a value not finite, or (periodic) I differs at the ends.
  InertiaTable(std::vector<double> theta, std::vector<double> inertia, std::vector<double> derivative,
               bool periodic);

  double inertia(double theta) const;
  double derivative(double theta) const;
  double min_inertia() const;  ///< smallest node value
  double max_inertia() const;  ///< largest node value
  /// Mean of the interpolant over the table range (exact: each cubic piece integrates to
  /// h (I0 + I1) / 2 + h^2 (I0' - I1') / 12).
  double mean_inertia() const;
  double period() const { return theta_.back() - theta_.front(); }
  const std::vector<double>& theta() const { return theta_; }

 private:
  std::size_t locate(double& theta) const;  ///< wraps theta, returns the interval index

  std::vector<double> theta_, inertia_, derivative_;
  bool periodic_;
};

/// Tabulates the reduced inertia of `bodies` whose velocity coefficients `coefficients(theta)`
/// gives (the hook for a kinematic solver), at n + 1 nodes over [theta0, theta1].
InertiaTable tabulate_inertia(std::span<const BodyMass> bodies,
                              const std::function<std::vector<VelocityCoefficients>(double)>& coefficients,
                              double theta0, double theta1, int n, bool periodic);

}  // namespace gearkit::dyn
