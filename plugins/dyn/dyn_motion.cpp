// `motion:` — the equation of motion of the drive line on the motor shaft, integrated in time.
#include "dyn_sections.hpp"

#include <gearkit/dyn/motion.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gearkit::plugins::dyn {

namespace {

constexpr double rad_s_to_rpm = 60 / (2 * std::numbers::pi);
using TorqueFunction = std::function<double(double, double, double)>;

TorqueFunction motor_function(const Model& m, const MotionQuestion& q) {
  if (m.motor.torque) {
    if (m.motor.torque->kind == TorqueLaw::Kind::constant_power && !(q.speed > 0))
      io::fail_at(m.motor.torque->mark, "motor torque: a constant power gives an infinite torque at rest; start the "
                                        "motion with 'speed' > 0");
    return function_of(*m.motor.torque);
  }
  if (m.motor.power) return [t = *m.motor.power / *m.motor.speed](double, double, double) { return t; };
  io::fail_at(m.motor.mark, "motion: the motor needs a 'torque' (for instance its torque-speed curve) or a 'power' "
                            "with its nominal 'speed'");
}

/// The load's resisting torque on the load shaft, scaled to balance the drive under 'scale: balance'.
TorqueFunction resisting_function(const Model& m, const Output& out) {
  if (!m.load.resisting) return [](double, double, double) { return 0.0; };
  TorqueFunction resist = function_of(*m.load.resisting);
  if (!m.load.resisting->balance) return resist;
  if (!out.load_resisting_scale)
    io::fail_at(m.load.resisting->mark, "'scale: balance' on the load's resisting torque needs the flywheel "
                                        "question to find its size");
  return [f = resist, k = *out.load_resisting_scale](double th, double w, double t) { return k * f(th, w, t); };
}

/// The machine as the integrator sees it: the drive line (with the flywheel when asked), its
/// reduced inertia and the acceleration law of the motor shaft.
struct Machine {
  gd::DriveLine line;
  std::size_t load = 0;    ///< index of the load shaft
  double r_load = 0;       ///< speed of the load shaft per speed of the motor shaft
  double inertia = 0;      ///< kg*m^2 at the motor shaft (the smallest, with a linkage)
  bool linkage = false;    ///< the load drives a linkage of varying inertia
  gd::AccelerationLaw law;
};

Machine machine_of(const Model& m, const MotionQuestion& q, const Output& out) {
  Machine machine;
  const std::size_t n = gd::shaft_count(m.line), load = n - 1;
  const double r_load = gd::speed_ratio(m.line, 0, load);
  const std::optional<gd::InertiaTable>& linkage = m.load.inertia_table;
  gd::DriveLine line = m.line;
  if (q.with_flywheel) line.shaft_inertia[load] += out.flywheel_inertia;
  machine.inertia = gd::reduced_inertia(line, 0) + (linkage ? linkage->min_inertia() * r_load * r_load : 0.0);
  if (!(machine.inertia > 0))
    io::fail_at(q.mark, "motion: the machine has no inertia; give motor.inertia, a stage 'inertia' or the load's "
                        "'inertia' or 'mass'");
  const TorqueFunction motor = motor_function(m, q);
  const TorqueFunction resist = resisting_function(m, out);
  const double rim_torque = m.load.radius ? m.load.force * *m.load.radius : 0.0;
  // A linkage on the load shaft adds I(theta_L) there and the term 1/2 I'(theta_L) omega_L^2,
  // which acts like a resisting torque in the power balance.
  machine.law = [=](double t, double theta, double omega) {
    std::vector<double> resisting(n, 0.0);
    const double theta_l = theta * r_load, omega_l = omega * r_load;
    resisting[load] = resist(theta_l, omega_l, t) + rim_torque;
    if (!linkage) return gd::drive_line_acceleration(line, motor(theta, omega, t), resisting, omega);
    gd::DriveLine here = line;
    here.shaft_inertia[load] += linkage->inertia(theta_l);
    resisting[load] += 0.5 * linkage->derivative(theta_l) * omega_l * omega_l;
    return gd::drive_line_acceleration(here, motor(theta, omega, t), resisting, omega);
  };
  machine.line = std::move(line);
  machine.load = load;
  machine.r_load = r_load;
  machine.linkage = linkage.has_value();
  return machine;
}

/// The cycle of the load seen from the motor shaft: a resisting torque table or a linkage
/// repeats once per its table; otherwise a motor turn.
double motor_cycle(const Model& m, double r_load) {
  const std::optional<gd::InertiaTable>& linkage = m.load.inertia_table;
  const bool cyclic_table = m.load.resisting && m.load.resisting->kind == TorqueLaw::Kind::table;
  if (cyclic_table && linkage) {
    const double table = m.load.resisting->angle.back() - m.load.resisting->angle.front();
    if (std::abs(table - linkage->period()) > 1e-9 * table)
      io::fail_at(m.load.inertia_table_mark,
                  fmt::format("inertia_table covers {:g} deg but the resisting torque table {:g} deg; give both over "
                              "the same cycle", linkage->period() * 180 / std::numbers::pi, table * 180 / std::numbers::pi));
  }
  if (cyclic_table) return (m.load.resisting->angle.back() - m.load.resisting->angle.front()) / r_load;
  return linkage ? linkage->period() / r_load : 2 * std::numbers::pi;
}

gd::MotionOptions motion_options(const Model& m, const MotionQuestion& q, double r_load) {
  gd::MotionOptions o;
  o.t_end = q.t_end;
  o.output_step = q.output_step;
  o.steady_tolerance = q.steady_tolerance;
  o.cycle = motor_cycle(m, r_load);
  // Speed extremes are located once per step: keep steps to a small part of a cycle.
  const double speed_scale = std::max(q.speed, m.motor.speed.value_or(0.0));
  if (speed_scale > 0) {
    const double step = q.output_step > 0 ? q.output_step : q.t_end / 2000;
    o.max_step = std::min(step, o.cycle / (32 * speed_scale));
  }
  return o;
}

/// Whether the load repeats in cycles (a torque table or a linkage), so a speed fluctuation exists.
bool cyclic_load(const Model& m) {
  return (m.load.resisting && m.load.resisting->kind == TorqueLaw::Kind::table) || m.load.inertia_table.has_value();
}

/// Rows and warnings for a machine that cannot start or that stalls.
void report_start(const MotionQuestion& q, const Machine& machine, const gd::MotionOptions& o,
                  const gd::MotionResult& r, io::Table& t, nlohmann::json& j, Output& out) {
  j["cannot_start"] = r.cannot_start;
  if (r.cannot_start) {
    bool some_angle = false;
    for (int i = 0; i < 360 && !some_angle; ++i) some_angle = machine.law(0, q.angle + o.cycle * i / 360, 0) > 0;
    out.report.warnings.push_back(
        some_angle ? fmt::format("the machine cannot start from rest at {:g} deg of the motor shaft: the driving "
                                 "torque does not overcome the resisting torque there (it would from other angles)",
                                 q.angle * 180 / std::numbers::pi)
                   : "the machine can never start from rest: at every angle of the cycle the driving torque does not "
                     "overcome the resisting torque reduced to the motor shaft");
    t.add_row({"starts", "no", ""});
  }
  if (r.stalled) {
    out.report.warnings.push_back(fmt::format("the machine stalls: its speed falls to zero at t = {:.4g} s", r.stall_time));
    t.add_row({"stalls at", io::fixed(r.stall_time, 4), "s"});
    j["stall_time_s"] = r.stall_time;
  }
}

/// Times to 90, 95 and 99 % of the steady speed w, for a start from below each.
void report_startup(const MotionQuestion& q, const gd::MotionResult& r, double w, io::Table& t, nlohmann::json& j) {
  nlohmann::json startup = nlohmann::json::object();
  for (int percent : {90, 95, 99}) {
    // Only a start from below the threshold is a start-up time (a cyclic speed also dips below it).
    if (q.speed < percent / 100.0 * w) {
      if (const auto time = gd::time_to_reach(r, percent / 100.0 * w)) {
        t.add_row({fmt::format("time to {} % of the steady speed", percent), io::fixed(*time, 4), "s"});
        startup[fmt::format("t_{}_percent_s", percent)] = *time;
      }
    }
  }
  j["startup"] = startup;
}

void report_steady(const Model& m, const MotionQuestion& q, const Machine& machine, const gd::MotionResult& r,
                   io::Table& t, nlohmann::json& j) {
  const double w = r.cycle_mean_speed.back(), r_load = machine.r_load;
  t.add_row({"steady state reached at", io::fixed(r.steady_time, 4), "s"});
  t.add_row({"steady mean speed of the motor", io::fixed(w * rad_s_to_rpm, 3), "rpm"});
  t.add_row({fmt::format("steady mean speed of '{}'", m.load.name), io::fixed(w * r_load * rad_s_to_rpm, 3), "rpm"});
  if (m.load.radius) t.add_row({"steady rim speed", io::fixed(w * r_load * *m.load.radius, 4), "m/s"});
  if (r.cycle_max_speed.size() >= 1 && cyclic_load(m)) {
    const double wmax = r.cycle_max_speed.back(), wmin = r.cycle_min_speed.back();
    const double delta = (wmax - wmin) / (0.5 * (wmax + wmin));
    t.add_row({"speed fluctuation delta in the last cycle", io::fixed(delta, 6), ""});
    j["steady_fluctuation"] = delta;
  }
  j["steady_time_s"] = r.steady_time;
  j["steady_omega_rad_s"] = w;
  j["steady_load_omega_rad_s"] = w * r_load;
  report_startup(q, r, w, t, j);
}

/// The table "Equation of motion on the motor shaft": inertia, start, stall, steady state.
void report_summary(const Model& m, const MotionQuestion& q, const Machine& machine, const gd::MotionOptions& o,
                    const gd::MotionResult& r, nlohmann::json& j, Output& out) {
  io::Table t{"Equation of motion on the motor shaft", {"quantity", "value", "unit"}, {}};
  t.add_row({machine.linkage ? "smallest reduced inertia at the motor shaft" : "reduced inertia at the motor shaft",
             io::fixed(machine.inertia, 6), "kg*m^2"});
  t.add_row({"start speed", io::fixed(q.speed * rad_s_to_rpm, 2), "rpm"});
  j["inertia_motor_shaft_kgm2"] = machine.inertia;
  j["equation"] = equation_of_motion(m, machine.line, out);
  j["start_omega_rad_s"] = q.speed;
  if (q.with_flywheel) {
    t.add_row({"flywheel added to the load shaft", io::fixed(out.flywheel_inertia, 4), "kg*m^2"});
    j["flywheel_inertia_kgm2"] = out.flywheel_inertia;
  }
  report_start(q, machine, o, r, t, j, out);
  j["steady"] = r.steady;
  if (r.step_limit_reached) {
    out.report.warnings.push_back(fmt::format("the integration stopped at t = {:.6g} s after {} steps, before t_end; "
                                              "give a shorter 't_end'", r.samples.back().t, o.max_steps));
    j["step_limit_reached"] = true;
  }
  if (r.steady) {
    report_steady(m, q, machine, r, t, j);
  } else if (!r.cannot_start && !r.stalled && !r.step_limit_reached) {
    out.report.warnings.push_back(fmt::format("no steady state within t_end = {:g} s (cycle means still change by more "
                                              "than {:g}); give a longer 't_end'", q.t_end, q.steady_tolerance));
  }
  out.report.tables.push_back(std::move(t));
}

/// The table "Acceleration at given speeds" (motion.acceleration_at).
void report_accelerations(const Model& m, const MotionQuestion& q, const Machine& machine, nlohmann::json& j,
                          Output& out) {
  if (q.acceleration_at.empty()) return;
  const double r_load = machine.r_load;
  std::vector<std::string> header{"n motor [rpm]", "alpha motor [rad/s^2]", "alpha load [rad/s^2]"};
  if (m.load.radius) header.push_back("a rim [m/s^2]");
  io::Table a{fmt::format("Acceleration at given speeds (motor shaft at {:g} deg)", q.angle * 180 / std::numbers::pi),
              header, {}};
  nlohmann::json ja = nlohmann::json::array();
  for (double w : q.acceleration_at) {
    double alpha = 0;
    try {
      alpha = machine.law(0, q.angle, w);
    } catch (const std::exception& e) {
      io::fail_at(q.mark, fmt::format("motion: {}", e.what()));
    }
    std::vector<std::string> row{io::fixed(w * rad_s_to_rpm, 2), io::fixed(alpha, 4), io::fixed(alpha * r_load, 4)};
    nlohmann::json ji{{"omega_rad_s", w}, {"alpha_rad_s2", alpha}, {"load_alpha_rad_s2", alpha * r_load}};
    if (m.load.radius) {
      row.push_back(io::fixed(alpha * r_load * *m.load.radius, 4));
      ji["rim_acceleration_m_s2"] = alpha * r_load * *m.load.radius;
    }
    a.add_row(std::move(row));
    ja.push_back(ji);
  }
  out.report.tables.push_back(std::move(a));
  j["acceleration_at"] = ja;
}

/// Every sample to JSON and the speed plot; a short table of about 20 of them for reading.
void report_samples(const Model& m, const Machine& machine, const gd::MotionResult& r, nlohmann::json& j,
                    Output& out) {
  const double r_load = machine.r_load;
  io::Table s{"Speed against time", {"t [s]", "n motor [rpm]", fmt::format("n {} [rpm]", m.load.name)}, {}};
  if (m.load.radius) s.header.push_back("v rim [m/s]");
  const std::size_t count = r.samples.size();
  const std::size_t stride = std::max<std::size_t>(1, (count + 19) / 20);
  nlohmann::json jt = nlohmann::json::array(), jw = nlohmann::json::array(), jth = nlohmann::json::array();
  io::Series motor_speed{"motor [rpm]", {}, {}, "#1f77b4"};
  io::Series load_speed{m.load.name + " [rpm]", {}, {}, "#d62728"};
  for (std::size_t i = 0; i < count; ++i) {
    const gd::MotionSample& p = r.samples[i];
    jt.push_back(p.t);
    jw.push_back(p.omega);
    jth.push_back(p.theta);
    motor_speed.x.push_back(p.t);
    motor_speed.y.push_back(p.omega * rad_s_to_rpm);
    load_speed.x.push_back(p.t);
    load_speed.y.push_back(p.omega * r_load * rad_s_to_rpm);
    if (i % stride == 0 || i + 1 == count) {
      std::vector<std::string> row{io::fixed(p.t, 4), io::fixed(p.omega * rad_s_to_rpm, 2),
                                   io::fixed(p.omega * r_load * rad_s_to_rpm, 3)};
      if (m.load.radius) row.push_back(io::fixed(p.omega * r_load * *m.load.radius, 4));
      s.add_row(std::move(row));
    }
  }
  out.report.tables.push_back(std::move(s));
  j["samples"] = {{"t_s", jt}, {"omega_rad_s", jw}, {"theta_rad", jth}};

  io::Plot plot;
  plot.title = "Speed against time";
  plot.x_label = "t [s]";
  plot.panels.push_back({"motor speed [rpm]", {motor_speed}, {}});
  plot.panels.push_back({m.load.name + " speed [rpm]", {load_speed}, {}});
  out.speed_plot = std::move(plot);
}

}  // namespace

void add_motion(const Model& m, Output& out) {
  const MotionQuestion& q = *m.motion;
  const Machine machine = machine_of(m, q, out);
  const gd::MotionOptions o = motion_options(m, q, machine.r_load);
  gd::MotionResult r;
  try {
    r = gd::integrate_motion(machine.law, q.angle, q.speed, o);
  } catch (const std::exception& e) {
    io::fail_at(q.mark, fmt::format("motion: {}", e.what()));
  }
  nlohmann::json j;
  report_summary(m, q, machine, o, r, j, out);
  report_accelerations(m, q, machine, j, out);
  report_samples(m, machine, r, j, out);
  out.report.json["motion"] = j;
}

}  // namespace gearkit::plugins::dyn
