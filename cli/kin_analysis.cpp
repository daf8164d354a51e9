// `gearkit kin`: the analysis at one position or over a sweep, independent of the report.
#include "kin_analysis.hpp"
#include "kin_units.hpp"

#include <gearkit/io/progress.hpp>
#include <gearkit/kin/fourbar.hpp>
#include <gearkit/kin/instant_centre.hpp>
#include <gearkit/mechanism/sweep_start.hpp>

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace gearkit::cli {

namespace {

std::string shown(const mechanism::Mechanism& mech, int driver, double v) {
  return fmt::format("{:.6g} {}", shown_input(mech, driver, v), input_unit(mech, driver));
}

using mechanism::approach_start;  // shared with the Python module (mechanism/sweep_start.hpp)
using mechanism::sweep_options;

// The workspace a swept sample is analysed in (outputs, reactions): the sweep's own when it is
// factorised there (SweepSample::data; nothing in describe_position refactorises it, except the
// friction analysis, which gets the probe), else `probe` set to the sample, factorised when the
// reactions need it.
kin::Data& sample_workspace(const kin::Model& m, int driver, const kin::SweepSample& sample, kin::Data& probe) {
  if (sample.data && m.frictions().empty()) return *sample.data;
  probe.q = sample.q;
  probe.inputs(driver) = sample.input;
  if (sample.qd.size() == 0) {
    kin::solve_at(m, probe, driver, sample.input);
    return probe;
  }
  probe.qd = sample.qd;  // the sweep solved them: outputs need q, qd, qdd and dq only
  probe.qdd = sample.qdd;
  if (m.has_loads() && !sample.on_change_point) {  // the reactions need Phi_q factorised here (no Newton: solved)
    kin::evaluate_constraints(m, probe, probe.t);
    kin::factorize(m, probe);
  }
  return probe;
}

// The change points a sweep crossed, kept in the analysis with a note each (in the text report;
// JSON has them in change_points[]). Notes, not warnings: the driver does move the mechanism on.
void note_change_points(const mechanism::Mechanism& mech, int driver, const kin::SweepResult& s, KinAnalysis& a) {
  for (const kin::ChangePoint& c : s.change_points) {
    a.change_points.push_back(c);
    if (!c.bifurcation) {
      a.notes.push_back(fmt::format("singular position at input {:.6f} {} (the Jacobian loses rank, e.g. a triple "
                                       "parallelogram lying flat): no other branch passes there; the sweep went on",
                                       shown_input(mech, driver, c.input), input_unit(mech, driver)));
      continue;
    }
    a.notes.push_back(fmt::format(
        "change point at input {:.6f} {}: two branches of the motion cross there (e.g. a parallelogram lying flat); "
        "{}{}", shown_input(mech, driver, c.input), input_unit(mech, driver),
        c.switched ? "the sweep went on along the other branch (--branch switch)"
                   : "the sweep went on along the branch that continues the motion smoothly (--branch switch takes the "
                     "other)",
        mech.model.has_loads() ? "; a position on it has its driving effort by virtual power and no reactions (they are "
                                 "statically indeterminate there)" : ""));
  }
}

// Reaches `value` from the drawn input by continuation in 2 deg (2 mm) steps, so that the
// position stays on the drawing's assembly branch (Newton from a distant guess may land on
// another). @returns false with a warning in `a` when a dead point is in the way. `reached`, when
// given, receives the continuation's last sample (with velocities): the position itself when the
// value lies on a change point, where Newton cannot solve it.
bool continue_from_drawing(const mechanism::Mechanism& mech, kin::Data& data, int driver, double value, KinAnalysis& a,
                           bool switch_branch = false, kin::SweepSample* reached = nullptr) {
  const double drawn = data.inputs(driver);
  const double step = angular(mech, driver) ? 2.0 * std::numbers::pi / 180.0 : 0.002;
  if (std::abs(value - drawn) <= step) return true;
  const kin::SweepResult s =
      kin::sweep(mech.model, data, sweep_options(driver, drawn, value, step, reached != nullptr, switch_branch));
  note_change_points(mech, driver, s, a);
  if (s.complete) {
    data.q = s.samples.back().q;
    if (reached) *reached = s.samples.back();
    return true;
  }
  if (s.assembled) a.dead_points.push_back(s.dead_points.front());  // the limit in the way is a dead point too
  a.warnings.push_back(s.assembled ? fmt::format("cannot reach input {} from the drawn configuration ({}): dead point at {:.6f} {}",
                                                 shown(mech, driver, value), shown(mech, driver, drawn),
                                                 shown_input(mech, driver, s.dead_points.front().input), input_unit(mech, driver))
                                   : fmt::format("cannot assemble at the drawn input {}: {}", shown(mech, driver, drawn), s.message));
  return false;
}

// The sweep's start cannot be assembled: the first input of its grid that the drawn configuration
// reaches by continuation, with `data` assembled there, or nullopt when none is (a warning says
// why). The limit found on the way towards the start is a dead point of the analysis.
std::optional<double> reachable_start(const mechanism::Mechanism& mech, kin::Data& data, int driver,
                                      const mechanism::DriverRange& range, KinAnalysis& a) {
  const double drawn = data.inputs(driver);
  const Eigen::VectorXd drawn_q = data.q;
  const kin::SweepResult s = kin::sweep(mech.model, data, sweep_options(driver, drawn, range.start, range.step, false, false));
  if (!s.assembled) {
    a.warnings.push_back(fmt::format("cannot assemble at the drawn input {}: {}", shown(mech, driver, drawn), s.message));
    return std::nullopt;
  }
  if (s.complete) {  // reachable: Newton from the drawing alone had not found it
    data.q = s.samples.back().q;
    data.inputs(driver) = range.start;
    return range.start;
  }
  const kin::DeadPoint& limit = s.dead_points.front();
  a.dead_points.push_back(limit);
  const double direction = range.end >= range.start ? 1.0 : -1.0;
  const double k = std::ceil((limit.input - range.start) * direction / range.step - 1e-9);
  const double start = range.start + direction * std::max(0.0, k) * range.step;
  // The limit lies between the drawing and the start: the grid goes on past it only when the
  // drawing is ahead of the start in the sweep's direction, and then up to the end at most.
  if ((drawn - range.start) * direction <= 0.0 || (start - range.end) * direction > 1e-9 * range.step) {
    a.warnings.push_back(fmt::format("no input of the sweep {} .. {} is reachable from the drawn configuration ({}): "
                                     "dead point at {}", shown(mech, driver, range.start), shown(mech, driver, range.end),
                                     shown(mech, driver, drawn), shown(mech, driver, limit.input)));
    return std::nullopt;
  }
  data.q = drawn_q;
  data.inputs(driver) = drawn;
  if (!continue_from_drawing(mech, data, driver, start, a)) return std::nullopt;
  a.warnings.push_back(fmt::format("the sweep's start {} is not reachable from the drawn configuration ({}): dead point "
                                   "at {}; swept from {} (inputs before it were not reached)", shown(mech, driver, range.start),
                                   shown(mech, driver, drawn), shown(mech, driver, limit.input), shown(mech, driver, start)));
  return start;
}

}  // namespace

namespace {

// The loads at a change point: Phi_q is singular, the multipliers are not unique (the reactions
// are statically indeterminate), but the driving effort follows from virtual power along the
// branch followed, -Q* . dq, finite and continuous with its neighbours.
void efforts_at_change_point(const kin::Model& m, const kin::Data& data, int driver, const Eigen::VectorXd& dq,
                             kin::ForceAnalysis& f) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  f = kin::ForceAnalysis{};
  f.applied = kin::applied_forces(m, data);
  f.determinate = false;
  for (std::size_t k = 0; k < m.drivers().size(); ++k) {
    f.effort_virtual_power.push_back(static_cast<int>(k) == driver ? -f.applied.dot(dq) : nan);
    f.effort_lagrange.push_back(nan);
  }
}

}  // namespace

void describe_position(const mechanism::Mechanism& mech, const std::optional<kin::FourBar>& four_bar, kin::Data& data,
                       int driver, double input, const Eigen::VectorXd* known_dq, KinPosition& p, bool on_change_point) {
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
  p.on_change_point = on_change_point;
  if (mech.model.has_loads()) {
    if (!p.forces) p.forces.emplace();
    if (on_change_point && have_dq) efforts_at_change_point(mech.model, data, driver, dq, *p.forces);
    else kin::solve_forces(mech.model, data, driver, *p.forces);  // reuses the last position's storage
  } else {
    p.forces.reset();
  }
}

KinAnalysis analyse_single(const mechanism::Mechanism& mech, kin::Data& data, int driver, std::optional<double> at,
                           const kin::DofReport& dof, bool switch_branch) {
  KinAnalysis a;
  a.single = true;
  a.driver = driver;
  a.dof = dof;
  const kin::Model& m = mech.model;
  const double value = at ? *at : data.inputs(driver);
  kin::SweepSample reached;
  if (!continue_from_drawing(mech, data, driver, value, a, switch_branch, &reached)) return a;
  if (reached.on_change_point && reached.input == value && reached.qd.size() > 0) {
    // On a change point: the continuation's interpolated sample is the position (Newton would
    // stop within sqrt(tolerance) of it, on a singular Jacobian).
    data.q = reached.q;
    data.qd = reached.qd;
    data.qdd = reached.qdd;
    data.inputs(driver) = value;
    describe_position(mech, kin::find_four_bar(m), data, driver, value, &reached.dq, a.positions.emplace_back(), true);
    for (int b = 0; b < static_cast<int>(m.bodies().size()); ++b) a.instant_centres.push_back(kin::instant_centre(data.q, reached.dq, b));
    return a;
  }
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
                          const kin::DofReport& dof, const PositionSink& sink, bool switch_branch) {
  KinAnalysis a;
  a.driver = driver;
  a.dof = dof;
  const kin::Model& m = mech.model;
  kin::SweepOptions o = sweep_options(driver, range.start, range.end, range.step, true, switch_branch);
  o.outputs = mech.outputs;
  // A sample the sweep's workspace is not factorised at is analysed in a Data of its own: that
  // workspace carries the continuation state from one sample to the next (sample_workspace()).
  kin::Data probe(m);
  KinPosition p;
  const std::optional<kin::FourBar> four_bar = kin::find_four_bar(m);
  io::Progress progress("kin", static_cast<std::size_t>(kin::sweep_sample_count(o)));
  std::size_t done = 0;
  kin::SweepResult s;
  const auto visit = [&](const kin::SweepSample& sample) {
    progress.update(done++);
    kin::Data& at = sample_workspace(m, driver, sample, probe);
    describe_position(mech, four_bar, at, driver, sample.input, &sample.dq, p, sample.on_change_point);
    // kin::sweep records a dead point before it visits the position there.
    p.at_dead_point = !s.dead_points.empty() && s.dead_points.back().input == sample.input;
    sink(p);
  };
  const Eigen::VectorXd drawn_q = data.q;
  const double drawn = data.inputs(driver);
  approach_start(mech, data, driver, o);
  kin::sweep(m, data, o, s, visit);
  if (!s.assembled) {
    // Not at the start: sweep from the first input the drawing reaches (a double rocker's input
    // between its limits), naming the limit as a dead point.
    data.q = drawn_q;
    data.inputs(driver) = drawn;
    if (const std::optional<double> start = reachable_start(mech, data, driver, range, a)) {
      o.start = *start;
      kin::sweep(m, data, o, s, visit);
    }
  }
  a.dead_points.insert(a.dead_points.end(), s.dead_points.begin(), s.dead_points.end());
  a.extremes = s.extremes;
  note_change_points(mech, driver, s, a);
  for (const kin::DeadPoint& d : s.dead_points)
    a.warnings.push_back(fmt::format("dead point at input {:.6f} {}: the driver cannot move the mechanism past it; "
                                     "the sweep stops there instead of jumping to another assembly branch",
                                     shown_input(mech, driver, d.input), input_unit(mech, driver)));
  return a;
}

}  // namespace gearkit::cli
