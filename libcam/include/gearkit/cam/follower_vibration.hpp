#pragma once
// A flexible follower train as one degree of freedom (Norton, Design of Machinery, 5th ed., sec.
// 15.1, fig. 15-1c; the model behind the polydyne idea of sec. 15.5): the follower's mass M sits
// on the return spring k and the damper c, and the cam drives it through the follower train's
// stiffness k_f,
//   M x'' + c x' + (k + k_f) x = k_f q(t) - F_0 - F_load,     contact force F = k_f (q - x),
// with q(t) the cam's motion (SI: m or rad, see follower_dynamics.hpp). The follower lags and
// overshoots the cam; after a rise it vibrates on through the dwell (residual vibration). How much
// depends on the law: a law whose acceleration jumps (simple harmonic, parabolic) excites the
// train far more than one whose acceleration and jerk start smoothly (cycloidal, 4-5-6-7).
#include <gearkit/cam/follower_dynamics.hpp>

#include <vector>

namespace gearkit::cam {

/// The steady (periodic) response over one turn at cam speed omega.
struct FlexibleResponse {
  double natural_frequency = 0;  ///< omega_n = sqrt((k + k_f) / M) [rad/s]
  double damping_ratio = 0;      ///< zeta = c / (2 sqrt((k + k_f) M))
  double static_ratio = 0;       ///< k_f / (k + k_f): the follower's static share of the cam's motion
  std::vector<double> theta;     ///< cam angles [rad]: `samples` evenly, plus the ends of the segments
  std::vector<double> x, v;      ///< follower mass position [m | rad] and velocity [per s]
  std::vector<double> force;     ///< k_f (q - x): the cam's generalised force on the follower [N | N m]
  bool periodic = true;          ///< false at an undamped resonance (no periodic response exists)
};

/// The periodic response, integrated exactly step by step (the forcing is a cubic Hermite
/// polynomial in time on each step, the homogeneous part the matrix exponential), so stiff
/// follower trains need no small steps. Requires train.stiffness > 0 and train.mass > 0.
FlexibleResponse flexible_response(const CamDesign& design, const FollowerTrain& train, double omega, int samples);

/// Residual vibration after a rise or return that ends in a dwell: the amplitude of the
/// follower's free vibration about its static position there, sqrt(e^2 + ((e' + zeta omega_n e) /
/// omega_d)^2) with e = x - x_static [m | rad].
struct ResidualVibration {
  std::size_t segment = 0;  ///< the rise or return
  double theta = 0;         ///< where it ends [rad]
  double amplitude = 0;     ///< [m | rad]
};
std::vector<ResidualVibration> residual_vibrations(const CamDesign& design, const FollowerTrain& train,
                                                   const FlexibleResponse& response);

/// The residual vibration amplitude [unit of lift] that one rise of `law`, lift L over beta
/// [rad] of cam at speed omega, leaves in a follower train at rest before it (natural frequency
/// omega_n [rad/s], damping ratio zeta, static ratio r = k_f / (k + k_f)). For comparing laws.
double residual_vibration_of_law(Law law, double lift, double beta, double omega, double omega_n, double zeta,
                                 double static_ratio);

}  // namespace gearkit::cam
