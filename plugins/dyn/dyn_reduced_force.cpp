// `reduced_force:` — virtual power at one instant: the force at a point (and the torque on a
// shaft) equivalent to given forces, weights and inertia forces (OTM 2015 problem 1 c).
#include "dyn_sections.hpp"

#include <gearkit/dyn/reduction.hpp>

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace gearkit::plugins::dyn {

void add_reduced_force(const Model& m, Output& out) {
  const ReducedForceQuestion& q = *m.reduced_force;
  io::Table t{"Virtual power of each term", {"term", "F_x [N]", "F_y [N]", "v_x [m/s]", "v_y [m/s]", "power [W]"}, {}};
  std::vector<gd::ForceAtPoint> all;
  nlohmann::json jt = nlohmann::json::array();
  const auto add = [&](const std::string& name, gd::Vec2 f, gd::Vec2 v) {
    all.push_back({f, v});
    const double p = gd::dot(f, v);
    t.add_row({name, io::fixed(f.x, 4), io::fixed(f.y, 4), io::fixed(v.x, 4), io::fixed(v.y, 4), io::fixed(p, 4)});
    jt.push_back({{"name", name}, {"force_N", {f.x, f.y}}, {"velocity_m_s", {v.x, v.y}}, {"power_W", p}});
  };
  for (const ReducedForceTerm& term : q.terms) {
    if (term.force.x != 0 || term.force.y != 0) add(term.name, term.force, term.velocity);
    if (term.mass > 0) {
      add(term.name + ": weight", gd::weight(term.mass, term.gravity), term.velocity);
      if (term.acceleration.x != 0 || term.acceleration.y != 0)
        add(term.name + ": inertia force", gd::inertia_force(term.mass, term.acceleration), term.velocity);
    }
  }
  out.report.tables.push_back(std::move(t));

  const double power = gd::virtual_power(all);
  double force = 0;
  try {
    force = gd::reduced_force(power, q.point_velocity);
  } catch (const std::invalid_argument& e) {
    io::fail_at(q.mark, e.what());
  }
  io::Table r{fmt::format("Reduced force at {} (along its velocity)", q.point), {"quantity", "value", "unit"}, {}};
  r.add_row({"total virtual power", io::fixed(power, 4), "W"});
  r.add_row({fmt::format("reduced force at {}", q.point), io::fixed(force, 3), "N"});
  r.add_row({fmt::format("force to apply at {} for equilibrium", q.point), io::fixed(-force, 3), "N"});
  nlohmann::json j{{"point", q.point}, {"terms", jt}, {"power_W", power}, {"reduced_force_N", force},
                   {"equilibrating_force_N", -force}};
  if (q.shaft_speed) {
    double torque = 0;
    try {
      torque = gd::reduced_torque_at(power, *q.shaft_speed);
    } catch (const std::invalid_argument& e) {
      io::fail_at(q.mark, e.what());
    }
    r.add_row({"reduced torque on the shaft", io::fixed(torque, 3), "N*m"});
    r.add_row({"torque to apply on the shaft for equilibrium", io::fixed(-torque, 3), "N*m"});
    j["reduced_torque_Nm"] = torque;
    j["equilibrating_torque_Nm"] = -torque;
  }
  out.report.tables.push_back(std::move(r));
  out.report.notes.push_back(fmt::format(
      "Positive: along the velocity of {} (the given terms drive it); negative: against it.", q.point));
  out.report.json["reduced_force"] = j;
}

}  // namespace gearkit::plugins::dyn
