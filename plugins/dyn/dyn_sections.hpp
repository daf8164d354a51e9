#pragma once
// The three questions a `gearkit dyn` model may ask, each adding its tables, JSON keys,
// warnings and plot to the command's output.
#include "dyn_model.hpp"

#include <gearkit/io/plot.hpp>
#include <gearkit/io/report.hpp>

#include <optional>

namespace gearkit::plugins::dyn {

struct Output {
  io::Report report;
  std::optional<io::Plot> torque_plot;  ///< torque against angle with the energy areas
  std::optional<io::Plot> speed_plot;   ///< speed against time
  double flywheel_inertia = 0;          ///< kg*m^2 on the load shaft, sized by add_flywheel
  /// The factor add_flywheel found for load.resisting under 'scale: balance'.
  std::optional<double> load_resisting_scale;
};

/// Steady cycle and flywheel on the load shaft (model.flywheel).
void add_flywheel(const Model& model, Output& out);
/// Energy and efficiency over a steady cycle at constant speed (model.energy).
void add_energy(const Model& model, Output& out);
/// Equation of motion on the motor shaft (model.motion).
void add_motion(const Model& model, Output& out);
/// The equation of motion as the course writes it: the power balance on the load shaft,
/// I omega alpha [+ 1/2 I' omega^3] + T_r omega [+ F r omega] - eta P = 0, as a report note and
/// its JSON (`shaft`, `form`, `inertia_kgm2`, `efficiency`, `drive`, and `motor_power_W` or
/// `motor_torque_Nm` when the motor law gives one). `line` is the drive line the motion uses.
nlohmann::json equation_of_motion(const Model& model, const gd::DriveLine& line, Output& out);
/// Reduced force (and torque) of forces, weights and inertia forces at one instant (model.reduced_force).
void add_reduced_force(const Model& model, Output& out);

/// The nominal motor speed, or an error at `where` naming the question that needs it.
double motor_speed(const Model& model, const io::SourceMark& where, std::string_view question);

}  // namespace gearkit::plugins::dyn
