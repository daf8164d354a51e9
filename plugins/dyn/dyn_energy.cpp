// `energy:` — energy per cycle, powers, losses, mean torques and efficiency at constant speed.
#include "dyn_sections.hpp"

#include <gearkit/dyn/energy.hpp>

#include <fmt/format.h>

#include <numbers>
#include <stdexcept>

namespace gearkit::plugins::dyn {

namespace {

constexpr double rad_s_to_rpm = 60 / (2 * std::numbers::pi);

/// The steady cycle at the motor's nominal speed with the question's loads and phases.
gd::SteadyCycle steady_cycle(const Model& m, const EnergyQuestion& q, double& rim_speed) {
  gd::SteadyCycle cycle;
  cycle.line = m.line;
  cycle.motor_speed = motor_speed(m, q.mark, "energy");
  const std::size_t load = gd::shaft_count(m.line) - 1;
  const double omega_load = cycle.motor_speed * gd::speed_ratio(m.line, 0, load);
  cycle.cycle_angle = q.cycle ? *q.cycle : omega_load * *q.cycle_time;
  rim_speed = m.load.radius ? omega_load * *m.load.radius : 0.0;

  for (const EnergyLoad& l : q.loads) {
    if (l.torque) cycle.torques.push_back({l.name, curve_of(*l.torque, cycle.cycle_angle), l.useful});
    if (l.force > 0)
      cycle.torques.push_back(
          {l.name, gd::PiecewiseLinear::constant(l.force * *m.load.radius, 0, cycle.cycle_angle), l.useful});
    if (l.energy > 0) cycle.energies.push_back({l.name, l.energy, l.useful});
    // Brought from rest to the rim speed by friction: as much energy is lost in the slip as the
    // mass gains, m v^2 in all.
    if (l.mass_to_speed > 0) cycle.energies.push_back({l.name, l.mass_to_speed * rim_speed * rim_speed, l.useful});
  }
  for (const EnergyPhase& p : q.phases) {
    if (p.to > cycle.cycle_angle * (1 + 1e-9))
      io::fail_at(p.mark, fmt::format("phase {} ends at {:g} deg, after the cycle's {:g} deg", io::quote(p.name),
                                      p.to * 180 / std::numbers::pi, cycle.cycle_angle * 180 / std::numbers::pi));
    cycle.phases.push_back({p.name, p.from, std::min(p.to, cycle.cycle_angle)});
  }
  return cycle;
}

void report_summary(const Model& m, const EnergyQuestion& q, const gd::SteadyCycle& cycle, double rim_speed,
                    const gd::CycleEnergyBalance& b, Output& out) {
  io::Table summary{"Energy over one steady cycle (constant speed)", {"quantity", "value", "unit"}, {}};
  summary.add_row({"cycle time", io::fixed(b.cycle_time, 4), "s"});
  summary.add_row({"cycle angle of the load shaft", io::fixed(cycle.cycle_angle / (2 * std::numbers::pi), 4), "rev"});
  if (m.load.radius) summary.add_row({"rim speed v", io::fixed(rim_speed, 4), "m/s"});
  summary.add_row({"energy received by the load per cycle", io::fixed(b.load_energy, 2), "J"});
  summary.add_row({"useful energy per cycle", io::fixed(b.useful_energy, 2), "J"});
  summary.add_row({"electrical energy per cycle", io::fixed(b.electrical_energy, 2), "J"});
  summary.add_row({"mean electrical power", io::fixed(b.mean_electrical_power, 2), "W"});
  summary.add_row({"overall efficiency", io::fixed(b.overall_efficiency, 4), ""});
  if (q.report_time) {
    const double e = b.mean_electrical_power * *q.report_time;
    summary.add_row({fmt::format("electrical energy in {:g} s", *q.report_time), io::fixed(e / 1e6, 4), "MJ"});
    summary.add_row({fmt::format("electrical energy in {:g} s", *q.report_time), io::fixed(e / 3.6e6, 4), "kWh"});
  }
  out.report.tables.push_back(std::move(summary));
}

nlohmann::json report_phases(const gd::CycleEnergyBalance& b, Output& out) {
  nlohmann::json jphases = nlohmann::json::array();
  if (b.phases.empty()) return jphases;
  io::Table t{"Power received by the load in each phase", {"phase", "duration [s]", "energy [J]", "mean power [W]"}, {}};
  for (const auto& p : b.phases) {
    t.add_row({p.name, io::fixed(p.duration, 4), io::fixed(p.energy, 2), io::fixed(p.mean_power, 2)});
    jphases.push_back({{"name", p.name}, {"duration_s", p.duration}, {"energy_J", p.energy}, {"mean_power_W", p.mean_power}});
  }
  out.report.tables.push_back(std::move(t));
  return jphases;
}

nlohmann::json report_elements(const gd::CycleEnergyBalance& b, Output& out) {
  io::Table elements{"Mean power through each element", {"element", "in [W]", "out [W]", "dissipated [W]"}, {}};
  nlohmann::json jel = nlohmann::json::array();
  for (const auto& e : b.elements) {
    elements.add_row({e.name, io::fixed(e.power_in, 2), io::fixed(e.power_out, 2), io::fixed(e.power_lost, 2)});
    jel.push_back({{"name", e.name}, {"power_in_W", e.power_in}, {"power_out_W", e.power_out}, {"power_lost_W", e.power_lost}});
  }
  out.report.tables.push_back(std::move(elements));
  return jel;
}

nlohmann::json report_shafts(const Model& m, const gd::CycleEnergyBalance& b, Output& out) {
  io::Table shafts{"Shafts", {"shaft", "n [rpm]", "mean power [W]", "mean torque [N*m]"}, {}};
  nlohmann::json jsh = nlohmann::json::array();
  for (std::size_t k = 0; k < b.shaft_speed.size(); ++k) {
    const std::string name = k < m.line.shaft_names.size() ? m.line.shaft_names[k] : fmt::format("shaft {}", k);
    shafts.add_row({name, io::fixed(b.shaft_speed[k] * rad_s_to_rpm, 2), io::fixed(b.shaft_mean_power[k], 2),
                    io::fixed(b.shaft_mean_torque[k], 4)});
    jsh.push_back({{"name", name}, {"omega_rad_s", b.shaft_speed[k]}, {"mean_power_W", b.shaft_mean_power[k]},
                   {"mean_torque_Nm", b.shaft_mean_torque[k]}});
  }
  out.report.tables.push_back(std::move(shafts));
  if (!m.line.stages.empty())
    out.report.notes.push_back("Mean torques at a reducer: the input is the shaft before it, the output the shaft after "
                               "it (each stage's output shaft carries the stage's name).");
  return jsh;
}

}  // namespace

void add_energy(const Model& m, Output& out) {
  const EnergyQuestion& q = *m.energy;
  double rim_speed = 0;
  const gd::SteadyCycle cycle = steady_cycle(m, q, rim_speed);
  gd::CycleEnergyBalance b;
  try {
    b = gd::analyse_energy(cycle);
  } catch (const std::invalid_argument& e) {
    io::fail_at(q.mark, fmt::format("energy: {}", e.what()));
  }
  report_summary(m, q, cycle, rim_speed, b, out);
  nlohmann::json jphases = report_phases(b, out);
  nlohmann::json jel = report_elements(b, out);
  nlohmann::json jsh = report_shafts(m, b, out);

  nlohmann::json j{{"cycle_time_s", b.cycle_time},
                   {"cycle_angle_rad", cycle.cycle_angle},
                   {"load_energy_J", b.load_energy},
                   {"useful_energy_J", b.useful_energy},
                   {"electrical_energy_J", b.electrical_energy},
                   {"mean_electrical_power_W", b.mean_electrical_power},
                   {"overall_efficiency", b.overall_efficiency},
                   {"phases", jphases},
                   {"elements", jel},
                   {"shafts", jsh}};
  if (m.load.radius) j["rim_speed_m_s"] = rim_speed;
  if (q.report_time) {
    j["report_time_s"] = *q.report_time;
    j["electrical_energy_in_report_time_J"] = b.mean_electrical_power * *q.report_time;
  }
  out.report.json["energy"] = j;
  if (b.useful_energy == 0)
    out.report.notes.push_back("No load is marked 'useful: true', so the overall efficiency is 0.");
}

}  // namespace gearkit::plugins::dyn
