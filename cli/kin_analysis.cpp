// `gearkit kin`: the analysis at one position or over a sweep, independent of the report.
#include "kin_analysis.hpp"
#include "kin_units.hpp"

#include <gearkit/io/progress.hpp>
#include <gearkit/kin/fourbar.hpp>
#include <gearkit/kin/instant_centre.hpp>

#include <fmt/format.h>

#include <cmath>

namespace gearkit::cli {

namespace {

std::string shown(const mechanism::Mechanism& mech, int driver, double v) {
  return fmt::format("{:.6g} {}", shown_input(mech, driver, v), input_unit(mech, driver));
}

// Reaches `value` from the drawn input by continuation in 2 deg (2 mm) steps, so that the
// position stays on the drawing's assembly branch (Newton from a distant guess may land on
// another). @returns false with a warning in `a` when a dead point is in the way.
bool continue_from_drawing(const mechanism::Mechanism& mech, kin::Data& data, int driver, double value, KinAnalysis& a) {
  const double drawn = data.inputs(driver);
  const double step = angular(mech, driver) ? 2.0 * std::numbers::pi / 180.0 : 0.002;
  if (std::abs(value - drawn) <= step) return true;
  kin::SweepOptions o;
  o.driver = driver;
  o.start = drawn;
  o.end = value;
  o.step = step;
  o.velocities = false;
  o.min_step = 1e-9 * std::max(1.0, std::abs(value - drawn));
  const kin::SweepResult s = kin::sweep(mech.model, data, o);
  if (s.complete) {
    data.q = s.samples.back().q;
    return true;
  }
  a.warnings.push_back(s.assembled ? fmt::format("cannot reach input {} from the drawn configuration ({}): dead point at {:.6f} {}",
                                                 shown(mech, driver, value), shown(mech, driver, drawn),
                                                 shown_input(mech, driver, s.dead_points.front().input), input_unit(mech, driver))
                                   : fmt::format("cannot assemble at the drawn input {}: {}", shown(mech, driver, drawn), s.message));
  return false;
}

}  // namespace

void describe_position(const mechanism::Mechanism& mech, const std::optional<kin::FourBar>& four_bar, kin::Data& data,
                       int driver, double input, const Eigen::VectorXd* known_dq, KinPosition& p) {
  p.input = input;
  p.q = data.q;
  p.qd = data.qd;
  p.qdd = data.qdd;
  Eigen::VectorXd& solved_dq = data.work;  // scratch of the right size, unused by what follows
  const bool have_dq = known_dq ? known_dq->size() > 0 : kin::input_sensitivity(mech.model, data, driver, solved_dq);
  const Eigen::VectorXd& dq = known_dq ? *known_dq : solved_dq;
  p.outputs.resize(mech.outputs.size());
  p.output_ratios.resize(mech.outputs.size());
  for (std::size_t k = 0; k < mech.outputs.size(); ++k) {
    p.outputs[k] = kin::evaluate_output(mech.model, data, mech.outputs[k]);
    p.output_ratios[k] = have_dq ? kin::output_derivative(mech.model, data, mech.outputs[k], dq) : NAN;
  }
  if (four_bar) p.transmission_angle = kin::transmission_angle(*four_bar, data);
  else p.transmission_angle.reset();
  if (mech.model.has_loads()) p.forces = kin::solve_forces(mech.model, data, driver);
  else p.forces.reset();
}

KinAnalysis analyse_single(const mechanism::Mechanism& mech, kin::Data& data, int driver, std::optional<double> at,
                           const kin::DofReport& dof) {
  KinAnalysis a;
  a.single = true;
  a.driver = driver;
  a.dof = dof;
  const kin::Model& m = mech.model;
  const double value = at ? *at : data.inputs(driver);
  if (!continue_from_drawing(mech, data, driver, value, a)) return a;
  const kin::PositionReport r = kin::solve_at(m, data, driver, value);
  if (!r.converged || r.singular) {
    a.warnings.push_back(fmt::format("cannot analyse at input {}: {}", shown(mech, driver, value),
                                     r.converged ? "singular Jacobian (dead point)" : r.message));
    return a;
  }
  describe_position(mech, kin::find_four_bar(m), data, driver, value, nullptr, a.positions.emplace_back());
  // From the velocities per unit input speed, so quasi-static models (speed 0) have them too.
  const Eigen::VectorXd v = kin::input_sensitivity(m, data, driver);
  for (int b = 0; b < static_cast<int>(m.bodies().size()); ++b)
    a.instant_centres.push_back(v.size() ? kin::instant_centre(data.q, v, b) : std::nullopt);
  return a;
}

KinAnalysis analyse_sweep(const mechanism::Mechanism& mech, kin::Data& data, int driver, const mechanism::DriverRange& range,
                          const kin::DofReport& dof, const PositionSink& sink) {
  KinAnalysis a;
  a.driver = driver;
  a.dof = dof;
  const kin::Model& m = mech.model;
  kin::SweepOptions o;
  o.driver = driver;
  o.start = range.start;
  o.end = range.end;
  o.step = range.step;
  o.outputs = mech.outputs;
  o.min_step = 1e-9 * std::max(1.0, std::abs(range.end - range.start));
  // Each sample is analysed further (reactions, outputs) in a Data of its own: the sweep's
  // workspace carries its continuation state from one sample to the next.
  kin::Data probe(m);
  KinPosition p;
  const std::optional<kin::FourBar> four_bar = kin::find_four_bar(m);
  io::Progress progress("kin", static_cast<std::size_t>(kin::sweep_sample_count(o)));
  std::size_t done = 0;
  kin::SweepResult s;
  const bool loads = m.has_loads();
  kin::sweep(m, data, o, s, [&](const kin::SweepSample& sample) {
    progress.update(done++);
    probe.q = sample.q;
    probe.inputs(driver) = sample.input;
    if (loads || sample.qd.size() == 0) {
      kin::solve_at(m, probe, driver, sample.input);  // the reactions need Phi_q factorised here
    } else {
      probe.qd = sample.qd;  // the sweep solved them: outputs need q, qd, qdd and dq only
      probe.qdd = sample.qdd;
    }
    describe_position(mech, four_bar, probe, driver, sample.input, &sample.dq, p);
    sink(p);
  });
  if (!s.assembled)
    a.warnings.push_back(fmt::format("cannot assemble at the sweep's start {}: {}", shown(mech, driver, range.start), s.message));
  a.dead_points = s.dead_points;
  a.extremes = s.extremes;
  for (const kin::DeadPoint& d : s.dead_points)
    a.warnings.push_back(fmt::format("dead point at input {:.6f} {}: the driver cannot move the mechanism past it; "
                                     "the sweep stops there instead of jumping to another assembly branch",
                                     shown_input(mech, driver, d.input), input_unit(mech, driver)));
  return a;
}

}  // namespace gearkit::cli
