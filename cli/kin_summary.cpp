// `gearkit kin`: the mechanism summary (kin_summary.hpp).
#include "kin_summary.hpp"
#include "kin_units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace gearkit::cli {

KinSummary::KinSummary(const mechanism::Mechanism& mech, int driver, double min_transmission_angle)
    : mech_(mech), driver_(driver), limit_(min_transmission_angle) {}

void KinSummary::add(const KinPosition& p) {
  if (positions_++ == 0) first_input_ = p.input;
  last_input_ = p.input;
  if (p.transmission_angle) mu_.add(p.input, *p.transmission_angle);
  // At a dead point the effort grows without bound (kin_analysis.hpp): its value means nothing.
  if (!p.forces || p.at_dead_point) return;
  effort_.add(p.input, p.forces->effort_virtual_power[static_cast<std::size_t>(driver_)]);
  if (!p.on_change_point) add_reactions(p);  // on a change point the reactions are indeterminate
}

void KinSummary::add_reactions(const KinPosition& p) {
  for (const kin::ConstraintReaction& c : p.forces->reactions) {
    auto it = std::find_if(joints_.begin(), joints_.end(), [&](const JointPeak& j) { return j.name == c.name && j.kind == c.kind; });
    if (it == joints_.end()) it = joints_.insert(joints_.end(), JointPeak{c.name, c.kind, {}});
    const double f = c.force.norm();
    if (std::isfinite(f) && !(f <= it->force.value)) it->force = {f, p.input};
  }
}

void KinSummary::write(const KinAnalysis& a, io::Report& rep) const {
  const std::string unit = input_unit(mech_, driver_), key = input_key(mech_, driver_);
  const auto where = [&](double input) { return io::fixed(shown_input(mech_, driver_, input), 4); };
  io::Table t{"Mechanism summary", {"quantity", "value", fmt::format("at {} [{}]", mech_.drivers[static_cast<std::size_t>(driver_)].name, unit)}, {}};
  nlohmann::json j = nlohmann::json::object();
  j["positions"] = positions_;
  j["min_transmission_angle_limit_deg"] = limit_ * kRadToDeg;
  if (mu_.count() > 0) {
    t.add_row({"least transmission angle mu [deg]", io::fixed(mu_.min().value * kRadToDeg, 2), where(mu_.min().input)});
    t.add_row({"largest transmission angle mu [deg]", io::fixed(mu_.max().value * kRadToDeg, 2), where(mu_.max().input)});
    j["transmission_angle_min_deg"] = mu_.min().value * kRadToDeg;
    j["transmission_angle_min_at_" + key] = shown_input(mech_, driver_, mu_.min().input);
    j["transmission_angle_max_deg"] = mu_.max().value * kRadToDeg;
    j["transmission_angle_max_at_" + key] = shown_input(mech_, driver_, mu_.max().input);
  }
  const bool ang = angular(mech_, driver_);
  const std::string effort = ang ? "driving torque" : "driving force", effort_unit = ang ? "N m" : "N";
  const std::string effort_json = ang ? "driving_torque" : "driving_force", effort_suffix = ang ? "_Nm" : "_N";
  if (effort_.count() > 0) {
    t.add_row({fmt::format("peak {} [{}]", effort, effort_unit), io::fixed(effort_.peak().value, 4), where(effort_.peak().input)});
    j[effort_json + "_peak" + effort_suffix] = effort_.peak().value;
    j[effort_json + "_peak_at_" + key] = shown_input(mech_, driver_, effort_.peak().input);
    if (positions_ > 1) {
      t.add_row({fmt::format("RMS {} [{}]", effort, effort_unit), io::fixed(effort_.rms(), 4),
                 fmt::format("{} .. {}", where(first_input_), where(last_input_))});
      j[effort_json + "_rms" + effort_suffix] = effort_.rms();
    }
  }
  nlohmann::json peaks = nlohmann::json::array();
  for (const JointPeak& p : joints_) {
    if (!std::isfinite(p.force.value)) continue;
    t.add_row({fmt::format("peak reaction at {} ({}) [N]", p.name, p.kind), io::fixed(p.force.value, 3), where(p.force.input)});
    peaks.push_back({{"joint", p.name}, {"kind", p.kind}, {"force_N", p.force.value}, {"at_" + key, shown_input(mech_, driver_, p.force.input)}});
  }
  j["reaction_peaks"] = peaks;
  nlohmann::json limits = nlohmann::json::array();
  for (const kin::OutputExtreme& x : a.extremes) {
    const kin::Output& o = mech_.outputs[static_cast<std::size_t>(x.output)];
    t.add_row({fmt::format("limit position: {} {} [{}]", o.name, x.maximum ? "max" : "min", output_unit(o)),
               io::fixed(shown_output(o, x.value), 4), where(x.input)});
    limits.push_back({{"kind", x.maximum ? "output max" : "output min"}, {"output", o.name}, {key, shown_input(mech_, driver_, x.input)}});
  }
  for (const kin::DeadPoint& d : a.dead_points) {
    t.add_row({"dead point (the driver cannot move the mechanism on)", "-", where(d.input)});
    limits.push_back({{"kind", "dead point"}, {key, shown_input(mech_, driver_, d.input)}});
  }
  j["limit_positions"] = limits;
  if (mu_.count() > 0 && mu_.min().value < limit_)
    rep.warnings.push_back(fmt::format("transmission angle down to {} deg at {} = {} {}, below the {} deg limit "
                                       "(--min-transmission-angle): the mechanism transmits force poorly there",
                                       io::fixed(mu_.min().value * kRadToDeg, 2), mech_.drivers[static_cast<std::size_t>(driver_)].name,
                                       where(mu_.min().input), unit, io::fixed(limit_ * kRadToDeg, 2)));
  if (!t.rows.empty()) rep.tables.push_back(std::move(t));
  rep.json["summary"] = std::move(j);
}

}  // namespace gearkit::cli
