#include "kin_reactions.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

namespace gearkit::cli {

namespace {

// A JSON key carries its unit: "F_n" in "N" -> "F_n_N", "T_2" in "N m" -> "T_2_Nm".
std::string key_with_unit(const kin::ReactionValue& v) {
  std::string unit;
  for (char c : v.unit)
    if (c != ' ' && c != '*') unit += c;
  return unit.empty() ? v.symbol : v.symbol + "_" + unit;
}

}  // namespace

void write_reaction(io::JsonWriter& w, const kin::Model& model, const kin::ConstraintReaction& r) {
  // Quoted once: a sweep writes these keys for every joint of every position.
  static const io::JsonKey joint("joint"), kind("kind"), on("on"), force("force_N");
  w.begin_object();
  w.key(joint);
  w.value(r.name);
  w.key(kind);
  w.value(r.kind);
  w.key(on);
  w.value(model.body_name(r.body));
  w.key(force);
  w.begin_array();
  w.value(r.force.x());
  w.value(r.force.y());
  w.end_array();
  if (r.moment != 0.0 || r.kind == "prismatic") {
    w.key("moment_Nm");
    w.value(r.moment);
  }
  if (!r.values.empty()) {
    w.key("values");
    w.begin_object();
    for (const kin::ReactionValue& v : r.values) {
      w.key(key_with_unit(v));
      w.value(v.value);
    }
    w.end_object();
  }
  w.end_object();
}

std::optional<io::Table> element_reaction_table(const kin::ForceAnalysis& forces) {
  io::Table t{"Element reactions", {"element", "kind", "quantity", "value", "unit", "meaning"}, {}};
  for (const kin::ConstraintReaction& r : forces.reactions)
    for (const kin::ReactionValue& v : r.values)
      t.add_row({r.name, r.kind, v.symbol, io::fixed(v.value, 3), v.unit, v.description});
  if (t.rows.empty()) return std::nullopt;
  return t;
}

namespace {

nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

double coefficient_of(const kin::Model& model, int constraint) {
  for (const kin::JointFriction& f : model.frictions())
    if (f.constraint == constraint) return f.mu;
  return 0.0;
}

nlohmann::json sense_json(const kin::Model& model, const kin::FrictionSense& s, int driver, const std::string& effort_key) {
  const auto k = static_cast<std::size_t>(driver);
  nlohmann::json j;
  j["self_locking"] = s.self_locking;
  j["wedged"] = s.wedged;
  j["wedging_factor"] = finite_or_null(s.wedging_factor);
  j[effort_key] = finite_or_null(s.effort[k]);
  j["efficiency"] = finite_or_null(s.efficiency[k]);
  j["critical_factor"] = finite_or_null(s.critical_factor);
  nlohmann::json critical = nlohmann::json::array();
  if (std::isfinite(s.critical_factor))
    for (const kin::JointFriction& f : model.frictions())
      critical.push_back({{"joint", model.constraints()[static_cast<std::size_t>(f.constraint)].name}, {"mu", f.mu * s.critical_factor}});
  j["critical_friction"] = critical;
  return j;
}

std::string effort_key_of(bool angular) { return angular ? "driving_torque_Nm" : "driving_force_N"; }

// One sense of motion in words: its effort and efficiency, or self-locking, and the wedging limit.
std::string sense_text(const kin::Model& model, const kin::FrictionSense& s, int driver, bool angular) {
  const auto k = static_cast<std::size_t>(driver);
  std::vector<std::string> mus;
  for (const kin::JointFriction& f : model.frictions())
    mus.push_back(fmt::format("{} {:.6g}", model.constraints()[static_cast<std::size_t>(f.constraint)].name, f.mu * s.critical_factor));
  const std::string limit = fmt::format("mu = {} ({:.6g} times the given coefficients)", fmt::join(mus, ", "), s.critical_factor);
  if (s.wedged) return "wedged (self-locking): no finite driving effort moves it; it wedges from " + limit;
  std::string text = fmt::format("driving {} {} {}", angular ? "torque" : "force", io::fixed(s.effort[k], 6), angular ? "N m" : "N");
  if (std::isfinite(s.efficiency[k])) text += fmt::format(", efficiency {}", io::fixed(s.efficiency[k], 4));
  if (s.self_locking) text += "; self-locking: the loads cannot drive it (efficiency <= 0) from " + limit;
  else text += std::isfinite(s.critical_factor) ? "; it would self-lock from " + limit : "; never self-locking at these forces";
  return text;
}

}  // namespace

nlohmann::json force_details_json(const kin::Model& model, const kin::ForceAnalysis& forces, int driver, bool angular) {
  const std::string effort_key = effort_key_of(angular);
  nlohmann::json position = nlohmann::json::object();
  if (!forces.unknown_loads.empty()) {
    nlohmann::json loads = nlohmann::json::array();
    for (const kin::UnknownLoad& u : forces.unknown_loads) {
      if (u.torque) loads.push_back({{"name", u.name}, {"torque_Nm", u.value}});
      else loads.push_back({{"name", u.name}, {"magnitude_N", u.value}, {"force_N", {u.force.x(), u.force.y()}}});
    }
    position["unknown_loads"] = loads;
  }
  if (!forces.warnings.empty()) position["force_warnings"] = forces.warnings;
  if (!forces.friction) return position;
  const kin::FrictionAnalysis& fa = *forces.friction;
  nlohmann::json joints = nlohmann::json::array();
  for (const kin::JointFrictionForce& jf : fa.joints) {
    const bool couple = jf.kind == "revolute";
    joints.push_back({{"joint", jf.name}, {"kind", jf.kind}, {"mu", coefficient_of(model, jf.constraint)},
                      {couple ? "pin_force_N" : "normal_N", jf.normal},
                      {couple ? "friction_couple_Nm" : "friction_N", jf.friction},
                      {couple ? "sliding_rad_s" : "sliding_m_s", jf.sliding}, {"power_W", jf.power}});
  }
  nlohmann::json f;
  f["joints"] = joints;
  f[angular ? "driving_torque_ideal_Nm" : "driving_force_ideal_N"] = fa.effort_ideal[static_cast<std::size_t>(driver)];
  f["forward"] = sense_json(model, fa.forward, driver, effort_key);
  f["reverse"] = sense_json(model, fa.reverse, driver, effort_key);
  f["dissipated_power_W"] = fa.dissipated_power;
  position["friction"] = f;
  return position;
}

namespace {

std::string finite_text(double v, int digits) { return std::isfinite(v) ? io::fixed(v, digits) : "-"; }

// One table per link: every force on it, where it acts, and its moment about that point.
void add_free_bodies(io::Report& report, const kin::Model& model, const KinPosition& position) {
  kin::Data data(model);
  data.q = position.q;
  data.qd = position.qd;
  data.qdd = position.qdd;
  nlohmann::json all = nlohmann::json::array();
  for (const kin::FreeBody& b : kin::free_bodies(model, data, *position.forces)) {
    io::Table t{"Free body: " + b.name, {"force", "kind", "x [mm]", "y [mm]", "Fx [N]", "Fy [N]", "M [N m]", "N [N]", "friction [N or N m]"}, {}};
    nlohmann::json forces = nlohmann::json::array();
    for (const kin::BodyForce& f : b.forces) {
      t.add_row({f.source, f.kind, io::fixed(f.at.x() * 1000, 3), io::fixed(f.at.y() * 1000, 3), io::fixed(f.force.x(), 4),
                 io::fixed(f.force.y(), 4), io::fixed(f.moment, 5), finite_text(f.normal, 4), finite_text(f.friction, 4)});
      nlohmann::json j = {{"from", f.source}, {"kind", f.kind}, {"at_mm", {f.at.x() * 1000, f.at.y() * 1000}},
                          {"force_N", {f.force.x(), f.force.y()}}, {"moment_Nm", f.moment}};
      if (std::isfinite(f.normal)) j["normal_N"] = f.normal;
      if (std::isfinite(f.friction)) j["friction"] = f.friction;
      forces.push_back(j);
    }
    report.tables.push_back(std::move(t));
    all.push_back({{"link", b.name}, {"forces", forces}});
  }
  report.json["free_bodies"] = all;
}

}  // namespace

void add_force_details_report(io::Report& report, const kin::Model& model, const KinPosition& position, int driver,
                              bool angular) {
  const kin::ForceAnalysis& forces = *position.forces;
  report.warnings.insert(report.warnings.end(), forces.warnings.begin(), forces.warnings.end());
  add_free_bodies(report, model, position);
  if (!forces.unknown_loads.empty()) {
    io::Table t{"Unknown loads (from the given driving effort)", {"load", "value", "unit"}, {}};
    for (const kin::UnknownLoad& u : forces.unknown_loads) t.add_row({u.name, io::fixed(u.value, 4), u.torque ? "N m" : "N"});
    report.tables.push_back(std::move(t));
  }
  if (!forces.friction) return;
  const kin::FrictionAnalysis& fa = *forces.friction;
  io::Table t{"Friction (forward sense)", {"joint", "kind", "mu", "N or |F| [N]", "friction [N or N m]", "sliding [m/s or rad/s]"}, {}};
  for (const kin::JointFrictionForce& jf : fa.joints)
    t.add_row({jf.name, jf.kind, io::fixed(coefficient_of(model, jf.constraint), 5), io::fixed(jf.normal, 4),
               io::fixed(jf.friction, 4), io::fixed(jf.sliding, 6)});
  report.tables.push_back(std::move(t));
  report.notes.push_back(fmt::format("Without friction: driving {} {} {}", angular ? "torque" : "force",
                                     io::fixed(fa.effort_ideal[static_cast<std::size_t>(driver)], 6), angular ? "N m" : "N"));
  report.notes.push_back("Forward (the analysed motion): " + sense_text(model, fa.forward, driver, angular));
  report.notes.push_back("Reverse (every velocity turned): " + sense_text(model, fa.reverse, driver, angular));
}

}  // namespace gearkit::cli
