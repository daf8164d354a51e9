// `gearkit kin FILE.yaml [--at VALUE | --sweep START:END:STEP] [--driver NAME] [--outputs A,B]
//                        [--plot FILE] [--animate FILE] [--format text|json|csv|md]`
// Planar mechanism analysis: degrees of freedom, positions, velocities, accelerations, dead
// points, limit positions of outputs, instant centres, Grashof class and transmission angle,
// driving torque and joint reactions.
#include "kin_analysis.hpp"
#include "kin_equations.hpp"
#include "kin_command.hpp"
#include "kin_reactions.hpp"
#include "kin_example.hpp"

#include <gearkit/io/atomic_file.hpp>
#include <gearkit/io/command_line.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/limits.hpp>
#include <gearkit/io/plot.hpp>
#include <gearkit/io/progress.hpp>
#include <gearkit/io/report.hpp>
#include <gearkit/kin/fourbar.hpp>
#include <gearkit/kin/instant_centre.hpp>

#include <fmt/format.h>

#include <cmath>
#include <sstream>

namespace gearkit::cli {

namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

bool angular(const mechanism::Mechanism& mech, int driver) {
  return mech.drivers[static_cast<std::size_t>(driver)].quantity == kin::DriverQuantity::angle;
}
// Input values are shown in deg (angles) or mm (displacements).
double shown_input(const mechanism::Mechanism& mech, int driver, double v) {
  return angular(mech, driver) ? v * kRadToDeg : v * 1000.0;
}
std::string input_unit(const mechanism::Mechanism& mech, int driver) { return angular(mech, driver) ? "deg" : "mm"; }
std::string input_key(const mechanism::Mechanism& mech, int driver) { return "input_" + input_unit(mech, driver); }

double shown_output(const kin::Output& o, double v) { return o.angular() ? v * kRadToDeg : v * 1000.0; }
std::string output_unit(const kin::Output& o) { return kin::output_units(o).value; }

// START:END:STEP with the driver's unit as default.
mechanism::DriverRange parse_sweep(const std::string& text, io::Quantity q, std::string_view unit) {
  std::vector<std::string> parts;
  std::stringstream ss(text);
  for (std::string part; std::getline(ss, part, ':');) parts.push_back(part);
  if (parts.size() != 3)
    io::fail_option("--sweep", fmt::format("expected START:END:STEP (e.g. 0:360:1), found {}", io::quote(text)));
  mechanism::DriverRange r;
  try {
    r.start = io::parse_quantity_si(parts[0], q, unit);
    r.end = io::parse_quantity_si(parts[1], q, unit);
    r.step = io::parse_quantity_si(parts[2], q, unit);
  } catch (const std::exception& e) {
    io::fail_option("--sweep", e.what());
  }
  if (!(r.step > 0.0)) io::fail_option("--sweep", fmt::format("expected a STEP > 0, found {}", io::quote(parts[2])));
  if (r.start == r.end) io::fail_option("--sweep", "expected START different from END");
  if (std::abs(r.end - r.start) / r.step + 1 > io::limits::kSweepPositions)
    io::fail_option("--sweep", fmt::format("expected at most {:g} positions, found {:.6g}", io::limits::kSweepPositions,
                                           std::floor(std::abs(r.end - r.start) / r.step) + 1));
  return r;
}

// The work of a sweep grows with positions times coordinates (docs/cli.md, "Limits").
void check_sweep_work(const kin::Model& m, const mechanism::DriverRange& r, const std::string& where) {
  const double positions = std::floor(std::abs(r.end - r.start) / r.step) + 1;
  const double work = positions * m.coordinates();
  if (work > io::limits::kSweepWork)
    throw io::InputError(fmt::format("{}: expected at most {:g} positions times coordinates for a sweep, found {:g} "
                                     "positions x {} coordinates; take a larger step",
                                     where, io::limits::kSweepWork, positions, m.coordinates()));
}

// Continuation from the drawn input to --at takes |at - drawn| / step steps of the solver.
void check_continuation_work(const kin::Model& m, double distance, double step) {
  const double steps = std::ceil(std::abs(distance) / step);
  if (steps > io::limits::kContinuationSteps || steps * m.coordinates() > io::limits::kContinuationWork)
    io::fail_option("--at", fmt::format("expected a value within {:g} continuation steps of the drawn input (and at "
                                        "most {:g} steps times coordinates), found {:g} steps for {} coordinates",
                                        io::limits::kContinuationSteps, io::limits::kContinuationWork, steps,
                                        m.coordinates()));
}

nlohmann::json coordinates_json(const kin::Model& m, const Eigen::VectorXd& v, int order) {
  static const char* names[3][3] = {{"x_mm", "y_mm", "angle_deg"},
                                    {"vx_mm_s", "vy_mm_s", "omega_rad_s"},
                                    {"ax_mm_s2", "ay_mm_s2", "alpha_rad_s2"}};
  nlohmann::json j = nlohmann::json::object();
  for (int i = 0; i < v.size(); ++i) {
    const int c = i % 3;
    const double value = c < 2 ? v(i) * 1000.0 : (order == 0 ? v(i) * kRadToDeg : v(i));
    j[m.bodies()[static_cast<std::size_t>(i / 3)].name + "." + names[order][c]] = value;
  }
  return j;
}

// Velocity ratios are shown per rad or per mm of input, in rad or mm of output.
std::string ratio_unit(const mechanism::Mechanism& mech, int driver, const kin::Output& o) {
  const bool in_angle = angular(mech, driver);
  if (o.angular()) return in_angle ? "-" : "rad/mm";
  return in_angle ? "mm/rad" : "-";
}

std::string effort_key(const mechanism::Mechanism& mech, int driver) {
  return angular(mech, driver) ? "driving_torque_Nm" : "driving_force_N";
}

}  // namespace

KinPosition describe_position(const mechanism::Mechanism& mech, kin::Data& data, int driver, double input) {
  KinPosition p;
  p.input = input;
  p.q = data.q;
  p.qd = data.qd;
  p.qdd = data.qdd;
  const Eigen::VectorXd dq = kin::input_sensitivity(mech.model, data, driver);
  for (const kin::Output& o : mech.outputs) {
    p.outputs.push_back(kin::evaluate_output(mech.model, data, o));
    p.output_ratios.push_back(dq.size() ? kin::output_derivative(mech.model, data, o, dq) : NAN);
  }
  if (const auto fb = kin::find_four_bar(mech.model)) p.transmission_angle = kin::transmission_angle(*fb, data);
  if (mech.model.has_loads()) p.forces = kin::solve_forces(mech.model, data, driver);
  return p;
}

namespace {

// A sweep when `range` is given, else one position at `at` (or the driver's value).
KinAnalysis analyse(const mechanism::Mechanism& mech, kin::Data& data, int driver, std::optional<double> at,
                    const mechanism::DriverRange* range) {
  KinAnalysis a;
  a.driver = driver;
  const kin::Model& m = mech.model;
  const std::string unit = input_unit(mech, driver);
  if (!range) {
    a.single = true;
    const double drawn = data.inputs(driver);
    const double value = at ? *at : drawn;
    // Reach the requested input by continuation from the drawn configuration, so the answer
    // stays on the drawing's assembly branch (Newton from a distant guess may land on another).
    const double step = angular(mech, driver) ? 2.0 * M_PI / 180.0 : 0.002;
    check_continuation_work(m, value - drawn, step);
    if (std::abs(value - drawn) > step) {
      kin::SweepOptions o;
      o.driver = driver;
      o.start = drawn;
      o.end = value;
      o.step = step;
      o.velocities = false;
      o.min_step = 1e-9 * std::max(1.0, std::abs(value - drawn));
      const kin::SweepResult s = kin::sweep(m, data, o);
      if (!s.complete) {
        kin::solve_position(m, data, 0.0);
        a.dof = kin::dof(m, data);
        a.warnings.push_back(
            s.assembled
                ? fmt::format("cannot reach input {:.6g} {} from the drawn configuration ({:.6g} {}): dead point at {:.6f} {}",
                              shown_input(mech, driver, value), unit, shown_input(mech, driver, drawn), unit,
                              shown_input(mech, driver, s.dead_points.front().input), unit)
                : fmt::format("cannot assemble at the drawn input {:.6g} {}: {}", shown_input(mech, driver, drawn), unit, s.message));
        return a;
      }
      data.q = s.samples.back().q;
    }
    const kin::PositionReport r = kin::solve_at(m, data, driver, value);
    a.dof = kin::dof(m, data);
    if (!r.converged || r.singular) {
      a.warnings.push_back(fmt::format("cannot analyse at input {:.6g} {}: {}", shown_input(mech, driver, value), unit,
                                       r.converged ? "singular Jacobian (dead point)" : r.message));
      return a;
    }
    a.positions.push_back(describe_position(mech, data, driver, value));
    // From the velocities per unit input speed, so quasi-static models (speed 0) have them too.
    const Eigen::VectorXd v = kin::input_sensitivity(m, data, driver);
    for (int b = 0; b < static_cast<int>(m.bodies().size()); ++b)
      a.instant_centres.push_back(v.size() ? kin::instant_centre(data.q, v, b) : std::nullopt);
    return a;
  }
  kin::SweepOptions o;
  o.driver = driver;
  o.start = range->start;
  o.end = range->end;
  o.step = range->step;
  o.outputs = mech.outputs;
  o.min_step = 1e-9 * std::max(1.0, std::abs(range->end - range->start));
  const kin::SweepResult s = kin::sweep(m, data, o);
  if (!s.assembled) {
    kin::solve_position(m, data, 0.0);
    a.dof = kin::dof(m, data);
    a.warnings.push_back(fmt::format("cannot assemble at the sweep's start {:.6g} {}: {}",
                                     shown_input(mech, driver, range->start), unit, s.message));
    return a;
  }
  io::Progress progress("kin", s.samples.size());
  for (const kin::SweepSample& sample : s.samples) {
    progress.update(a.positions.size());
    data.q = sample.q;
    data.inputs(driver) = sample.input;
    kin::solve_at(m, data, driver, sample.input);
    a.positions.push_back(describe_position(mech, data, driver, sample.input));
  }
  data.q = s.samples.front().q;
  data.inputs(driver) = s.samples.front().input;
  kin::solve_position(m, data, 0.0);
  a.dof = kin::dof(m, data);
  a.dead_points = s.dead_points;
  a.extremes = s.extremes;
  for (const kin::DeadPoint& d : s.dead_points)
    a.warnings.push_back(fmt::format("dead point at input {:.6f} {}: the driver cannot move the mechanism past it; "
                                     "the sweep stops there instead of jumping to another assembly branch",
                                     shown_input(mech, driver, d.input), unit));
  return a;
}

io::Report build_report(const mechanism::Mechanism& mech, const KinAnalysis& a) {
  const kin::Model& m = mech.model;
  const int driver = a.driver;
  io::Report rep;
  rep.title = "Mechanism: " + mech.title;
  rep.warnings = a.warnings;
  auto& j = rep.json;
  j["mechanism"] = mech.title;
  j["dof"] = a.dof.dof;
  j["gruebler"] = a.dof.gruebler;
  j["gruebler_count"] = a.dof.gruebler_count;
  j["redundant"] = a.dof.redundant;
  j["redundant_constraints"] = a.dof.redundant_rows;
  j["driver"] = mech.drivers[static_cast<std::size_t>(driver)].name;
  rep.notes.push_back("Gruebler-Kutzbach: " + a.dof.gruebler_count);
  rep.notes.push_back(fmt::format("Rank of Phi_q: {} of {} constraint equations -> {} degree(s) of freedom; {} redundant",
                                  a.dof.rank, a.dof.constraint_equations, a.dof.dof, a.dof.redundant));
  if (a.dof.redundant > 0)
    rep.notes.push_back("Redundant constraint rows: " + fmt::format("{}", fmt::join(a.dof.redundant_rows, ", ")));
  if (const auto fb = kin::find_four_bar(m)) {
    const kin::GrashofResult g = kin::grashof(fb->ground, fb->crank_length, fb->coupler_length, fb->rocker_length);
    j["grashof"] = g.text;
    rep.notes.push_back("Four-bar: " + g.text);
  }

  // Positions table.
  io::Table t;
  t.title = a.single ? "Position, velocity and acceleration" : "Sweep";
  const std::string unit = input_unit(mech, driver);
  t.header.push_back(fmt::format("{} [{}]", mech.drivers[static_cast<std::size_t>(driver)].name, unit));
  for (const kin::Body& b : m.bodies()) t.header.push_back(b.name + " [deg]");
  for (const kin::Output& o : mech.outputs) {
    t.header.push_back(fmt::format("{} [{}]", o.name, output_unit(o)));
    t.header.push_back(fmt::format("d{}/d(input) [{}]", o.name, ratio_unit(mech, driver, o)));
  }
  const bool four_bar = !a.positions.empty() && a.positions.front().transmission_angle;
  if (four_bar) t.header.push_back("mu [deg]");
  const bool forces = !a.positions.empty() && a.positions.front().forces;
  if (forces) t.header.push_back(angular(mech, driver) ? "T [N m]" : "F [N]");
  nlohmann::json positions = nlohmann::json::array();
  for (const KinPosition& p : a.positions) {
    std::vector<std::string> row{io::fixed(shown_input(mech, driver, p.input), 4)};
    for (int b = 0; b < static_cast<int>(m.bodies().size()); ++b) row.push_back(io::fixed(p.q(3 * b + 2) * kRadToDeg, 4));
    nlohmann::json pj;
    pj[input_key(mech, driver)] = shown_input(mech, driver, p.input);
    pj["q"] = coordinates_json(m, p.q, 0);
    pj["qd"] = coordinates_json(m, p.qd, 1);
    pj["qdd"] = coordinates_json(m, p.qdd, 2);
    nlohmann::json outs = nlohmann::json::object();
    for (std::size_t k = 0; k < mech.outputs.size(); ++k) {
      const kin::Output& o = mech.outputs[k];
      const double rate_scale = o.angular() ? 1.0 : 1000.0;
      const std::string u = output_unit(o);
      outs[o.name + "_" + u] = shown_output(o, p.outputs[k].value);
      const kin::OutputUnits units = kin::output_units(o);
      if (*units.rate) outs[o.name + "_rate_" + units.rate] = p.outputs[k].rate * rate_scale;
      if (*units.acceleration) outs[o.name + "_acceleration_" + units.acceleration] = p.outputs[k].acceleration * rate_scale;
      // Ratio in the units shown: output unit per input unit.
      const double ratio = p.output_ratios[k] * (o.angular() ? 1.0 : 1000.0) / (angular(mech, driver) ? 1.0 : 1000.0);
      // An acceleration magnitude has no velocity ratio (kin::output_derivative gives NaN).
      const bool has_ratio = o.kind != kin::OutputKind::point_acceleration;
      outs[o.name + "_ratio"] = has_ratio ? nlohmann::json(ratio) : nlohmann::json(nullptr);
      row.push_back(io::fixed(shown_output(o, p.outputs[k].value), 4));
      row.push_back(has_ratio ? io::fixed(ratio, 5) : "-");
    }
    pj["outputs"] = outs;
    if (p.transmission_angle) {
      pj["transmission_angle_deg"] = *p.transmission_angle * kRadToDeg;
      row.push_back(io::fixed(*p.transmission_angle * kRadToDeg, 2));
    }
    if (p.forces) {
      const double effort = p.forces->effort_virtual_power[static_cast<std::size_t>(driver)];
      pj[effort_key(mech, driver)] = effort;
      pj[angular(mech, driver) ? "driving_torque_lagrange_Nm" : "driving_force_lagrange_N"] =
          p.forces->effort_lagrange[static_cast<std::size_t>(driver)];
      row.push_back(io::fixed(effort, 4));
      nlohmann::json reactions = nlohmann::json::array();
      for (const kin::ConstraintReaction& r : p.forces->reactions) reactions.push_back(reaction_json(m, r));
      pj["reactions"] = reactions;
      nlohmann::json members = nlohmann::json::array();
      for (const kin::TwoForceMember& tf : p.forces->two_force_members)
        members.push_back({{"link", tf.name}, {"axial_force_N", tf.axial_force}, {"state", tf.tension() ? "tension" : "compression"}});
      pj["two_force_members"] = members;
      if (!p.forces->determinate) pj["reactions_note"] = "redundant constraints: reactions are statically indeterminate (minimum-norm values shown)";
      add_force_details_json(pj, m, *p.forces, driver, angular(mech, driver));
    }
    t.add_row(std::move(row));
    positions.push_back(std::move(pj));
  }
  j["positions"] = positions;
  rep.tables.push_back(std::move(t));

  // Dead points and limit positions.
  nlohmann::json dead = nlohmann::json::array();
  if (!a.dead_points.empty()) {
    io::Table d{"Dead points", {fmt::format("input [{}]", unit)}, {}};
    for (int b = 0; b < static_cast<int>(m.bodies().size()); ++b) d.header.push_back(m.bodies()[static_cast<std::size_t>(b)].name + " [deg]");
    for (const kin::DeadPoint& dp : a.dead_points) {
      std::vector<std::string> row{io::fixed(shown_input(mech, driver, dp.input), 6)};
      for (int b = 0; b < static_cast<int>(m.bodies().size()); ++b) row.push_back(io::fixed(dp.q(3 * b + 2) * kRadToDeg, 4));
      d.add_row(row);
      dead.push_back({{input_key(mech, driver), shown_input(mech, driver, dp.input)}, {"q", coordinates_json(m, dp.q, 0)},
                      {"description", dp.description}});
    }
    rep.tables.push_back(std::move(d));
  }
  j["dead_points"] = dead;
  nlohmann::json extremes = nlohmann::json::array();
  if (!a.extremes.empty()) {
    io::Table e{"Limit positions of the outputs", {"output", "extreme", fmt::format("input [{}]", unit), "value"}, {}};
    for (const kin::OutputExtreme& x : a.extremes) {
      const kin::Output& o = mech.outputs[static_cast<std::size_t>(x.output)];
      e.add_row({o.name, x.maximum ? "max" : "min", io::fixed(shown_input(mech, driver, x.input), 6),
                 io::fixed(shown_output(o, x.value), 4) + " " + output_unit(o)});
      nlohmann::json ratios = nlohmann::json::object();
      for (int i = 0; i < x.dq.size(); ++i)
        if (i % 3 == 2) ratios[m.bodies()[static_cast<std::size_t>(i / 3)].name + ".omega_ratio"] = x.dq(i) / (angular(mech, driver) ? 1.0 : 1000.0);
      extremes.push_back({{"output", o.name}, {"kind", x.maximum ? "max" : "min"},
                          {input_key(mech, driver), shown_input(mech, driver, x.input)},
                          {"value_" + output_unit(o), shown_output(o, x.value)}, {"q", coordinates_json(m, x.q, 0)},
                          {"angular_velocity_ratios", ratios}});
    }
    rep.tables.push_back(std::move(e));
  }
  j["limit_positions"] = extremes;

  // Single position: reactions and instant centres.
  if (a.single && !a.positions.empty()) {
    const KinPosition& p = a.positions.front();
    if (p.forces) {
      io::Table r{"Joint reactions (force on the first link of the joint)", {"joint", "kind", "on", "Fx [N]", "Fy [N]", "|F| [N]"}, {}};
      for (const kin::ConstraintReaction& c : p.forces->reactions)
        r.add_row({c.name, c.kind, m.body_name(c.body), io::fixed(c.force.x(), 3), io::fixed(c.force.y(), 3), io::fixed(c.force.norm(), 3)});
      rep.tables.push_back(std::move(r));
      if (auto elements = element_reaction_table(*p.forces)) rep.tables.push_back(std::move(*elements));
      add_force_details_report(rep, m, p, driver, angular(mech, driver));
      if (!p.forces->two_force_members.empty()) {
        io::Table tf{"Two-force members", {"link", "axial force [N]", "state"}, {}};
        for (const kin::TwoForceMember& x : p.forces->two_force_members)
          tf.add_row({x.name, io::fixed(std::abs(x.axial_force), 3), x.tension() ? "tension" : "compression"});
        rep.tables.push_back(std::move(tf));
      }
      const double vp = p.forces->effort_virtual_power[static_cast<std::size_t>(driver)];
      const double lg = p.forces->effort_lagrange[static_cast<std::size_t>(driver)];
      rep.notes.push_back(fmt::format("Driving {}: {:.4f} {} by virtual power, {:.4f} {} by Lagrange multipliers",
                                      angular(mech, driver) ? "torque" : "force", vp, angular(mech, driver) ? "N m" : "N",
                                      lg, angular(mech, driver) ? "N m" : "N"));
    }
    io::Table ic{"Instant centres relative to ground", {"link", "x [mm]", "y [mm]"}, {}};
    nlohmann::json icj = nlohmann::json::object();
    for (std::size_t b = 0; b < a.instant_centres.size(); ++b) {
      const auto& c = a.instant_centres[b];
      ic.add_row({m.bodies()[b].name, c ? io::fixed(c->x() * 1000, 3) : "at infinity", c ? io::fixed(c->y() * 1000, 3) : "(translation)"});
      icj[m.bodies()[b].name] = c ? nlohmann::json{{"x_mm", c->x() * 1000}, {"y_mm", c->y() * 1000}} : nlohmann::json(nullptr);
    }
    rep.tables.push_back(std::move(ic));
    j["instant_centres"] = icj;
  }
  return rep;
}

std::string plot_svg(const mechanism::Mechanism& mech, const KinAnalysis& a) {
  io::Plot plot;
  plot.title = mech.title;
  plot.x_label = fmt::format("{} [{}]", mech.drivers[static_cast<std::size_t>(a.driver)].name, input_unit(mech, a.driver));
  std::vector<double> x;
  for (const KinPosition& p : a.positions) x.push_back(shown_input(mech, a.driver, p.input));
  for (std::size_t k = 0; k < mech.outputs.size(); ++k) {
    const kin::Output& o = mech.outputs[k];
    io::PlotPanel panel;
    panel.y_label = fmt::format("{} [{}]", o.name, output_unit(o));
    io::Series s{o.name, x, {}, {}};
    for (const KinPosition& p : a.positions) s.y.push_back(shown_output(o, p.outputs[k].value));
    panel.series.push_back(s);
    plot.panels.push_back(panel);
  }
  if (mech.outputs.empty()) {
    io::PlotPanel panel;
    panel.y_label = "link angles [deg]";
    for (std::size_t b = 0; b < mech.model.bodies().size(); ++b) {
      io::Series s{mech.model.bodies()[b].name, x, {}, {}};
      for (const KinPosition& p : a.positions) s.y.push_back(p.q(3 * static_cast<int>(b) + 2) * kRadToDeg);
      panel.series.push_back(s);
    }
    plot.panels.push_back(panel);
  }
  if (!a.positions.empty() && a.positions.front().transmission_angle) {
    io::PlotPanel panel{"transmission angle [deg]", {{"mu", x, {}, {}}}, {}};
    for (const KinPosition& p : a.positions) panel.series[0].y.push_back(*p.transmission_angle * kRadToDeg);
    plot.panels.push_back(panel);
  }
  if (!a.positions.empty() && a.positions.front().forces) {
    const bool ang = angular(mech, a.driver);
    io::PlotPanel panel{ang ? "driving torque [N m]" : "driving force [N]", {{ang ? "T" : "F", x, {}, {}}}, {}};
    for (const KinPosition& p : a.positions)
      panel.series[0].y.push_back(p.forces->effort_virtual_power[static_cast<std::size_t>(a.driver)]);
    plot.panels.push_back(panel);
  }
  return io::to_svg(plot);
}

}  // namespace

int run_kin_command(plugin::CommandContext& context) {
  io::po::options_description desc("gearkit kin options");
  desc.add_options()("file", io::po::value<std::string>()->value_name("FILE.yaml"), "mechanism model (see docs/kin.md)")(
      "at", io::po::value<std::string>()->value_name("VALUE"), "analyse one position at this input (deg or mm by default)")(
      "sweep", io::po::value<std::string>()->value_name("START:END:STEP"), "sweep the driver over a range")(
      "driver", io::po::value<std::string>()->value_name("NAME"), "which driver --at/--sweep move (default: the first)")(
      "outputs", io::po::value<std::string>()->value_name("A,B,..."), "only these named outputs of the model")(
      "plot", io::po::value<std::string>()->value_name("FILE.svg"), "SVG plot of the outputs against the input")(
      "animate", io::po::value<std::string>()->value_name("FILE.svg"), "animated SVG of the mechanism through the sweep")(
      "equations", io::po::bool_switch(), "constraint equations, Jacobian, velocity and acceleration equations and "
      "velocity ratios in the coordinates of the file's equations: section (docs/kin.md)")(
      "example", io::po::value<std::string>()->value_name("chain:N"),
      "write a generated mechanism file instead of analysing one (chain:N: N four-bar loops)");
  io::add_common_options(desc);
  io::po::positional_options_description positional;
  positional.add("file", 1);
  io::po::variables_map vm;
  const char* usage =
      "gearkit kin FILE.yaml [--at VALUE | --sweep START:END:STEP] [--driver NAME] [--outputs A,B] [--plot FILE] "
      "[--animate FILE] [--equations] [--format text|json|csv|md]";
  if (!io::parse_command_line(context.args, desc, positional, vm, usage, context.out)) return 0;
  const io::CommonOptions common = io::common_options(vm);
  if (vm.count("example")) {
    if (vm.count("file")) io::fail_option("--example", "expected no mechanism file with --example, found one");
    io::OutputSet outputs(context.out);
    outputs.add("--output", common.output, example_mechanism_yaml(vm["example"].as<std::string>()));
    outputs.commit();
    return 0;
  }
  if (!vm.count("file")) throw io::InputError(fmt::format("expected the FILE argument, found none; usage: {}", usage));
  if (vm.count("at") && vm.count("sweep")) io::fail_option("--at", "expected either --at or --sweep, found both");

  const std::string file = vm["file"].as<std::string>();
  mechanism::Mechanism mech =
      mechanism::load_mechanism(file, [&context](std::string_view type) { return context.host.find_element_type(type); });
  const kin::Model& m = mech.model;
  if (mech.drivers.empty())
    io::fail_at({file, 0, 0}, "expected at least one driver (an input angle or slider displacement), found none");

  int driver = 0;
  if (vm.count("driver")) {
    const std::string name = vm["driver"].as<std::string>();
    driver = -1;
    for (std::size_t k = 0; k < mech.drivers.size(); ++k)
      if (mech.drivers[k].name == name) driver = static_cast<int>(k);
    if (driver < 0) io::fail_option("--driver", fmt::format("expected the name of a driver of the model, found {}", io::quote(name)));
  }
  if (vm.count("outputs")) {
    std::vector<kin::Output> chosen;
    std::stringstream ss(vm["outputs"].as<std::string>());
    for (std::string name; std::getline(ss, name, ',');) {
      auto it = std::find_if(mech.outputs.begin(), mech.outputs.end(), [&](const kin::Output& o) { return o.name == name; });
      if (it == mech.outputs.end()) io::fail_option("--outputs", fmt::format("expected names of outputs defined in the model, found {}", io::quote(name)));
      chosen.push_back(*it);
    }
    mech.outputs = chosen;
  }
  const io::Quantity q = angular(mech, driver) ? io::Quantity::angle : io::Quantity::length;
  const std::string unit = input_unit(mech, driver);
  std::optional<double> at;
  mechanism::DriverRange range{};
  bool sweeping = mech.drivers[static_cast<std::size_t>(driver)].range.has_value();
  if (sweeping) range = *mech.drivers[static_cast<std::size_t>(driver)].range;
  if (vm.count("at")) {
    try {
      at = io::parse_quantity_si(vm["at"].as<std::string>(), q, unit);
    } catch (const std::exception& e) {
      io::fail_option("--at", e.what());
    }
    sweeping = false;
  }
  if (vm.count("sweep")) {
    range = parse_sweep(vm["sweep"].as<std::string>(), q, unit);
    sweeping = true;
  }
  if (sweeping) check_sweep_work(m, range, vm.count("sweep") ? "option '--sweep'" : file);

  // Mobility against the number of drivers: a model must be exactly driven.
  kin::Data data(m);
  {
    kin::Data probe(m);
    kin::solve_position(m, probe, 0.0);
    const kin::DofReport d = kin::dof(m, probe);
    if (d.drivers < d.dof)
      io::fail_at({file, 0, 0}, fmt::format("under-driven: the mechanism has {} degree(s) of freedom ({}; rank of Phi_q {}) "
                                            "but {} driver(s)", d.dof, d.gruebler_count, d.rank, d.drivers));
    if (d.drivers > d.dof)
      io::fail_at({file, 0, 0}, fmt::format("over-constrained: the mechanism has {} degree(s) of freedom ({}; rank of Phi_q {}) "
                                            "but {} driver(s)", d.dof, d.gruebler_count, d.rank, d.drivers));
  }
  const KinAnalysis analysis = analyse(mech, data, driver, at, sweeping ? &range : nullptr);
  io::Report report = build_report(mech, analysis);
  if (vm["equations"].as<bool>()) add_equations_section_from_module(report, mech, analysis, common.format);
  io::OutputSet outputs(context.out);  // every file committed together, after the report renders
  if (vm.count("plot")) {
    if (analysis.positions.empty()) report.warnings.push_back("no positions to plot; --plot file not written");
    else outputs.add("--plot", vm["plot"].as<std::string>(), plot_svg(mech, analysis));
  }
  if (vm.count("animate")) {
    if (analysis.positions.empty()) report.warnings.push_back("no positions to animate; --animate file not written");
    else outputs.add("--animate", vm["animate"].as<std::string>(), animation_svg(mech, analysis));
  }
  return io::emit(report, common, outputs);
}

}  // namespace gearkit::cli
