#pragma once
// The one-coordinate equation of motion of a machine reduced to a shaft,
//   I(theta) theta'' + 1/2 I'(theta) theta'^2 = T_drive(theta, theta') - T_resist(theta, theta'),
// integrated with Boost.Odeint (runge_kutta_dopri5 with dense output), from rest or from a
// given state: start-up, speed against time and angle, steady state.
// SI units: s, rad, rad/s, rad/s^2, kg*m^2, N*m.
#include <functional>
#include <optional>
#include <vector>

namespace gearkit::dyn {

/// theta'' as a function of (t, theta, theta').
using AccelerationLaw = std::function<double(double t, double theta, double omega)>;

/// A machine reduced to one coordinate.
struct ReducedSystem {
  std::function<double(double theta)> inertia;             ///< I(theta), kg*m^2, > 0
  std::function<double(double theta)> inertia_derivative;  ///< dI/dtheta, kg*m^2/rad; empty = 0
  std::function<double(double theta, double omega)> drive_torque;      ///< N*m; empty = 0
  std::function<double(double theta, double omega)> resisting_torque; ///< N*m; empty = 0
};

/// theta'' = (T_drive - T_resist - 1/2 I' theta'^2) / I. The law throws std::domain_error
/// (naming theta) when I(theta) is not positive and finite.
AccelerationLaw acceleration_law(ReducedSystem system);

struct MotionOptions {
  double t_end = 10;             ///< s, integration stops here at the latest (> 0)
  double output_step = 0;        ///< s between samples; 0 = t_end / 2000
  double abs_tolerance = 1e-10;  ///< Odeint error control, on theta [rad] and omega [rad/s]
  double rel_tolerance = 1e-10;
  /// s, largest step (0 = output_step). The speed extremes of a cycle are located once per
  /// step, so keep it well below the time of one cycle when cycle_max/min_speed matter.
  double max_step = 0;
  /// Angle of one cycle, rad (> 0). The speed is averaged over each cycle; the motion is steady
  /// once the last change of the cycle mean and the change still to come (extrapolated from the
  /// last two changes as a geometric series; a change that does not decay counts as a thousand
  /// more) are both below steady_tolerance relative to the mean, and the integration then stops.
  /// 0 = one turn (2 pi).
  double cycle = 0;
  double steady_tolerance = 1e-6;
  bool stop_when_steady = true;
  /// Largest number of integration steps plus completed cycles: a bound on the work and memory
  /// of one call, so that a long t_end over a fast cycle cannot run for hours. The result says
  /// when it was reached. The shipped machines need 2,000 to 3,200 steps; a step costs up to
  /// about 10 us (a drive line whose motor speed is found by root bracketing), so the default
  /// keeps the worst case near 2 s.
  long max_steps = 200'000;
};

struct MotionSample {
  double t = 0, theta = 0, omega = 0, alpha = 0;
};

struct MotionResult {
  std::vector<MotionSample> samples;     ///< at output_step, plus the final state
  bool cannot_start = false;             ///< started at rest and the acceleration was <= 0
  bool stalled = false;                  ///< the speed fell back to 0 after starting
  double stall_time = 0;                 ///< s
  bool step_limit_reached = false;       ///< stopped by options.max_steps before t_end
  bool steady = false;                   ///< the steady criterion was met before t_end
  double steady_time = 0;                ///< s, end of the cycle that met it
  std::vector<double> cycle_end_times;   ///< s, each time theta completed a cycle
  std::vector<double> cycle_mean_speed;  ///< rad/s, mean speed of each completed cycle
  std::vector<double> cycle_max_speed;   ///< rad/s, largest speed seen in each cycle
  std::vector<double> cycle_min_speed;   ///< rad/s, smallest speed seen in each cycle
};

/// Integrates from (theta0, omega0) at t = 0.
/// When omega0 == 0 and the acceleration there is not positive, nothing moves: the result has
/// cannot_start set and the initial sample only. A speed that falls to 0 after starting stops
/// the integration (stalled), since a real machine would not run backwards under its loads.
/// @throws std::invalid_argument for bad options (t_end <= 0, negative steps or tolerances);
///         exceptions of the law (std::domain_error) pass through.
MotionResult integrate_motion(const AccelerationLaw& law, double theta0, double omega0, const MotionOptions& options);

/// First time the speed reaches `omega` (linear interpolation between samples), if it does.
std::optional<double> time_to_reach(const MotionResult& result, double omega);

}  // namespace gearkit::dyn
