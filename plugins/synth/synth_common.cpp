// The parts every synthesis task shares: the solver check of the written mechanism, the
// four-bar's tables, drawing and transmission chart, and small readers.
#include "synth_output.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/mechanism/reader.hpp>
#include <gearkit/kin/fourbar.hpp>
#include <gearkit/kin/sweep.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace gearkit::plugins::synth {

namespace {

constexpr double pi = std::numbers::pi;

double output_value(const mechanism::Mechanism& mech, const kin::Data& data, const std::string& name) {
  for (const kin::Output& o : mech.outputs)
    if (o.name == name) return kin::evaluate_output(mech.model, data, o).value;
  throw std::logic_error("synth: the written mechanism lacks output " + name);
}

// Moves the driver from its current input to `value` by continuation; false at a dead point.
bool reach(const mechanism::Mechanism& mech, kin::Data& data, double from, double value) {
  if (std::abs(value - from) > 1e-9) {
    kin::SweepOptions o;
    o.start = from;
    o.end = value;
    o.step = std::min(pi / 180, std::abs(value - from) / 4);
    o.velocities = false;
    o.min_step = 1e-9 * std::max(1.0, std::abs(value - from));
    const kin::SweepResult s = kin::sweep(mech.model, data, o);
    if (!s.complete) return false;
    data.q = s.samples.back().q;
  }
  const kin::PositionReport r = kin::solve_at(mech.model, data, 0, value);
  return r.converged;
}

}  // namespace

double verify_with_solver(const std::string& yaml, const std::vector<Checkpoint>& checkpoints, io::Report& report) {
  // The file has only revolute and prismatic joints: no element type to look up.
  const mechanism::Mechanism mech = mechanism::read_mechanism(io::load_yaml_text(yaml, "synthesised mechanism"),
                                                              [](std::string_view) { return nullptr; });
  kin::Data data(mech.model);
  double current = data.inputs(0), distance = 0, angle = 0;  // worst misses [m], [rad]
  // A position may carry several checkpoints (a pose: its point and its angle) at one crank angle.
  std::size_t positions = 0;
  for (std::size_t j = 0; j < checkpoints.size(); ++j) {
    const Checkpoint& c = checkpoints[j];
    if (j == 0 || c.theta2 != checkpoints[j - 1].theta2) ++positions;
    if (!reach(mech, data, current, c.theta2)) {
      report.warnings.push_back(fmt::format("solver check: gearkit kin cannot drive the written mechanism to "
                                            "position {} (crank at {} deg)", positions, deg(c.theta2)));
      return std::numeric_limits<double>::infinity();
    }
    current = c.theta2;
    if (c.output && c.angular)
      angle = std::max(angle, std::abs(std::remainder(output_value(mech, data, c.output_name) - *c.output, 2 * pi)));
    else if (c.output)
      distance = std::max(distance, std::abs(output_value(mech, data, c.output_name) - *c.output));
    else
      distance = std::max(distance, std::hypot(output_value(mech, data, "Px") - c.point.x(), output_value(mech, data, "Py") - c.point.y()));
  }
  report.json["solver_check_max_miss_mm"] = distance * 1000;
  report.json["solver_check_max_miss_deg"] = angle * 180 / pi;
  // 1e-8 m and 1e-8 rad: a hundred times the solver's residual tolerance.
  if (distance > 1e-8 || angle > 1e-8)
    report.warnings.push_back(fmt::format("solver check: the written mechanism misses a precision position by {:.3g} mm "
                                          "or {:.3g} deg", distance * 1000, angle * 180 / pi));
  else
    report.notes.push_back(fmt::format("Solver check: gearkit kin, driven through the {} precision positions from the "
                                       "written file, reaches each within {:.1e} mm and {:.1e} deg.", positions,
                                       distance * 1000, angle * 180 / pi));
  return std::max(distance, angle);
}

double unwrapped(double start, double t2, int direction) {
  return start + direction * gs::wrap_two_pi(direction * (t2 - start));
}

std::string mm(double metres) { return io::fixed(metres * 1000, 3); }
std::string deg(double radians) { return io::fixed(radians * 180 / pi, 3); }

void add_four_bar_tables(const gs::FourBar& f, const gs::DefectReport& defects, const gs::TransmissionRange& mu,
                         io::Report& report) {
  io::Table t{"Linkage", {"link", "from", "to", "length [mm]"}, {}};
  t.add_row({"ground", fmt::format("O2 ({}, {})", mm(f.O2.x()), mm(f.O2.y())), fmt::format("O4 ({}, {})", mm(f.O4.x()), mm(f.O4.y())), mm(f.ground())});
  t.add_row({"crank", "O2", "A", mm(f.crank)});
  t.add_row({"coupler", "A", "B", mm(f.coupler)});
  t.add_row({"rocker", "O4", "B", mm(f.rocker)});
  t.add_row({"coupler point", "A", fmt::format("P ({}, {}) in the coupler frame", mm(f.coupler_point.x()), mm(f.coupler_point.y())),
             mm(f.coupler_point.norm())});
  report.tables.push_back(std::move(t));
  const kin::GrashofResult g = kin::grashof(f.ground(), f.crank, f.coupler, f.rocker);
  io::Table c{"Checks", {"check", "result"}, {}};
  c.add_row({"Grashof", g.text});
  c.add_row({"input link", gs::crank_turns_fully(f) ? "crank: turns fully" : "rocker: limited swing"});
  c.add_row({"defects", defects.ok() ? "none (branch, order, Grashof)" : fmt::format("{}", fmt::join(defects.notes, "; "))});
  c.add_row({"transmission angle over the task's travel [deg]", fmt::format("{} .. {}", deg(mu.min), deg(mu.max))});
  report.tables.push_back(std::move(c));
  report.json["linkage"] = {{"O2_mm", {f.O2.x() * 1000, f.O2.y() * 1000}},
                            {"O4_mm", {f.O4.x() * 1000, f.O4.y() * 1000}},
                            {"ground_mm", f.ground() * 1000},
                            {"crank_mm", f.crank * 1000},
                            {"coupler_mm", f.coupler * 1000},
                            {"rocker_mm", f.rocker * 1000},
                            {"coupler_point_mm", {f.coupler_point.x() * 1000, f.coupler_point.y() * 1000}},
                            {"branch", f.branch}};
  report.json["grashof"] = g.text;
  report.json["crank_turns_fully"] = gs::crank_turns_fully(f);
  report.json["defects"] = defects.notes;
  report.json["transmission_angle_min_deg"] = mu.min * 180 / pi;
  report.json["transmission_angle_max_deg"] = mu.max * 180 / pi;
  // The transmission angle's warning comes from the summary, over the motion really made.
  for (const std::string& n : defects.notes) report.warnings.push_back(n);
}

void draw_four_bar(const gs::FourBar& f, const std::vector<double>& theta2, double travel, int direction,
                   io::Drawing& d) {
  for (const io::Layer& l : std::vector<io::Layer>{{"linkage", 7, "#000", false}, {"positions", 8, "#999", false},
                                                   {"coupler_curve", 5, "#1f77b4", false}, {"targets", 1, "#d62728", false},
                                                   {"pivots", 7, "#000", false}})
    if (std::none_of(d.layers.begin(), d.layers.end(), [&](const io::Layer& e) { return e.name == l.name; })) d.layers.push_back(l);
  const auto mm_xy = [](const gs::Vec2& p) { return io::Vertex{p.x() * 1000, p.y() * 1000, 0}; };
  const double r = std::max({f.crank, f.coupler, f.rocker, f.ground()}) * 1000 / 60;
  // Up to five positions are drawn in full; beyond that only the first and the curve.
  const std::size_t drawn = theta2.size() <= 5 ? theta2.size() : 1;
  for (std::size_t j = 0; j < drawn; ++j) {
    const auto pose = gs::pose_at(f, theta2[j]);
    if (!pose) continue;
    const std::string layer = j == 0 ? "linkage" : "positions";
    d.polylines.push_back({layer, {mm_xy(f.O2), mm_xy(pose->A), mm_xy(pose->B), mm_xy(f.O4)}, false});
    d.polylines.push_back({layer, {mm_xy(pose->A), mm_xy(pose->P), mm_xy(pose->B)}, false});
    for (const gs::Vec2& p : {pose->A, pose->B}) d.circles.push_back({layer, p.x() * 1000, p.y() * 1000, r / 2});
    d.texts.push_back({layer, pose->P.x() * 1000 + r, pose->P.y() * 1000 + r, 1.5 * r, fmt::format("{}", j + 1)});
  }
  for (const auto& [name, p] : {std::pair{"O2", f.O2}, std::pair{"O4", f.O4}}) {
    d.circles.push_back({"pivots", p.x() * 1000, p.y() * 1000, r});
    d.texts.push_back({"pivots", p.x() * 1000 + 1.5 * r, p.y() * 1000 - 3 * r, 2 * r, name});
  }
  io::Polyline curve{"coupler_curve", {}, false};
  const int n = std::max(2, static_cast<int>(std::ceil(travel / (pi / 180))));
  for (int k = 0; k <= n; ++k)
    if (const auto pose = gs::pose_at(f, theta2.front() + direction * travel * k / n)) curve.vertices.push_back(mm_xy(pose->P));
  if (curve.vertices.size() > 1) d.polylines.push_back(std::move(curve));
}

void draw_targets(const std::vector<gs::Vec2>& points, double radius, io::Drawing& d) {
  for (const gs::Vec2& p : points) d.circles.push_back({"targets", p.x() * 1000, p.y() * 1000, radius * 1000});
}

io::Plot transmission_plot(const gs::FourBar& f, double start, double travel, int direction, const std::string& title) {
  io::Series s{"transmission angle [deg]", {}, {}, ""};
  const int n = std::max(2, static_cast<int>(std::ceil(travel / (pi / 360))));
  for (int k = 0; k <= n; ++k) {
    const double theta2 = start + direction * travel * k / n;
    const auto pose = gs::pose_at(f, theta2);
    s.x.push_back(theta2 * 180 / pi);
    s.y.push_back(pose ? gs::transmission_angle(*pose, f) * 180 / pi : std::numeric_limits<double>::quiet_NaN());
  }
  return {title, "crank angle theta2 [deg]", {{"transmission angle mu [deg]", {s}, {}}}, 800, 260};
}

gs::Vec2 read_point(const YAML::Node& node, const std::string& file) {
  if (!node.IsSequence() || node.size() != 2) io::fail_at(io::mark_of(node, file), "expected a point [x, y]");
  return {io::scalar_quantity(node[0], file, io::Quantity::length, "mm"),
          io::scalar_quantity(node[1], file, io::Quantity::length, "mm")};
}

std::vector<double> read_angles(const YAML::Node& node, const std::string& file) {
  if (!node.IsSequence()) io::fail_at(io::mark_of(node, file), "expected a list of angles");
  std::vector<double> a;
  for (const YAML::Node& n : node) a.push_back(io::scalar_quantity(n, file, io::Quantity::angle, "deg"));
  return a;
}

}  // namespace gearkit::plugins::synth
