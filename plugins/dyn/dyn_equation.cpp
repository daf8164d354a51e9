// The equation of motion written as the course writes it (seed 004 B3 f): the power balance on
// the load shaft, I omega alpha + T_r omega - eta P = 0, with the model's values.
#include "dyn_sections.hpp"

#include <fmt/format.h>

#include <cmath>

namespace gearkit::plugins::dyn {

namespace {

// The driving term: the motor's power, a constant or T_m(omega_m) omega_m.
std::string drive_term(const Model& m, nlohmann::json& j) {
  if (m.motor.torque && m.motor.torque->kind == TorqueLaw::Kind::constant_power) {
    j["motor_power_W"] = m.motor.torque->value;
    return fmt::format("P = {:g} W (constant)", m.motor.torque->value);
  }
  if (m.motor.torque && m.motor.torque->kind == TorqueLaw::Kind::constant) {
    j["motor_torque_Nm"] = m.motor.torque->value * m.motor.torque->scale;
    return fmt::format("P = T_m omega_m, T_m = {:g} N*m", m.motor.torque->value * m.motor.torque->scale);
  }
  if (!m.motor.torque && m.motor.power && m.motor.speed) {
    j["motor_torque_Nm"] = *m.motor.power / *m.motor.speed;
    return fmt::format("P = T_m omega_m, T_m = {:g} N*m (nominal power over nominal speed)", *m.motor.power / *m.motor.speed);
  }
  return "P = T_m(omega_m) omega_m (the motor's torque law)";
}

}  // namespace

nlohmann::json equation_of_motion(const Model& m, const gd::DriveLine& line, Output& out) {
  const std::size_t load = gd::shaft_count(line) - 1;
  const double inertia = gd::reduced_inertia(line, load);
  const double eta = gd::efficiency_between(line, 0, load);
  nlohmann::json j;
  j["shaft"] = m.load.name;
  j["inertia_kgm2"] = inertia;
  j["efficiency"] = eta;
  // The terms present in this model, in the course's order.
  std::string form = "I omega alpha";
  if (m.load.inertia_table) form += " + 1/2 I'(theta) omega^3";
  if (m.load.resisting) form += " + T_r(theta) omega";
  if (m.load.radius && m.load.force != 0.0) form += " + F r omega";
  form += " - eta P = 0";
  j["form"] = form;
  const std::string drive = drive_term(m, j);
  j["drive"] = drive;
  out.report.notes.push_back(fmt::format(
      "Equation of motion on the '{}' shaft (its power balance while the motor drives): {}, with I = {:.6g} kg*m^2 "
      "(reduced to that shaft{}), eta = {:.6g} (the stages' efficiencies), {}{}.",
      m.load.name, form, inertia, m.load.inertia_table ? ", plus the linkage's I(theta)" : "", eta, drive,
      m.load.radius && m.load.force != 0.0 ? fmt::format(", F = {:g} N at r = {:g} m", m.load.force, *m.load.radius) : ""));
  return j;
}

}  // namespace gearkit::plugins::dyn
