// The dynamics sections of the cam report: follower train, spring, forces, torque, stress, jump,
// speed sweep, flexible follower; JSON under "dynamics" with unit-suffixed keys.
#include "cam_report.hpp"

#include "cam_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace gearkit::plugins::cam {

namespace gc = gearkit::cam;

namespace {

constexpr double kRpm = 30 / std::numbers::pi;  // rad/s -> rpm
constexpr double kHz = 1 / (2 * std::numbers::pi);

/// Units of the generalised quantities: translating in N, kg, N/mm; oscillating in N m, kg m^2, N m/rad.
struct DynUnits {
  explicit DynUnits(const CamModel& m) : osc(m.design.follower.motion == gc::FollowerMotion::oscillating) {}
  bool osc;
  std::string force() const { return osc ? "N*m" : "N"; }
  std::string force_key() const { return osc ? "N_m" : "N"; }
  std::string mass() const { return osc ? "kg*m^2" : "kg"; }
  std::string mass_key() const { return osc ? "inertia_kg_m2" : "mass_kg"; }
  std::string spring() const { return osc ? "N*m/rad" : "N/mm"; }
  std::string spring_key() const { return osc ? "N_m_per_rad" : "N_per_mm"; }
  double spring_shown(double k) const { return osc ? k : k / 1000; }
  std::string damping() const { return osc ? "N*m*s/rad" : "N*s/m"; }
  std::string damping_key() const { return osc ? "N_m_s_per_rad" : "N_s_per_m"; }
  std::string motion() const { return osc ? "deg" : "mm"; }
  std::string motion_key() const { return osc ? "deg" : "mm"; }
  double motion_shown(double q) const { return osc ? deg(q) : q * 1000; }
};

std::string g(double v) { return fmt::format("{:.6g}", v); }
std::string at(double theta) { return io::fixed(angle_deg(theta), 2); }

bool spring_closed(const CamModel& m) { return m.design.follower.closure == gc::Closure::spring; }

/// The contact force with its sign for a spring-closed follower (negative: the follower has left
/// the cam); the force on the surface in contact for a form-closed one.
double signed_force(const gc::DynamicState& s) { return s.wall == 0 ? s.force / s.lever : s.contact_force; }

template <class F>
const gc::DynamicState& largest(const std::vector<gc::DynamicState>& states, F&& key) {
  return *std::max_element(states.begin(), states.end(), [&](const auto& a, const auto& b) { return key(a) < key(b); });
}

/// A sized preload as the report shows it: size_spring's supremum leaves a rounding residue
/// (3.2e-14 N) where the rate alone meets the need; within 1e-12 of the forces at play (spring
/// and inertia over the lift, the load) it is 0. The analysis keeps the residue, so that a
/// contact force of exactly 0 on the base circle does not read as a jump.
double shown_preload(const CamModel& model, const CamDynamics& r, double preload, double spring_rate) {
  const gc::FollowerTrain& t = r.train;
  const double scale = (spring_rate + t.mass * r.omega * r.omega) * model.design.program.max_s() + std::abs(t.load);
  return preload <= 1e-12 * scale ? 0.0 : preload;
}

/// A contact force as the report shows it: the same rounding residue (3.2e-14 N on the base circle
/// of a cam that needs no preload) within 1e-12 of the forces at play, preload included, is 0.
double shown_force(const CamModel& model, const CamDynamics& r, double force) {
  const gc::FollowerTrain& t = r.train;
  const double scale = (t.spring_rate + t.mass * r.omega * r.omega) * model.design.program.max_s() + std::abs(t.load) +
                       std::abs(t.preload);
  return std::abs(force) <= 1e-12 * scale ? 0.0 : force;
}

void train_section(const CamModel& model, const CamDynamics& r, io::Report& rep, nlohmann::json& j) {
  const DynUnits u(model);
  const gc::FollowerTrain& t = r.train;
  const double preload = r.preload_sized ? shown_preload(model, r, t.preload, t.spring_rate) : t.preload;
  const double margin = model.dynamics->jump_margin;
  const std::string sized = margin == 1 ? fmt::format("sized for {} rpm, {} N", g(r.sizing_omega * kRpm), g(model.dynamics->min_force))
                                        : fmt::format("sized for {} rpm (jump margin {} x the design speed), {} N",
                                                      g(r.sizing_omega * kRpm), g(margin), g(model.dynamics->min_force));
  io::Table tab{"Follower train", {"quantity", "value", "note"}, {}};
  tab.add_row({fmt::format("{} [{}]", u.osc ? "moment of inertia" : "effective mass", u.mass()), g(t.mass), "given"});
  tab.add_row({fmt::format("spring rate [{}]", u.spring()), g(u.spring_shown(t.spring_rate)), r.rate_sized ? sized : "given"});
  tab.add_row({fmt::format("preload [{}]", u.force()), g(preload), r.preload_sized ? sized : "given"});
  tab.add_row({fmt::format("damping [{}]", u.damping()), g(t.damping),
               model.dynamics->damping_ratio ? fmt::format("damping ratio {}", g(*model.dynamics->damping_ratio)) : "given"});
  if (t.load != 0) tab.add_row({fmt::format("constant load [{}]", u.force()), g(t.load), "given"});
  if (t.spring_rate > 0)
    tab.add_row({"natural frequency on the spring [Hz]", g(spring_natural_frequency(t) * kHz), "sqrt(k/M) / 2 pi"});
  if (r.needed)
    tab.add_row({fmt::format("preload this rate needs [{}]", u.force()),
                 g(shown_preload(model, r, r.needed->preload, r.needed->spring_rate)), sized});
  rep.tables.push_back(tab);
  j[u.mass_key()] = number(t.mass);
  j["spring_rate_" + u.spring_key()] = number(u.spring_shown(t.spring_rate));
  j["preload_" + u.force_key()] = number(preload);
  j["damping_" + u.damping_key()] = number(t.damping);
  j["load_" + u.force_key()] = number(t.load);
  j["spring_rate_sized"] = r.rate_sized;
  j["preload_sized"] = r.preload_sized;
  j["min_contact_force_N"] = number(model.dynamics->min_force);
  j["jump_margin"] = number(margin);
  j["spring_sized_for_rpm"] = number(r.sizing_omega * kRpm);
  if (r.needed) j["preload_needed_" + u.force_key()] = number(shown_preload(model, r, r.needed->preload, r.needed->spring_rate));
  if (t.spring_rate > 0) j["natural_frequency_spring_Hz"] = number(spring_natural_frequency(t) * kHz);
}

/// The force of the cam on the follower along its own motion, Q: for a translating follower the
/// axial force F_c = F_n cos phi (Norton, Design of Machinery, sect. 8.5 and eq. 15.8: the lumped
/// model's cam force F_c acts along the follower's axis; the normal force F_n at pressure angle
/// phi has that axial component and the side thrust F_n sin phi on the guide); for an
/// oscillating follower the torque of the cam on the arm about its pivot, F_n L cos phi.
void axial_rows(const CamModel& model, const CamDynamics& r, io::Table& tab, nlohmann::json& j) {
  const DynUnits u(model);
  const auto& most = largest(r.states, [](const auto& x) { return x.force; });
  const auto& least = largest(r.states, [](const auto& x) { return -x.force; });
  const std::string what = u.osc ? "torque of the cam on the follower arm Q = F_n L cos phi" : "axial force on the follower F_c = F_n cos phi";
  const std::string key = u.osc ? "arm_torque" : "axial_force";
  tab.add_row({fmt::format("largest {} [{}]", what, u.force()), g(most.force), at(most.theta)});
  tab.add_row({fmt::format("least {} [{}]", what, u.force()), g(shown_force(model, r, least.force)), at(least.theta)});
  j[key + "_max_" + u.force_key()] = number(most.force);
  j[key + "_max_at_deg"] = number(angle_deg(most.theta));
  j[key + "_min_" + u.force_key()] = number(shown_force(model, r, least.force));
  j[key + "_min_at_deg"] = number(angle_deg(least.theta));
}

void force_rows(const CamModel& model, const CamDynamics& r, io::Table& tab, nlohmann::json& j) {
  const auto& s = r.states;
  if (spring_closed(model)) {
    const auto& most = largest(s, [](const auto& x) { return signed_force(x); });
    const auto& least = largest(s, [](const auto& x) { return -signed_force(x); });
    tab.add_row({"largest contact force [N]", g(signed_force(most)), at(most.theta)});
    tab.add_row({"least contact force [N] (< 0: the follower leaves the cam)", g(shown_force(model, r, signed_force(least))),
                 at(least.theta)});
    j["contact_force_max_N"] = number(signed_force(most));
    j["contact_force_max_at_deg"] = number(angle_deg(most.theta));
    j["contact_force_min_N"] = number(shown_force(model, r, signed_force(least)));
    j["contact_force_min_at_deg"] = number(angle_deg(least.theta));
    return;
  }
  const auto& cam = largest(s, [](const auto& x) { return x.wall > 0 ? x.contact_force : -1.0; });
  const auto& other = largest(s, [](const auto& x) { return x.wall < 0 ? x.contact_force : -1.0; });
  const bool groove = model.design.follower.closure == gc::Closure::groove;
  tab.add_row({groove ? "largest force on the inner wall [N]" : "largest force on the first cam [N]",
               g(cam.wall > 0 ? cam.contact_force : 0.0), at(cam.theta)});
  tab.add_row({groove ? "largest force on the outer wall [N]" : "largest force on the conjugate cam [N]",
               g(other.wall < 0 ? other.contact_force : 0.0), at(other.theta)});
  j["contact_force_max_N"] = number(cam.wall > 0 ? cam.contact_force : 0.0);
  j["contact_force_max_at_deg"] = number(angle_deg(cam.theta));
  j["contact_force_other_max_N"] = number(other.wall < 0 ? other.contact_force : 0.0);
  j["contact_force_other_max_at_deg"] = number(angle_deg(other.theta));
}

/// The mean camshaft torque over the samples, 0 where it lies within the rounding of its own
/// sum: n terms summed one by one err by at most (n - 1) u sum |T_i| (Higham, Accuracy and
/// Stability of Numerical Algorithms, 2nd ed., eq. 4.4), each T_i by a few u |T_i| more, so a
/// mean below 2 n u mean|T_i| is round-off around zero (a loss-free cam: no damping, no friction).
double mean_torque(const std::vector<gc::DynamicState>& s) {
  const double n = static_cast<double>(s.size());
  double mean = 0, mean_abs = 0;
  for (const auto& x : s) mean += x.torque / n, mean_abs += std::abs(x.torque) / n;
  return std::abs(mean) <= 2 * n * std::numeric_limits<double>::epsilon() * mean_abs ? 0.0 : mean;
}

void torque_rows(const CamDynamics& r, io::Table& tab, nlohmann::json& j) {
  const auto& s = r.states;
  const auto& tmax = largest(s, [](const auto& x) { return x.torque; });
  const auto& tmin = largest(s, [](const auto& x) { return -x.torque; });
  const double mean = mean_torque(s);
  tab.add_row({"largest camshaft torque [N*m]", g(tmax.torque), at(tmax.theta)});
  tab.add_row({"least camshaft torque [N*m]", g(tmin.torque), at(tmin.theta)});
  tab.add_row({"mean camshaft torque [N*m]", g(mean), "-"});
  tab.add_row({"peak power [W]", g(tmax.torque * r.omega), at(tmax.theta)});
  tab.add_row({"mean power [W] (losses per cycle times speed)", g(mean * r.omega), "-"});
  j["camshaft_torque_max_N_m"] = number(tmax.torque);
  j["camshaft_torque_max_at_deg"] = number(angle_deg(tmax.theta));
  j["camshaft_torque_min_N_m"] = number(tmin.torque);
  j["camshaft_torque_min_at_deg"] = number(angle_deg(tmin.theta));
  j["camshaft_torque_mean_N_m"] = number(mean);
  j["power_max_W"] = number(tmax.torque * r.omega);
  j["power_mean_W"] = number(mean * r.omega);
  j["work_per_cycle_J"] = number(mean * 2 * std::numbers::pi);
}

void contact_rows(const CamModel& model, const CamDynamics& r, io::Table& tab, nlohmann::json& j) {
  const auto& s = r.states;
  if (model.contact) {
    const auto& p = largest(s, [](const auto& x) { return std::isnan(x.hertz_stress) ? INFINITY : x.hertz_stress; });
    tab.add_row({"largest Hertz contact stress [MPa]", std::isnan(p.hertz_stress) ? "none" : g(p.hertz_stress / 1e6),
                 at(p.theta)});
    j["hertz_stress_max_MPa"] = number(p.hertz_stress / 1e6);
    j["hertz_stress_max_at_deg"] = number(angle_deg(p.theta));
    if (model.contact->allowable) j["hertz_stress_allowable_MPa"] = number(*model.contact->allowable / 1e6);
  }
  if (model.design.follower.contact == gc::Contact::roller) {
    const auto& w = largest(s, [](const auto& x) { return std::abs(x.roller_speed); });
    tab.add_row({"largest roller speed [rpm]", g(std::abs(w.roller_speed) * kRpm), at(w.theta)});
    j["roller_speed_max_rpm"] = number(std::abs(w.roller_speed) * kRpm);
    if (r.train.roller_inertia > 0) {
      const auto& t = largest(s, [](const auto& x) { return x.contact_force > 0 ? x.traction / x.contact_force : INFINITY; });
      const double ratio = t.contact_force > 0 ? t.traction / t.contact_force : INFINITY;
      tab.add_row({"largest traction / contact force (roller slip if above the friction)", g(ratio), at(t.theta)});
      j["roller_traction_ratio_max"] = number(ratio);
    }
  } else {
    const auto& v = largest(s, [](const auto& x) { return x.sliding_speed; });
    tab.add_row({"largest sliding speed [m/s]", g(v.sliding_speed), at(v.theta)});
    j["sliding_speed_max_m_s"] = number(v.sliding_speed);
  }
}

void jump_rows(const CamModel& model, const CamDynamics& r, io::Table& tab, nlohmann::json& j) {
  if (!spring_closed(model)) return;
  const double to = model.dynamics->jump_search_to;
  tab.add_row({"jump speed (contact force reaches 0) [rpm]",
               r.jump ? g(r.jump->omega * kRpm) : fmt::format("none up to {}", g(to * kRpm)),
               r.jump ? at(r.jump->theta) : "-"});
  j["jump_speed_rpm"] = r.jump ? number(r.jump->omega * kRpm) : nlohmann::json();
  if (r.jump) {
    tab.add_row({"jump speed / design speed", g(r.jump->omega / r.omega), "-"});
    j["jump_speed_over_design_speed"] = number(r.jump->omega / r.omega);
  }
  if (r.jump) j["jump_at_deg"] = number(angle_deg(r.jump->theta));
  j["jump_search_to_rpm"] = number(to * kRpm);
}

void sweep_section(const CamModel& model, const CamDynamics& r, io::Report& rep, nlohmann::json& j) {
  if (!r.sweep) return;
  const DynUnits u(model);
  io::Table tab{"Speed sweep", {"cam speed [rpm]", fmt::format("least force of the cam on the follower Q [{}]", u.force())}, {}};
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t i = 0; i < r.sweep->omega.size(); ++i) {
    tab.add_row({g(r.sweep->omega[i] * kRpm), g(r.sweep->margin[i])});
    rows.push_back({{"speed_rpm", number(r.sweep->omega[i] * kRpm)}, {"least_force_" + u.force_key(), number(r.sweep->margin[i])}});
  }
  rep.tables.push_back(tab);
  j["speed_sweep"] = rows;
  j["speed_sweep_jump_rpm"] = r.sweep->jump ? number(*r.sweep->jump * kRpm) : nlohmann::json();
}

void flexible_section(const CamModel& model, const CamDynamics& r, io::Report& rep, nlohmann::json& j) {
  if (!r.flexible) return;
  const DynUnits u(model);
  const gc::FlexibleResponse& f = *r.flexible;
  io::Table tab{"Flexible follower (one degree of freedom)", {"quantity", "value", "at cam angle [deg]"}, {}};
  tab.add_row({"natural frequency [Hz]", g(f.natural_frequency * kHz), "-"});
  tab.add_row({"damping ratio", g(f.damping_ratio), "-"});
  tab.add_row({"natural frequency / cam frequency", g(f.natural_frequency / r.omega), "-"});
  nlohmann::json fj;
  fj["natural_frequency_Hz"] = number(f.natural_frequency * kHz);
  fj["damping_ratio"] = number(f.damping_ratio);
  fj["periodic"] = f.periodic;
  std::size_t least = 0;
  for (std::size_t i = 0; i < f.force.size(); ++i)
    if (f.force[i] < f.force[least]) least = i;
  tab.add_row({fmt::format("least cam force [{}]", u.force()), g(f.force[least]), at(f.theta[least])});
  fj["force_min_" + u.force_key()] = number(f.force[least]);
  fj["force_min_at_deg"] = number(angle_deg(f.theta[least]));
  nlohmann::json res = nlohmann::json::array();
  for (const gc::ResidualVibration& v : r.residuals) {
    tab.add_row({fmt::format("residual vibration after the {} ending at {} deg [{}]",
                             model.design.program.segments()[v.segment].kind == gc::SegmentKind::rise ? "rise" : "return",
                             io::fixed(deg(v.theta), 2), u.motion()),
                 g(u.motion_shown(v.amplitude)), "-"});
    res.push_back({{"segment", v.segment}, {"end_deg", number(deg(v.theta))}, {"amplitude_" + u.motion_key(), number(u.motion_shown(v.amplitude))}});
  }
  fj["residual_vibration"] = res;
  rep.tables.push_back(tab);
  if (r.law_segment) {
    const gc::Segment& s = model.design.program.segments()[*r.law_segment];
    io::Table laws{fmt::format("Residual vibration of each law for the segment {} - {} deg", io::fixed(deg(s.start), 2),
                               io::fixed(deg(s.end), 2)),
                   {"law", fmt::format("amplitude [{}]", u.motion()), "per unit lift"}, {}};
    nlohmann::json lj = nlohmann::json::array();
    const double lift = u.osc ? s.lift : s.lift * 1e-3;
    for (const LawResidual& l : r.laws) {
      laws.add_row({std::string(gc::name_of(l.law)), g(u.motion_shown(l.amplitude)), g(l.amplitude / lift)});
      lj.push_back({{"law", gc::name_of(l.law)}, {"amplitude_" + u.motion_key(), number(u.motion_shown(l.amplitude))}});
    }
    rep.tables.push_back(laws);
    fj["laws"] = lj;
    fj["laws_segment"] = *r.law_segment;
  }
  j["flexible"] = fj;
}

void dynamics_warnings(const CamModel& model, const CamDynamics& r, io::Report& rep) {
  const double w = r.omega;
  if (spring_closed(model) && r.jump && r.jump->omega <= w) {
    rep.warnings.push_back(fmt::format("the follower leaves the cam (contact force < 0) from {} rpm, first at cam angle "
                                       "{} deg: below the design speed {} rpm; a stiffer spring or more preload is needed",
                                       g(r.jump->omega * kRpm), at(r.jump->theta), g(w * kRpm)));
  } else if (spring_closed(model) && r.least_margin < -1e-9 * std::max(1.0, r.train.preload)) {
    rep.warnings.push_back(fmt::format("at {} rpm the contact force falls below the least wanted {} N", g(w * kRpm),
                                       g(model.dynamics->min_force)));
  }
  if (model.contact && model.contact->allowable) {
    const auto& p = largest(r.states, [](const auto& x) { return std::isnan(x.hertz_stress) ? 0.0 : x.hertz_stress; });
    if (p.hertz_stress > *model.contact->allowable)
      rep.warnings.push_back(fmt::format("Hertz contact stress {} MPa at cam angle {} deg exceeds the allowable {} MPa",
                                         g(p.hertz_stress / 1e6), at(p.theta), g(*model.contact->allowable / 1e6)));
  }
  if (model.contact) {
    for (const auto& x : r.states)
      if (std::isnan(x.hertz_stress) && x.contact_force > 0) {
        rep.warnings.push_back(fmt::format("no Hertz stress at cam angle {} deg: the roller does not fit the hollow "
                                           "(concave radius smaller than the roller)", at(x.theta)));
        break;
      }
  }
  if (r.train.roller_inertia > 0 && r.train.friction > 0) {
    for (const auto& x : r.states)
      if (x.traction > r.train.friction * x.contact_force) {
        rep.warnings.push_back(fmt::format("the roller skids at cam angle {} deg: it needs {} N of traction to follow the "
                                           "cam, more than the friction {} x {} N",
                                           at(x.theta), g(x.traction), g(r.train.friction), g(x.contact_force)));
        break;
      }
  }
  if (model.dynamics->damping_ratio && *model.dynamics->damping_ratio > 0 && r.train.spring_rate + r.train.stiffness == 0)
    rep.warnings.push_back(fmt::format("damping_ratio {} gives no damping: the sized spring has no rate and the follower "
                                       "train no stiffness, so the critical damping 2 sqrt(k M) is 0; give damping instead",
                                       g(*model.dynamics->damping_ratio)));
  if (r.flexible && !r.flexible->periodic)
    rep.warnings.push_back("the undamped flexible follower is at resonance with the cam: no steady response");
  if (r.flexible && spring_closed(model)) {
    std::size_t least = 0;
    for (std::size_t i = 0; i < r.flexible->force.size(); ++i)
      if (r.flexible->force[i] < r.flexible->force[least]) least = i;
    if (r.flexible->force[least] < 0)
      rep.warnings.push_back(fmt::format("with the follower's flexibility the cam force falls to {} {} at cam angle {} "
                                         "deg: the flexible follower leaves the cam (vibration)",
                                         g(r.flexible->force[least]), DynUnits(model).force(), at(r.flexible->theta[least])));
  }
}

void wall_notes(const CamModel& model, const CamDynamics& r, io::Report& rep, nlohmann::json& j) {
  if (spring_closed(model)) return;
  nlohmann::json changes = nlohmann::json::array();
  std::string list;
  for (std::size_t i = 0; i < r.states.size(); ++i) {
    const auto& a = r.states[i];
    const auto& b = r.states[(i + 1) % r.states.size()];
    if (a.wall == b.wall) continue;
    changes.push_back(number(angle_deg(b.theta)));
    list += (list.empty() ? "" : ", ") + at(b.theta);
  }
  j["wall_changes_deg"] = changes;
  if (!list.empty())
    rep.notes.push_back(fmt::format("the contact changes sides (any backlash closes with an impact) at cam angle {} deg", list));
}

}  // namespace

void dynamics_report(const CamModel& model, const CamDynamics& r, io::Report& rep) {
  nlohmann::json j;
  train_section(model, r, rep, j);
  io::Table tab{fmt::format("Dynamics at {} rpm", g(r.omega * kRpm)), {"quantity", "value", "at cam angle [deg]"}, {}};
  j["design_speed_rpm"] = number(r.omega * kRpm);
  force_rows(model, r, tab, j);
  axial_rows(model, r, tab, j);
  torque_rows(r, tab, j);
  contact_rows(model, r, tab, j);
  jump_rows(model, r, tab, j);
  rep.tables.push_back(tab);
  sweep_section(model, r, rep, j);
  flexible_section(model, r, rep, j);
  dynamics_warnings(model, r, rep);
  wall_notes(model, r, rep, j);
  rep.json["dynamics"] = j;
}

}  // namespace gearkit::plugins::cam
