#pragma once
// Energy and efficiency of a machine over one steady cycle at constant speed: a drive line
// (motor, stages) whose last shaft drives a load made of torques over the cycle angle and of
// energies taken once per cycle. The power demanded by the load at each instant crosses every
// stage with the efficiency taken in the direction it flows (see drive_line.hpp), so
//   E_electric = E_load+ / (eta_e-m prod eta) - E_load- * (eta_e-m prod eta)
// with E_load+ the energy the load absorbs and E_load- the energy it gives back.
// SI units: rad, rad/s, s, N*m, J, W.
#include <gearkit/dyn/curve.hpp>
#include <gearkit/dyn/drive_line.hpp>

#include <string>
#include <vector>

namespace gearkit::dyn {

/// A torque the load opposes over the cycle angle of the load shaft (positive = absorbs power).
struct LoadTorque {
  std::string name;
  PiecewiseLinear torque;  ///< N*m against the load shaft's angle, rad
  bool useful = false;     ///< counts as useful work for the overall efficiency
};

/// An energy the load takes once per cycle, not tied to an angle (e.g. a package brought to the
/// belt speed: m v^2, half kinetic energy and half slip loss).
struct LoadEnergy {
  std::string name;
  double energy = 0;  ///< J per cycle, >= 0
  bool useful = false;
};

/// A stretch of the cycle whose mean power is asked for (idle, working).
struct Phase {
  std::string name;
  double theta_from = 0, theta_to = 0;  ///< rad of the load shaft, from < to
};

struct SteadyCycle {
  DriveLine line;
  double motor_speed = 0;  ///< rad/s, constant
  double cycle_angle = 0;  ///< rad of the load shaft per cycle
  std::vector<LoadTorque> torques;
  std::vector<LoadEnergy> energies;
  std::vector<Phase> phases;
};

struct PhaseEnergy {
  std::string name;
  double duration = 0;    ///< s
  double energy = 0;      ///< J received by the load (torques only)
  double mean_power = 0;  ///< W
};

struct ElementPower {
  std::string name;         ///< "motor" or the stage name
  double power_in = 0;      ///< W, mean over the cycle
  double power_out = 0;     ///< W
  double power_lost = 0;    ///< W, in - out
};

struct CycleEnergyBalance {
  double cycle_time = 0;            ///< s
  std::vector<double> shaft_speed;  ///< rad/s of each shaft
  double load_energy = 0;           ///< J per cycle received by the load
  double useful_energy = 0;         ///< J per cycle of the parts marked useful
  double electrical_energy = 0;     ///< J per cycle taken by the motor
  double mean_electrical_power = 0; ///< W
  double overall_efficiency = 0;    ///< useful / electrical
  std::vector<double> shaft_mean_power;   ///< W through each shaft (towards the load)
  std::vector<double> shaft_mean_torque;  ///< N*m on each shaft, mean power / speed
  std::vector<ElementPower> elements;     ///< motor, then each stage
  std::vector<PhaseEnergy> phases;
};

/// The energy balance of one steady cycle.
/// @throws std::invalid_argument if the line is invalid (validate()), the motor speed or cycle
///         angle is not positive, an energy is negative, a phase is empty or outside the cycle,
///         or a load torque's table range differs from the cycle angle.
CycleEnergyBalance analyse_energy(const SteadyCycle& cycle);

/// Integrals of max(f, 0) and of min(f, 0) over [a, b] for a piecewise-linear f (exact).
struct SignedIntegrals {
  double positive = 0, negative = 0;
};
SignedIntegrals signed_integrals(const PiecewiseLinear& f, double a, double b);

}  // namespace gearkit::dyn
