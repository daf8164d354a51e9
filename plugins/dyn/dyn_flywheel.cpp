// `flywheel:` — steady cycle on the load shaft: energy excursion, speeds, angles, inertia.
#include "dyn_sections.hpp"

#include <gearkit/dyn/flywheel.hpp>
#include <gearkit/dyn/motion.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <tuple>

namespace gearkit::plugins::dyn {

namespace {

constexpr double rad_to_deg = 180 / std::numbers::pi;
constexpr double rad_s_to_rpm = 60 / (2 * std::numbers::pi);

// The driving torque on the load shaft when the file gives none: the motor's constant torque
// (power / nominal speed, or a constant torque) carried through the stages.
gd::PiecewiseLinear default_drive(const Model& m, const FlywheelQuestion& q) {
  const std::size_t load = gd::shaft_count(m.line) - 1;
  double motor_torque = 0;
  if (m.motor.power) {
    motor_torque = *m.motor.power / *m.motor.speed;
  } else if (m.motor.torque && m.motor.torque->kind == TorqueLaw::Kind::constant) {
    motor_torque = m.motor.torque->value * m.motor.torque->scale;
  } else {
    io::fail_at(q.mark, "flywheel: give 'drive' (the driving torque on the load shaft), or a motor with 'power' "
                        "or a constant 'torque'");
  }
  return gd::PiecewiseLinear::constant(gd::reduced_torque(m.line, motor_torque, 0, load), 0, q.cycle);
}

// The load's resisting torque on its shaft, and the constant part a rim force adds to it.
struct Resisting {
  gd::PiecewiseLinear law;   // the torque law alone (the shape, when it is to be balanced)
  gd::PiecewiseLinear rim;   // constant torque of load.force at load.radius (0 if none)
};

Resisting default_resisting(const Model& m, const FlywheelQuestion& q) {
  if (!m.load.resisting)
    io::fail_at(q.mark, "flywheel: give 'resisting' (the resisting torque on the load shaft) here or in 'load'");
  return {curve_of(*m.load.resisting, q.cycle),
          gd::PiecewiseLinear::constant(m.load.radius ? m.load.force * *m.load.radius : 0.0, 0, q.cycle)};
}

std::vector<double> degrees(const std::vector<double>& rad) {
  std::vector<double> d = rad;
  for (double& v : d) v *= rad_to_deg;
  return d;
}

// One shaded area between the two curves over [a, b] (rad, inside the cycle).
io::ShadedArea area(const gd::PiecewiseLinear& drive, const gd::PiecewiseLinear& resist, double a, double b,
                    const std::string& label, bool surplus) {
  io::ShadedArea s;
  const int n = 64;
  for (int i = 0; i <= n; ++i) {
    const double th = a + (b - a) * i / n;
    const double d = i == n ? drive.left_value(th) : drive(th);
    const double r = i == n ? resist.left_value(th) : resist(th);
    s.x.push_back(th * rad_to_deg);
    s.y_low.push_back(std::min(d, r));
    s.y_high.push_back(std::max(d, r));
  }
  s.label = label;
  s.color = surplus ? "#8c8" : "#e99";
  return s;
}

io::Plot torque_plot(const gd::PiecewiseLinear& drive, const gd::PiecewiseLinear& resist, const gd::CycleEnergy& c,
                     const std::string& shaft) {
  io::Plot plot;
  plot.title = fmt::format("Torques on the {} shaft over one cycle; areas are energies", shaft);
  plot.x_label = "theta [deg]";
  io::PlotPanel panel;
  panel.y_label = "T [N*m]";
  panel.series.push_back({"driving torque", degrees(drive.x()), drive.y(), "#1f77b4"});
  panel.series.push_back({"resisting torque", degrees(resist.x()), resist.y(), "#d62728"});
  const double end = c.theta_start + c.period;
  for (const gd::EnergyLobe& lobe : c.lobes) {
    const std::string label = fmt::format("{:+.0f} J", lobe.energy);
    const bool surplus = lobe.energy > 0;
    if (lobe.theta_end <= end + 1e-12) {
      panel.areas.push_back(area(drive, resist, lobe.theta_start, std::min(lobe.theta_end, end), label, surplus));
    } else {  // the lobe that wraps past the cycle end is drawn in two parts, labelled once
      const bool first_larger = end - lobe.theta_start >= lobe.theta_end - end;
      panel.areas.push_back(area(drive, resist, lobe.theta_start, end, first_larger ? label : "", surplus));
      panel.areas.push_back(area(drive, resist, c.theta_start, lobe.theta_end - c.period,
                                 first_larger ? "" : label, surplus));
    }
  }
  // Where the speed is highest and lowest, as vertical lines across the torques.
  const double top = std::max(drive.max_value(), resist.max_value());
  for (const auto& [theta, name, colour] : {std::tuple{c.theta_at_energy_max, "omega_max", "#2ca02c"},
                                             std::tuple{c.theta_at_energy_min, "omega_min", "#9467bd"}}) {
    const double deg = theta * 180.0 / std::numbers::pi;
    panel.series.push_back({fmt::format("theta({}) = {:.2f} deg = {:.4f} rad", name, deg, theta), {deg, deg}, {0.0, top}, colour});
  }
  plot.panels.push_back(std::move(panel));
  return plot;
}

// The fluctuation the sized machine really has, from its equation of motion over one cycle
// started at the angle of least speed with omega_min. With a constant inertia it equals the
// requested delta (the closed form is exact); with a linkage's I(theta) it shows the difference.
std::optional<double> integrated_fluctuation(const gd::PiecewiseLinear& drive, const gd::PiecewiseLinear& resist,
                                             const gd::CycleEnergy& c, const gd::FlywheelSizing& s,
                                             double fixed_inertia,
                                             const std::optional<gd::InertiaTable>& linkage) {
  gd::ReducedSystem sys;
  const double constant = fixed_inertia + s.inertia_flywheel;
  sys.inertia = [&](double th) { return constant + (linkage ? linkage->inertia(th) : 0.0); };
  if (linkage) sys.inertia_derivative = [&](double th) { return linkage->derivative(th); };
  sys.drive_torque = [&](double th, double) { return drive(th); };
  sys.resisting_torque = [&](double th, double) { return resist(th); };
  gd::MotionOptions o;
  o.cycle = c.period;
  o.t_end = 1.5 * c.period / s.omega_mean;
  o.output_step = o.t_end / 2000;
  o.stop_when_steady = false;
  try {
    const gd::MotionResult r = gd::integrate_motion(gd::acceleration_law(sys), c.theta_at_energy_min, s.omega_min, o);
    if (r.cycle_max_speed.empty() || r.stalled) return std::nullopt;
    const double wmax = r.cycle_max_speed.front(), wmin = r.cycle_min_speed.front();
    return (wmax - wmin) / (0.5 * (wmax + wmin));
  } catch (const std::exception&) {
    return std::nullopt;  // e.g. no inertia at all: the closed form already said what is needed
  }
}

}  // namespace

// A torque typed at its printed precision (M_r,max = 2158 N*m for 2158.033) leaves the cycle
// unbalanced by a few parts in 10^5; up to kPrintedImbalance the resisting torque is scaled to
// close the cycle, with a warning that states the imbalance. More than that is a wrong input.
constexpr double kPrintedImbalance = 1e-3;

void close_printed_cycle(const gd::PiecewiseLinear& drive, gd::PiecewiseLinear& resist, std::vector<std::string>& warnings) {
  if (!drive.periodic() || !resist.periodic() || drive.range() <= 0.0) return;
  const double e_drive = drive.integral(drive.x_front(), drive.x_front() + drive.range());
  const double e_resist = resist.integral(resist.x_front(), resist.x_front() + resist.range());
  const double larger = std::max(std::abs(e_drive), std::abs(e_resist));
  const double imbalance = std::abs(e_drive - e_resist) / larger;
  if (!(larger > 0.0) || e_resist == 0.0 || imbalance <= 1e-6 || imbalance > kPrintedImbalance) return;
  const double k = e_drive / e_resist;
  resist = resist.scaled(k);
  warnings.push_back(fmt::format("flywheel: the cycle does not balance exactly: the driving torque does {:.6g} J per "
                                 "cycle, the resisting torque takes {:.6g} J (relative imbalance {:.2g}, within the "
                                 "precision of printed values); the resisting torque is scaled by {:.7f} to close it",
                                 e_drive, e_resist, imbalance, k));
}

double motor_speed(const Model& model, const io::SourceMark& where, std::string_view question) {
  if (!model.motor.speed)
    io::fail_at(where, fmt::format("{}: needs the motor's nominal 'speed' (motor.speed)", question));
  return *model.motor.speed;
}

namespace {

/// The two torques on the load shaft over one cycle, one of them scaled to balance the cycle
/// when the file asks for it ('scale: balance').
struct CycleTorques {
  gd::PiecewiseLinear drive, resist;
  std::optional<double> scale;  ///< the balancing factor, when one torque was scaled
  bool balance_resist = false;  ///< the scaled torque is the resisting one
};

CycleTorques cycle_torques(const Model& m, const FlywheelQuestion& q, Output& out) {
  gd::PiecewiseLinear drive = q.drive ? curve_of(*q.drive, q.cycle) : default_drive(m, q);
  const Resisting parts = q.resisting ? Resisting{curve_of(*q.resisting, q.cycle), gd::PiecewiseLinear::constant(0, 0, q.cycle)}
                                      : default_resisting(m, q);
  const auto combine = [&parts](double k) { return gd::difference(parts.law.scaled(k), parts.rim.scaled(-1)); };
  CycleTorques t{std::move(drive), combine(1), std::nullopt, false};
  const TorqueLaw* resisting_law = q.resisting ? &*q.resisting : &*m.load.resisting;
  const bool balance_drive = q.drive && q.drive->balance;
  t.balance_resist = resisting_law->balance;
  if (balance_drive && t.balance_resist)
    io::fail_at(q.drive->mark, "flywheel: only one of the two torques can be scaled to balance the cycle");
  try {
    if (t.balance_resist) {
      // Only the law is scaled; a rim force keeps its given size.
      t.scale = gd::balance_scale(gd::difference(t.drive, parts.rim), parts.law);
      t.resist = combine(*t.scale);
      if (!q.resisting) out.load_resisting_scale = *t.scale;
    } else if (balance_drive) {
      t.scale = gd::balance_scale(t.resist, t.drive);
      t.drive = t.drive.scaled(*t.scale);
    }
  } catch (const std::invalid_argument& e) {
    io::fail_at(q.mark, fmt::format("flywheel: {}", e.what()));
  }
  if (!t.scale) close_printed_cycle(t.drive, t.resist, out.report.warnings);
  return t;
}

/// The steady cycle, the flywheel sized for it and the fluctuation the equation of motion gives.
struct FlywheelResult {
  gd::CycleEnergy cycle;
  gd::FlywheelSizing sizing;
  std::optional<double> integrated;
  double motor_torque = 0;  ///< N*m: the mean driving torque carried to the motor shaft
};

/// @param omega_motor rad/s, the motor's nominal speed.
FlywheelResult flywheel_for(const Model& m, const FlywheelQuestion& q, const CycleTorques& t, double omega_motor) {
  const std::size_t load = gd::shaft_count(m.line) - 1;
  const double omega_mean = omega_motor * gd::speed_ratio(m.line, 0, load);
  FlywheelResult f;
  try {
    f.cycle = gd::analyse_cycle(t.drive, t.resist);
  } catch (const std::invalid_argument& e) {
    io::fail_at(q.mark, fmt::format("flywheel: {} (with 'scale: balance' on the torque whose size follows from the "
                                    "energy balance)", e.what()));
  }
  const std::optional<gd::InertiaTable>& linkage = m.load.inertia_table;
  const double fixed_inertia = gd::reduced_inertia(m.line, load);
  try {
    f.sizing = gd::size_flywheel(f.cycle.energy_excursion, omega_mean, q.fluctuation,
                                 fixed_inertia + (linkage ? linkage->mean_inertia() : 0.0));
  } catch (const std::invalid_argument& e) {
    io::fail_at(q.mark, fmt::format("flywheel: {}", e.what()));
  }
  f.integrated = integrated_fluctuation(t.drive, t.resist, f.cycle, f.sizing, fixed_inertia, linkage);
  // The same power on the motor shaft: T_motor = T_load (omega_load / omega_motor) / eta.
  f.motor_torque = f.cycle.mean_drive_torque * gd::speed_ratio(m.line, 0, load) / gd::efficiency_between(m.line, 0, load);
  return f;
}

/// The table "Flywheel: steady cycle on the ... shaft" and the note on a linkage's inertia.
void report_flywheel(const Model& m, const CycleTorques& t, const FlywheelResult& f, Output& out) {
  const gd::CycleEnergy& c = f.cycle;
  const gd::FlywheelSizing& s = f.sizing;
  io::Table table{fmt::format("Flywheel: steady cycle on the '{}' shaft", m.load.name), {"quantity", "value", "unit"}, {}};
  table.add_row({"mean speed omega_m", io::fixed(s.omega_mean, 3), "rad/s"});
  table.add_row({"mean speed n_m", io::fixed(s.omega_mean * rad_s_to_rpm, 2), "rpm"});
  table.add_row({"coefficient of speed fluctuation delta", io::fixed(s.fluctuation, 5), ""});
  table.add_row({"omega_max", io::fixed(s.omega_max, 3), "rad/s"});
  table.add_row({"omega_min", io::fixed(s.omega_min, 3), "rad/s"});
  table.add_row({"mean driving torque", io::fixed(c.mean_drive_torque, 3), "N*m"});
  table.add_row({"mean torque on the motor shaft", io::fixed(f.motor_torque, 3), "N*m"});
  table.add_row({"largest driving torque", io::fixed(t.drive.max_value(), 3), "N*m"});
  table.add_row({"largest resisting torque", io::fixed(t.resist.max_value(), 3), "N*m"});
  if (t.scale) table.add_row({t.balance_resist ? "resisting torque scale (balance)" : "driving torque scale (balance)",
                              io::fixed(*t.scale, 6), ""});
  table.add_row({"energy per cycle", io::fixed(c.drive_energy, 2), "J"});
  table.add_row({"theta at omega_max", io::fixed(c.theta_at_energy_max * rad_to_deg, 3), "deg"});
  table.add_row({"theta at omega_max", io::fixed(c.theta_at_energy_max, 4), "rad"});
  table.add_row({"theta at omega_min", io::fixed(c.theta_at_energy_min * rad_to_deg, 3), "deg"});
  table.add_row({"theta at omega_min", io::fixed(c.theta_at_energy_min, 4), "rad"});
  table.add_row({"largest energy excursion E_max - E_min", io::fixed(c.energy_excursion, 2), "J"});
  table.add_row({"inertia of the machine (reduced)", io::fixed(s.inertia_machine, 4), "kg*m^2"});
  table.add_row({"total inertia needed", io::fixed(s.inertia_total, 4), "kg*m^2"});
  table.add_row({"flywheel inertia", io::fixed(s.inertia_flywheel, 4), "kg*m^2"});
  if (f.integrated) table.add_row({"delta from the equation of motion with it", io::fixed(*f.integrated, 5), ""});
  out.report.tables.push_back(std::move(table));
  if (const std::optional<gd::InertiaTable>& linkage = m.load.inertia_table)
    out.report.notes.push_back(fmt::format(
        "The linkage's reduced inertia varies from {:.6g} to {:.6g} kg*m^2 over its cycle; the flywheel is sized with "
        "its mean {:.6g} kg*m^2, and the equation of motion gives the fluctuation the machine really has.",
        linkage->min_inertia(), linkage->max_inertia(), linkage->mean_inertia()));
}

/// The table of energy areas between the torque curves; returns them for JSON.
nlohmann::json report_lobes(const gd::CycleEnergy& c, Output& out) {
  io::Table lobes{"Energy areas between the torque curves (+ speeds up, - slows down)",
                  {"from [deg]", "to [deg]", "energy [J]"}, {}};
  nlohmann::json jl = nlohmann::json::array();
  for (const gd::EnergyLobe& l : c.lobes) {
    lobes.add_row({io::fixed(l.theta_start * rad_to_deg, 3), io::fixed(l.theta_end * rad_to_deg, 3),
                   io::fixed(l.energy, 2)});
    jl.push_back({{"theta_start_deg", l.theta_start * rad_to_deg},
                  {"theta_end_deg", l.theta_end * rad_to_deg},
                  {"energy_J", l.energy}});
  }
  out.report.tables.push_back(std::move(lobes));
  out.report.notes.push_back("The speed is highest where the driving torque falls below the resisting one and lowest "
                             "where it rises above it; I_total = (E_max - E_min) / (delta omega_m^2), exact for "
                             "omega_m = (omega_max + omega_min) / 2 and a constant inertia.");
  return jl;
}

void flywheel_json(const Model& m, const CycleTorques& t, const FlywheelResult& f, nlohmann::json lobes,
                   nlohmann::json& j) {
  const gd::CycleEnergy& c = f.cycle;
  const gd::FlywheelSizing& s = f.sizing;
  j["shaft"] = m.load.name;
  j["omega_mean_rad_s"] = s.omega_mean;
  j["fluctuation"] = s.fluctuation;
  j["omega_max_rad_s"] = s.omega_max;
  j["omega_min_rad_s"] = s.omega_min;
  j["theta_at_omega_max_deg"] = c.theta_at_energy_max * rad_to_deg;
  j["theta_at_omega_min_deg"] = c.theta_at_energy_min * rad_to_deg;
  j["theta_at_omega_max_rad"] = c.theta_at_energy_max;
  j["theta_at_omega_min_rad"] = c.theta_at_energy_min;
  j["motor_torque_Nm"] = f.motor_torque;
  j["energy_excursion_J"] = c.energy_excursion;
  j["energy_per_cycle_J"] = c.drive_energy;
  j["mean_drive_torque_Nm"] = c.mean_drive_torque;
  j["max_resisting_torque_Nm"] = t.resist.max_value();
  if (t.scale) j[t.balance_resist ? "resisting_scale" : "drive_scale"] = *t.scale;
  j["inertia_machine_kgm2"] = s.inertia_machine;
  j["inertia_total_kgm2"] = s.inertia_total;
  j["inertia_flywheel_kgm2"] = s.inertia_flywheel;
  j["energy_lobes"] = std::move(lobes);
  if (f.integrated) j["fluctuation_integrated"] = *f.integrated;
  if (const std::optional<gd::InertiaTable>& linkage = m.load.inertia_table) {
    j["linkage_inertia_min_kgm2"] = linkage->min_inertia();
    j["linkage_inertia_max_kgm2"] = linkage->max_inertia();
    j["linkage_inertia_mean_kgm2"] = linkage->mean_inertia();
  }
}

}  // namespace

void add_flywheel(const Model& m, Output& out) {
  const FlywheelQuestion& q = *m.flywheel;
  const double omega_motor = motor_speed(m, q.mark, "flywheel");
  const CycleTorques t = cycle_torques(m, q, out);
  const FlywheelResult f = flywheel_for(m, q, t, omega_motor);
  report_flywheel(m, t, f, out);
  nlohmann::json lobes = report_lobes(f.cycle, out);
  const gd::FlywheelSizing& s = f.sizing;
  if (!s.flywheel_needed)
    out.report.warnings.push_back(fmt::format(
        "no flywheel needed: the machine's own {:.4g} kg*m^2 on the '{}' shaft already keeps the fluctuation at "
        "{:.4g}, below the {:.4g} asked for",
        s.inertia_machine, m.load.name, s.fluctuation_without_flywheel, s.fluctuation));
  flywheel_json(m, t, f, std::move(lobes), out.report.json);
  out.flywheel_inertia = s.inertia_flywheel;
  out.torque_plot = torque_plot(t.drive, t.resist, f.cycle, m.load.name);
}

}  // namespace gearkit::plugins::dyn
