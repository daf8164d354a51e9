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

// A sweep of the driver from `from` to `to` by `step`, dead points located to 1e-9 of its span;
// positions only unless `velocities`.
kin::SweepOptions sweep_options(int driver, double from, double to, double step, bool velocities) {
  kin::SweepOptions o;
  o.driver = driver;
  o.start = from;
  o.end = to;
  o.step = step;
  o.velocities = velocities;
  o.min_step = 1e-9 * std::max(1.0, std::abs(to - from));
  return o;
}

// Reaches `value` from the drawn input by continuation in 2 deg (2 mm) steps, so that the
// position stays on the drawing's assembly branch (Newton from a distant guess may land on
// another). @returns false with a warning in `a` when a dead point is in the way.
bool continue_from_drawing(const mechanism::Mechanism& mech, kin::Data& data, int driver, double value, KinAnalysis& a) {
  const double drawn = data.inputs(driver);
  const double step = angular(mech, driver) ? 2.0 * std::numbers::pi / 180.0 : 0.002;
  if (std::abs(value - drawn) <= step) return true;
  const kin::SweepResult s = kin::sweep(mech.model, data, sweep_options(driver, drawn, value, step, false));
  if (s.complete) {
    data.q = s.samples.back().q;
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
  const kin::SweepResult s = kin::sweep(mech.model, data, sweep_options(driver, drawn, range.start, range.step, false));
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

// The flat positions of a change-point four-bar (s + l = p + q) that a sweep passes: the crank
// lies on the ground line and the coupler and rocker in line, and the parallelogram and
// anti-parallelogram branches cross there, so the continuation may go on along either without
// any check noticing (the determinant's sign need not change). Fed the crank angle of each sample.
class PassedFlatPositions {
 public:
  explicit PassedFlatPositions(const std::optional<kin::FourBar>& fb) {
    if (!fb || kin::grashof(fb->ground, fb->crank_length, fb->coupler_length, fb->rocker_length).kind !=
                   kin::GrashofClass::change_point)
      return;
    crank_ = fb->crank;
    const Eigen::Vector2d ground_line = fb->o4.local - fb->o2.local;  // ground points: local is global
    ground_angle_ = std::atan2(ground_line.y(), ground_line.x());
    const double b = fb->coupler_length, c = fb->rocker_length, tolerance = 1e-9 * (fb->ground + fb->crank_length + b + c);
    const auto flat = [&](double a_o4) { return std::abs(a_o4 - (b + c)) <= tolerance || std::abs(a_o4 - std::abs(b - c)) <= tolerance; };
    flat_at_zero_ = flat(std::abs(fb->ground - fb->crank_length));
    flat_at_pi_ = flat(fb->ground + fb->crank_length);
  }

  void add(const Eigen::VectorXd& q) {
    if (crank_ < 0) return;
    const double phi = q(3 * crank_ + 2) - ground_angle_;  // from the line O2 O4
    if (last_) {
      const double lo = std::min(*last_, phi), hi = std::max(*last_, phi);
      for (double k = std::ceil(lo / std::numbers::pi); k * std::numbers::pi <= hi; ++k) {
        const bool even = std::fmod(std::abs(k), 2.0) == 0.0;
        if ((even ? flat_at_zero_ : flat_at_pi_) && k * std::numbers::pi > lo) crossings_.push_back(k * std::numbers::pi);
      }
    }
    last_ = phi;
  }

  /// The crank angles [rad] of the flat positions passed with samples beyond them.
  std::vector<double> passed() const {
    std::vector<double> out;
    for (const double c : crossings_)
      if (last_ && std::abs(c - *last_) > 1e-9) out.push_back(c + ground_angle_);
    return out;
  }

 private:
  int crank_ = -1;
  double ground_angle_ = 0.0;
  bool flat_at_zero_ = false, flat_at_pi_ = false;
  std::optional<double> last_;
  std::vector<double> crossings_;
};

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
  kin::SweepOptions o = sweep_options(driver, range.start, range.end, range.step, true);
  o.outputs = mech.outputs;
  // Each sample is analysed further (reactions, outputs) in a Data of its own: the sweep's
  // workspace carries its continuation state from one sample to the next.
  kin::Data probe(m);
  KinPosition p;
  const std::optional<kin::FourBar> four_bar = kin::find_four_bar(m);
  io::Progress progress("kin", static_cast<std::size_t>(kin::sweep_sample_count(o)));
  std::size_t done = 0;
  kin::SweepResult s;
  const bool loads = m.has_loads();
  PassedFlatPositions flat(four_bar);
  const auto visit = [&](const kin::SweepSample& sample) {
    progress.update(done++);
    flat.add(sample.q);
    probe.q = sample.q;
    probe.inputs(driver) = sample.input;
    if (loads || sample.qd.size() == 0) {
      kin::solve_at(m, probe, driver, sample.input);  // the reactions need Phi_q factorised here
    } else {
      probe.qd = sample.qd;  // the sweep solved them: outputs need q, qd, qdd and dq only
      probe.qdd = sample.qdd;
    }
    describe_position(mech, four_bar, probe, driver, sample.input, &sample.dq, p);
    // kin::sweep records a dead point before it visits the position there.
    p.at_dead_point = !s.dead_points.empty() && s.dead_points.back().input == sample.input;
    sink(p);
  };
  const Eigen::VectorXd drawn_q = data.q;
  const double drawn = data.inputs(driver);
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
  for (const double phi : flat.passed())
    a.warnings.push_back(fmt::format("the sweep passed the change point at crank angle {:.6g} deg, where the four-bar lies "
                                     "flat (s + l = p + q): past it the motion may go on along either branch (parallelogram "
                                     "or anti-parallelogram) and the sweep does not check which; compare with a drawing on "
                                     "each side", phi * kRadToDeg));
  // A four-bar with s + l = p + q stops where it flattens: two branches cross there (a change
  // point), and the sweep does not choose one; the driver could move it on.
  bool change_point = false;
  if (four_bar)
    change_point = kin::grashof(four_bar->ground, four_bar->crank_length, four_bar->coupler_length,
                                four_bar->rocker_length).kind == kin::GrashofClass::change_point;
  for (const kin::DeadPoint& d : s.dead_points)
    a.warnings.push_back(
        change_point
            ? fmt::format("change point at input {:.6f} {}: the four-bar lies flat and two branches cross (s + l = p + q); "
                          "the sweep stops there rather than choose one (sweep on from a drawing past it)",
                          shown_input(mech, driver, d.input), input_unit(mech, driver))
            : fmt::format("dead point at input {:.6f} {}: the driver cannot move the mechanism past it; "
                          "the sweep stops there instead of jumping to another assembly branch",
                          shown_input(mech, driver, d.input), input_unit(mech, driver)));
  return a;
}

}  // namespace gearkit::cli
