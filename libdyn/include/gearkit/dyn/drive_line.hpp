#pragma once
// A drive line: a motor shaft, then stages (gear pairs, reducers, belts) each joining one shaft
// to the next with a speed ratio and an efficiency; every shaft may carry inertia. Reduction to
// one shaft follows virtual power:
//   kinetic energy   -> I_red = sum I_k (omega_k / omega_ref)^2   (no efficiency: it is a state)
//   power of torques -> T_red = T (omega_k / omega_ref) * eta^(+-1)
// where the efficiency is applied in the direction the power flows: a torque that delivers power
// (a motor) reaches another shaft diminished (times eta), a torque that absorbs power (a load)
// needs more from the other shaft (divided by eta).
//
// Shafts are numbered from the motor: shaft 0 is the motor shaft, stage i joins shaft i to
// shaft i + 1. Speeds, torques and powers are magnitudes in each shaft's own sense of rotation
// while the motor runs forward; a torque is positive when it drives the line.
// SI units: rad/s, N*m, W, kg*m^2.
#include <cstddef>
#include <string>
#include <vector>

namespace gearkit::dyn {

struct Stage {
  std::string name;
  double ratio = 1;       ///< omega_out / omega_in (the seeds' tau); its sign is ignored
  double efficiency = 1;  ///< in (0, 1]
};

struct DriveLine {
  double motor_efficiency = 1;        ///< electrical to mechanical (eta_e-m), in (0, 1]
  std::vector<Stage> stages;
  std::vector<double> shaft_inertia;  ///< kg*m^2 on each shaft, stages.size() + 1 entries
  std::vector<std::string> shaft_names;  ///< optional, for messages and reports
};

/// Checks the line. @throws std::invalid_argument naming the stage or shaft when a ratio is 0
/// or not finite, an efficiency is not in (0, 1], an inertia is negative or not finite, or the
/// number of shafts is not stages + 1.
void validate(const DriveLine& line);

std::size_t shaft_count(const DriveLine& line);

/// omega_to / omega_from (positive). @throws std::out_of_range for a shaft index past the end.
double speed_ratio(const DriveLine& line, std::size_t from, std::size_t to);

/// Product of the efficiencies of the stages between two shafts (either order).
double efficiency_between(const DriveLine& line, std::size_t a, std::size_t b);

/// Reduced inertia at shaft `ref`: sum of I_k (omega_k / omega_ref)^2, kg*m^2.
double reduced_inertia(const DriveLine& line, std::size_t ref);

/// Power that must enter a stage so that `power_out` leaves it (W): power_out / eta when power
/// flows forward (power_out > 0), power_out * eta when it flows back through the stage.
double power_at_input(double power_out, double efficiency);

/// The torque at shaft `to` with the same virtual power as `torque` at shaft `from`, the
/// efficiencies in between applied in the direction the power flows: times eta for a torque that
/// drives (torque > 0), divided by eta for one that brakes (torque < 0). Valid for one torque
/// alone on the stages in between (with several, the net power through each stage decides; see
/// drive_line_acceleration).
double reduced_torque(const DriveLine& line, double torque, std::size_t from, std::size_t to);

/// Angular acceleration of the motor shaft, rad/s^2, from the power balance of every stage with
/// the efficiency taken in the direction the power crosses it at this instant (which depends on
/// the acceleration itself; the balance is monotone in it and solved exactly).
/// @param motor_torque N*m on shaft 0, positive driving
/// @param resisting_torque N*m on each shaft (shaft_count entries), positive braking
/// @param omega_motor rad/s, >= 0 (only its sign matters; at rest the direction of the first
///        motion is assumed forward)
/// @throws std::invalid_argument if the reduced inertia is not positive or the sizes differ.
double drive_line_acceleration(const DriveLine& line, double motor_torque,
                               const std::vector<double>& resisting_torque, double omega_motor);

}  // namespace gearkit::dyn
