// `gearkit kin`: the report's head, rows and tail (kin_report.hpp).
#include "kin_report.hpp"
#include "kin_reactions.hpp"
#include "kin_units.hpp"

#include <gearkit/kin/fourbar.hpp>

#include <fmt/format.h>

#include <cmath>

namespace gearkit::cli {

namespace {

constexpr const char* kCoordinateNames[3][3] = {{"x_mm", "y_mm", "angle_deg"},
                                                {"vx_mm_s", "vy_mm_s", "omega_rad_s"},
                                                {"ax_mm_s2", "ay_mm_s2", "alpha_rad_s2"}};

// A coordinate as shown: lengths in mm, angles in deg (positions) or rad/s, rad/s^2.
double shown_coordinate(int index, int order, double v) {
  return index % 3 < 2 ? v * 1000.0 : (order == 0 ? v * kRadToDeg : v);
}

nlohmann::json coordinates_object(const kin::Model& m, const Eigen::VectorXd& v, int order) {
  nlohmann::json j = nlohmann::json::object();
  for (int i = 0; i < v.size(); ++i)
    j[m.bodies()[static_cast<std::size_t>(i / 3)].name + "." + kCoordinateNames[order][i % 3]] = shown_coordinate(i, order, v(i));
  return j;
}

// Below this an axial force is round-off, neither tension nor compression [N].
constexpr double kUnloaded = 1e-9;

std::string member_state(double axial_force) {
  if (std::abs(axial_force) <= kUnloaded) return "unloaded";
  return axial_force > 0 ? "tension" : "compression";
}

}  // namespace

io::Report kin_report_head(const mechanism::Mechanism& mech, const kin::DofReport& dof, int driver) {
  io::Report rep;
  rep.title = "Mechanism: " + mech.title;
  auto& j = rep.json;
  j["mechanism"] = mech.title;
  j["dof"] = dof.dof;
  j["gruebler"] = dof.gruebler;
  j["gruebler_count"] = dof.gruebler_count;
  j["redundant"] = dof.redundant;
  j["redundant_constraints"] = dof.redundant_rows;
  j["driver"] = mech.drivers[static_cast<std::size_t>(driver)].name;
  rep.notes.push_back("Gruebler-Kutzbach: " + dof.gruebler_count);
  rep.notes.push_back(fmt::format("Rank of Phi_q: {} of {} constraint equations -> {} degree(s) of freedom; {} redundant",
                                  dof.rank, dof.constraint_equations, dof.dof, dof.redundant));
  if (dof.redundant > 0)
    rep.notes.push_back("Redundant constraint rows: " + fmt::format("{}", fmt::join(dof.redundant_rows, ", ")));
  if (const auto fb = kin::find_four_bar(mech.model)) {
    const kin::GrashofResult g = kin::grashof(fb->ground, fb->crank_length, fb->coupler_length, fb->rocker_length);
    j["grashof"] = g.text;
    rep.notes.push_back("Four-bar: " + g.text);
  }
  return rep;
}

KinRows::KinRows(const mechanism::Mechanism& mech, int driver, bool transmission, bool forces, bool single)
    : mech_(mech), driver_(driver) {
  const kin::Model& m = mech.model;
  const std::string& driver_name = mech.drivers[static_cast<std::size_t>(driver)].name;
  table_.title = single ? "Position, velocity and acceleration" : "Sweep";
  table_.header.push_back(fmt::format("{} [{}]", driver_name, input_unit(mech, driver)));
  for (const kin::Body& b : m.bodies()) table_.header.push_back(b.name + " [deg]");
  for (const kin::Output& o : mech.outputs) {
    // An output named like the driver repeats the input column (issue 13 item 4): JSON only.
    output_in_table_.push_back(o.name != driver_name);
    if (!output_in_table_.back()) continue;
    table_.header.push_back(fmt::format("{} [{}]", o.name, output_unit(o)));
    table_.header.push_back(fmt::format("d{}/d(input) [{}]", o.name, ratio_unit(mech, driver, o)));
  }
  if (transmission) table_.header.push_back("mu [deg]");
  if (forces) table_.header.push_back(angular(mech, driver) ? "T [N m]" : "F [N]");
  for (int order = 0; order < 3; ++order)
    for (int i = 0; i < m.coordinates(); ++i)
      coordinate_keys_[order].emplace_back(m.bodies()[static_cast<std::size_t>(i / 3)].name + "." + kCoordinateNames[order][i % 3]);
  for (const kin::Output& o : mech.outputs) {
    // A speed output has no acceleration key, an acceleration magnitude neither rate nor ratio.
    const kin::OutputUnits u = kin::output_units(o);
    output_keys_.push_back({io::JsonKey(o.name + "_" + u.value), io::JsonKey(*u.rate ? o.name + "_rate_" + u.rate : ""),
                            io::JsonKey(*u.acceleration ? o.name + "_acceleration_" + u.acceleration : ""),
                            io::JsonKey(o.name + "_ratio"), *u.rate != 0, *u.acceleration != 0,
                            o.kind != kin::OutputKind::point_acceleration});
  }
  input_key_ = io::JsonKey(input_key(mech, driver));
  effort_key_ = io::JsonKey(effort_key(mech, driver));
  lagrange_key_ = io::JsonKey(angular(mech, driver) ? "driving_torque_lagrange_Nm" : "driving_force_lagrange_N");
}

void KinRows::cells(const KinPosition& p, std::vector<std::string>& row) const {
  // The cells' strings are reused from row to row: no allocation per position.
  std::size_t n = 0;
  const auto cell = [&](double v, int digits) {
    if (n == row.size()) row.emplace_back();
    row[n].clear();
    io::append_fixed(row[n++], v, digits);
  };
  cell(shown_input(mech_, driver_, p.input), 4);
  for (std::size_t b = 0; b < mech_.model.bodies().size(); ++b) cell(p.q(3 * static_cast<int>(b) + 2) * kRadToDeg, 4);
  for (std::size_t k = 0; k < mech_.outputs.size(); ++k) {
    if (!output_in_table_[k]) continue;
    const kin::Output& o = mech_.outputs[k];
    cell(shown_output(o, p.outputs[k].value), 4);
    if (output_keys_[k].has_ratio) {
      cell(shown_ratio(mech_, driver_, o, p.output_ratios[k]), 5);
    } else {
      if (n == row.size()) row.emplace_back();
      row[n++] = "-";
    }
  }
  if (p.transmission_angle) cell(*p.transmission_angle * kRadToDeg, 2);
  if (p.forces) {
    const double effort = p.forces->effort_virtual_power[static_cast<std::size_t>(driver_)];
    if (!std::isfinite(effort) && p.forces->friction && p.forces->friction->forward.wedged) {
      if (n == row.size()) row.emplace_back();
      row[n++] = "wedged";  // no finite effort moves it (a warning says so); null in JSON
    } else {
      cell(effort, 4);
    }
  }
  row.resize(n);
}

void KinRows::coordinates_json(const Eigen::VectorXd& v, int order, io::JsonWriter& w) const {
  w.begin_object();
  for (int i = 0; i < v.size(); ++i) {
    w.key(coordinate_keys_[order][static_cast<std::size_t>(i)]);
    w.value(shown_coordinate(i, order, v(i)));
  }
  w.end_object();
}

void KinRows::forces_json(const KinPosition& p, io::JsonWriter& w) const {
  const kin::ForceAnalysis& f = *p.forces;
  // A sense that locks by friction has no finite effort, nor has the Lagrange form at a change
  // point (singular Phi_q, indeterminate multipliers): null, and no "not finite" warning.
  const auto effort = [&](double v) {
    if (std::isfinite(v) || (!f.friction && f.determinate)) w.value(v);
    else w.null();
  };
  w.key(effort_key_);
  effort(f.effort_virtual_power[static_cast<std::size_t>(driver_)]);
  w.key(lagrange_key_);
  effort(f.effort_lagrange[static_cast<std::size_t>(driver_)]);
  static const io::JsonKey reactions("reactions"), members("two_force_members");
  w.key(reactions);
  w.begin_array();
  for (const kin::ConstraintReaction& r : f.reactions) write_reaction(w, mech_.model, r);
  w.end_array();
  w.key(members);
  w.begin_array();
  for (const kin::TwoForceMember& tf : f.two_force_members) {
    w.begin_object();
    w.key("link");
    w.value(tf.name);
    w.key("axial_force_N");
    w.value(tf.axial_force);
    w.key("state");
    w.value(member_state(tf.axial_force));
    w.end_object();
  }
  w.end_array();
  if (!f.determinate) {
    w.key("reactions_note");
    w.value("redundant constraints: reactions are statically indeterminate (minimum-norm values shown)");
  }
  if (f.friction || !f.unknown_loads.empty() || !f.warnings.empty()) {
    const nlohmann::json details = force_details_json(mech_.model, f, driver_, angular(mech_, driver_));
    for (const auto& [key, value] : details.items()) {
      w.key(key);
      w.raw_value(value.dump());
    }
  }
}

void KinRows::json(const KinPosition& p, io::JsonWriter& w) const {
  static const io::JsonKey q("q"), qd("qd"), qdd("qdd"), outputs("outputs"), mu("transmission_angle_deg");
  w.begin_object();
  w.key(input_key_);
  w.value(shown_input(mech_, driver_, p.input));
  w.key(q);
  coordinates_json(p.q, 0, w);
  w.key(qd);
  coordinates_json(p.qd, 1, w);
  w.key(qdd);
  coordinates_json(p.qdd, 2, w);
  w.key(outputs);
  w.begin_object();
  for (std::size_t k = 0; k < mech_.outputs.size(); ++k) {
    const kin::Output& o = mech_.outputs[k];
    const double rate_scale = o.angular() ? 1.0 : 1000.0;
    w.key(output_keys_[k].value);
    w.value(shown_output(o, p.outputs[k].value));
    if (output_keys_[k].has_rate) {
      w.key(output_keys_[k].rate);
      // A speed's rate where the point stands still is undefined: null, which KinWriter's
      // warning explains (no "not finite" warning of its own).
      if (o.kind == kin::OutputKind::point_speed && !std::isfinite(p.outputs[k].rate)) w.null();
      else w.value(p.outputs[k].rate * rate_scale);
    }
    if (output_keys_[k].has_acceleration) {
      w.key(output_keys_[k].acceleration);
      w.value(p.outputs[k].acceleration * rate_scale);
    }
    w.key(output_keys_[k].ratio);
    if (output_keys_[k].has_ratio) w.value(shown_ratio(mech_, driver_, o, p.output_ratios[k]));
    else w.null();
  }
  w.end_object();
  if (p.transmission_angle) {
    w.key(mu);
    w.value(*p.transmission_angle * kRadToDeg);
  }
  if (p.on_change_point) {  // says why the Lagrange effort is null and the reactions are absent
    w.key("on_change_point");
    w.value(true);
  }
  if (p.forces) forces_json(p, w);
  w.end_object();
}

namespace {

void dead_points_section(const mechanism::Mechanism& mech, const KinAnalysis& a, io::Report& rep) {
  const kin::Model& m = mech.model;
  nlohmann::json dead = nlohmann::json::array();
  if (!a.dead_points.empty()) {
    // The input column is named after its driver: a link called "input" must not repeat it.
    io::Table d{"Dead points", {fmt::format("{} [{}]", mech.drivers[static_cast<std::size_t>(a.driver)].name, input_unit(mech, a.driver))}, {}};
    for (const kin::Body& b : m.bodies()) d.header.push_back(b.name + " [deg]");
    for (const kin::DeadPoint& dp : a.dead_points) {
      std::vector<std::string> row{io::fixed(shown_input(mech, a.driver, dp.input), 6)};
      for (int b = 0; b < static_cast<int>(m.bodies().size()); ++b) row.push_back(io::fixed(dp.q(3 * b + 2) * kRadToDeg, 4));
      d.add_row(row);
      dead.push_back({{input_key(mech, a.driver), shown_input(mech, a.driver, dp.input)}, {"q", coordinates_object(m, dp.q, 0)},
                      {"description", dp.description}});
    }
    rep.tables.push_back(std::move(d));
  }
  rep.json["dead_points"] = dead;
}

// Bifurcations crossed: where, and which branch the sweep took (the warnings say it in words).
void change_points_section(const mechanism::Mechanism& mech, const KinAnalysis& a, io::Report& rep) {
  nlohmann::json changes = nlohmann::json::array();
  for (const kin::ChangePoint& c : a.change_points)
    changes.push_back({{input_key(mech, a.driver), shown_input(mech, a.driver, c.input)},
                       {"q", coordinates_object(mech.model, c.q, 0)},
                       {"branch", c.switched ? "switched" : "continued"},
                       {"bifurcation", c.bifurcation}});
  rep.json["change_points"] = changes;
}

void limit_positions_section(const mechanism::Mechanism& mech, const KinAnalysis& a, io::Report& rep) {
  const kin::Model& m = mech.model;
  const int driver = a.driver;
  nlohmann::json extremes = nlohmann::json::array();
  if (!a.extremes.empty()) {
    io::Table e{"Limit positions of the outputs", {"output", "extreme", fmt::format("input [{}]", input_unit(mech, driver)), "value"}, {}};
    for (const kin::OutputExtreme& x : a.extremes) {
      const kin::Output& o = mech.outputs[static_cast<std::size_t>(x.output)];
      e.add_row({o.name, x.maximum ? "max" : "min", io::fixed(shown_input(mech, driver, x.input), 6),
                 io::fixed(shown_output(o, x.value), 4) + " " + output_unit(o)});
      nlohmann::json ratios = nlohmann::json::object();
      for (int i = 2; i < x.dq.size(); i += 3)
        ratios[m.bodies()[static_cast<std::size_t>(i / 3)].name + ".omega_ratio"] = x.dq(i) / (angular(mech, driver) ? 1.0 : 1000.0);
      extremes.push_back({{"output", o.name}, {"kind", x.maximum ? "max" : "min"},
                          {input_key(mech, driver), shown_input(mech, driver, x.input)},
                          {"value_" + output_unit(o), shown_output(o, x.value)}, {"q", coordinates_object(m, x.q, 0)},
                          {"angular_velocity_ratios", ratios}});
    }
    rep.tables.push_back(std::move(e));
  }
  rep.json["limit_positions"] = extremes;
}

void reactions_section(const mechanism::Mechanism& mech, const KinPosition& p, int driver, io::Report& rep) {
  const kin::Model& m = mech.model;
  if (p.on_change_point) {  // Phi_q singular: no multipliers, no reactions, no free bodies
    const bool ang = angular(mech, driver);
    rep.notes.push_back(fmt::format("Driving {}: {:.4f} {} by virtual power along the branch followed (on a change point "
                                    "the reactions are statically indeterminate and not given)",
                                    ang ? "torque" : "force", p.forces->effort_virtual_power[static_cast<std::size_t>(driver)],
                                    ang ? "N m" : "N"));
    return;
  }
  io::Table r{"Joint reactions (force on the first link of the joint)", {"joint", "kind", "on", "Fx [N]", "Fy [N]", "|F| [N]"}, {}};
  for (const kin::ConstraintReaction& c : p.forces->reactions)
    r.add_row({c.name, c.kind, m.body_name(c.body), io::fixed(c.force.x(), 3), io::fixed(c.force.y(), 3), io::fixed(c.force.norm(), 3)});
  rep.tables.push_back(std::move(r));
  if (auto elements = element_reaction_table(*p.forces)) rep.tables.push_back(std::move(*elements));
  if (!p.forces->two_force_members.empty()) {
    io::Table tf{"Two-force members", {"link", "axial force [N]", "state"}, {}};
    for (const kin::TwoForceMember& x : p.forces->two_force_members)
      tf.add_row({x.name, io::fixed(std::abs(x.axial_force), 3), member_state(x.axial_force)});
    rep.tables.push_back(std::move(tf));
  }
  const double vp = p.forces->effort_virtual_power[static_cast<std::size_t>(driver)];
  const double lg = p.forces->effort_lagrange[static_cast<std::size_t>(driver)];
  const bool ang = angular(mech, driver);
  if (!std::isfinite(vp) && p.forces->friction && p.forces->friction->forward.wedged)
    rep.notes.push_back(fmt::format("Driving {}: none, friction wedges the mechanism in the analysed sense (see the warnings)",
                                    ang ? "torque" : "force"));
  else
    rep.notes.push_back(fmt::format("Driving {}: {:.4f} {} by virtual power, {:.4f} {} by Lagrange multipliers",
                                    ang ? "torque" : "force", vp, ang ? "N m" : "N", lg, ang ? "N m" : "N"));
  add_force_details_report(rep, m, p, driver, ang);
}

void instant_centres_section(const mechanism::Mechanism& mech, const KinAnalysis& a, io::Report& rep) {
  const kin::Model& m = mech.model;
  io::Table ic{"Instant centres relative to ground", {"link", "x [mm]", "y [mm]"}, {}};
  nlohmann::json icj = nlohmann::json::object();
  for (std::size_t b = 0; b < a.instant_centres.size(); ++b) {
    const auto& c = a.instant_centres[b];
    ic.add_row({m.bodies()[b].name, c ? io::fixed(c->x() * 1000, 3) : "at infinity", c ? io::fixed(c->y() * 1000, 3) : "(translation)"});
    icj[m.bodies()[b].name] = c ? nlohmann::json{{"x_mm", c->x() * 1000}, {"y_mm", c->y() * 1000}} : nlohmann::json(nullptr);
  }
  rep.tables.push_back(std::move(ic));
  rep.json["instant_centres"] = icj;
}

}  // namespace

io::Report kin_report_tail(const mechanism::Mechanism& mech, const KinAnalysis& a) {
  io::Report rep;
  rep.warnings = a.warnings;
  rep.notes = a.notes;
  dead_points_section(mech, a, rep);
  change_points_section(mech, a, rep);
  limit_positions_section(mech, a, rep);
  if (a.single && !a.positions.empty()) {
    if (a.positions.front().forces) reactions_section(mech, a.positions.front(), a.driver, rep);
    instant_centres_section(mech, a, rep);
  }
  return rep;
}

}  // namespace gearkit::cli
