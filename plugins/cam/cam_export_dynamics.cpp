// Dynamics exports of the cam command: the force, torque and stress plot, and the camshaft as a
// `gearkit dyn` model for the flywheel question.
#include "cam_export.hpp"

#include "cam_text.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gearkit::plugins::cam {

namespace gc = gearkit::cam;

namespace {

/// A series over the turn from angles [rad] and values, closed at 360 deg with the first value;
/// at most about 1440 points (a quarter of a degree), which keeps the SVG small.
io::Series closed_series(const std::string& name, const std::vector<double>& theta, const std::vector<double>& y,
                         const std::string& color = "") {
  io::Series s{name, {}, {}, color};
  const double start = theta.front();
  const std::size_t step = std::max<std::size_t>(1, theta.size() / 1440);
  for (std::size_t i = 0; i <= theta.size(); i = i < theta.size() && i + step > theta.size() ? theta.size() : i + step) {
    const std::size_t k = i % theta.size();
    s.x.push_back(deg(theta[k] - start) + deg(start) + (i == theta.size() ? 360.0 : 0.0));
    s.y.push_back(y[k]);
  }
  return s;
}

io::Series constant(const std::string& name, double value, const std::vector<double>& theta, const std::string& color) {
  return {name, {deg(theta.front()), deg(theta.front()) + 360}, {value, value}, color};
}

}  // namespace

io::Plot dynamics_plot(const CamModel& model, const CamDynamics& dyn) {
  io::Plot plot;
  // The speed it is drawn at, and the cam speed of the s-v-a-j plot when that differs (issue 32).
  const double rpm = dyn.omega * 30 / std::numbers::pi;
  const std::string other = model.omega && std::abs(*model.omega - dyn.omega) > 1e-12 * dyn.omega
                                ? fmt::format(" (the s-v-a-j plot: cam speed {:.6g} rpm)", *model.omega * 30 / std::numbers::pi)
                                : "";
  plot.title = fmt::format("Cam dynamics at the design speed {:.6g} rpm{}{}", rpm, other, model.name.empty() ? "" : ": " + model.name);
  plot.x_label = "cam angle theta [deg]";
  const bool osc = model.design.follower.motion == gc::FollowerMotion::oscillating;
  std::vector<double> theta, force, axial, torque, stress;
  for (const gc::DynamicState& s : dyn.states) {
    theta.push_back(s.theta);
    force.push_back(s.wall == 0 ? s.force / s.lever : s.contact_force * s.wall);
    axial.push_back(s.force);
    torque.push_back(s.torque);
    stress.push_back(s.hertz_stress / 1e6);
  }
  io::PlotPanel f{osc ? "contact force F_n [N]" : "force [N], F_c = F_n cos phi",
                  {closed_series("contact force F_n", theta, force, "#1f4e9c")}, {}};
  // Q: the axial force F_c = F_n cos phi of a translating follower (same panel, N); the arm's
  // torque of an oscillating one (a panel of its own, N*m).
  if (!osc) f.series.push_back(closed_series("axial force F_c", theta, axial, "#6a3d9a"));
  if (dyn.flexible) {
    std::vector<double> flex;
    for (std::size_t i = 0; i < dyn.flexible->theta.size(); ++i)
      flex.push_back(dyn.flexible->force[i] / gc::lever(model.design, gc::contact_at(model.design, dyn.flexible->theta[i])));
    f.series.push_back(closed_series("flexible follower", dyn.flexible->theta, flex, "#d9822b"));
  }
  if (model.dynamics->min_force > 0) f.series.push_back(constant("least wanted", model.dynamics->min_force, theta, "#888"));
  f.series.push_back(constant("zero", 0, theta, "#bbb"));
  io::PlotPanel t{"camshaft torque [N*m]", {closed_series("camshaft torque", theta, torque, "#2a7f3f")}, {}};
  plot.panels = {f};
  if (osc) plot.panels.push_back({"torque of the cam on the arm Q [N*m]", {closed_series("Q = F_n L cos phi", theta, axial, "#6a3d9a")}, {}});
  plot.panels.push_back(t);
  if (model.contact) {
    io::PlotPanel p{"Hertz contact stress [MPa]", {closed_series("p0", theta, stress, "#b22222")}, {}};
    if (model.contact->allowable) p.series.push_back(constant("allowable", *model.contact->allowable / 1e6, theta, "#888"));
    plot.panels.push_back(p);
  }
  return plot;
}

std::string dyn_model(const CamModel& model, const CamDynamics& dyn, const std::string& file) {
  // The camshaft is the load shaft; its torque over the turn, kinetostatic at the design speed
  // (follower inertia included), is the resisting torque; the motor gives the mean torque
  // (scale: balance makes the cycle steady to the tolerance gearkit dyn asks). Written by the
  // emitter, so that any cam name or file name reads back (issue 25).
  const double rpm = dyn.omega * 30 / std::numbers::pi;
  YAML::Emitter y;
  y << YAML::Comment(fmt::format("Written by gearkit cam from {}: the camshaft's torque over one turn at {:.9g} rpm", file, rpm))
    << YAML::Newline
    << YAML::Comment("(kinetostatic: follower inertia, spring, damping and friction), for `gearkit dyn` (docs/dyn.md).");
  y << YAML::BeginMap << YAML::Key << "title" << YAML::Value << YAML::DoubleQuoted
    << "camshaft of " + (model.name.empty() ? file : model.name);
  y << YAML::Key << "motor" << YAML::Value << YAML::BeginMap << YAML::Key << "speed" << YAML::Value
    << fmt::format("{:.9g} rpm", rpm) << YAML::EndMap;
  y << YAML::Key << "load" << YAML::Value << YAML::BeginMap << YAML::Key << "name" << YAML::Value << "camshaft" << YAML::Key
    << "resisting" << YAML::Value << YAML::BeginMap << YAML::Key << "table" << YAML::Value << YAML::BeginSeq;
  const double start = dyn.states.front().theta;
  for (std::size_t i = 0; i <= dyn.states.size(); ++i) {
    const gc::DynamicState& s = dyn.states[i % dyn.states.size()];
    const double angle = i == dyn.states.size() ? 360.0 : deg(s.theta - start);
    y << YAML::Flow << YAML::BeginSeq << fmt::format("{:.9g} deg", angle) << fmt::format("{:.12g}", s.torque) << YAML::EndSeq;
  }
  y << YAML::EndSeq << YAML::EndMap << YAML::EndMap;
  y << YAML::Key << "flywheel" << YAML::Value << YAML::BeginMap << YAML::Key << "fluctuation" << YAML::Value
    << fmt::format("{:.9g}", model.dynamics->fluctuation) << YAML::Key << "drive" << YAML::Value << YAML::Flow
    << YAML::BeginMap << YAML::Key << "constant" << YAML::Value << "1 N*m" << YAML::Key << "scale" << YAML::Value
    << "balance" << YAML::EndMap << YAML::EndMap << YAML::EndMap;
  return std::string(y.c_str()) + "\n";
}

}  // namespace gearkit::plugins::cam
