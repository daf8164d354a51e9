// `gearkit synth path FILE`: a four-bar whose coupler point passes near target points, by global
// optimisation (NLopt) under Grashof, transmission-angle, link-ratio and pivot-region constraints.
#include "synth_output.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/synth/path_generation.hpp>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace gearkit::plugins::synth {

namespace {

constexpr double pi = std::numbers::pi;

gs::Region read_region(io::MapReader& r, const std::string& key) {
  io::MapReader m = r.map(key);
  const auto range = [&](const char* axis) {
    const YAML::Node n = m.node(axis);
    if (!n.IsSequence() || n.size() != 2) io::fail_at(m.mark(axis), fmt::format("expected {}: [min, max]", axis));
    const double lo = io::scalar_quantity(n[0], r.file(), io::Quantity::length, "mm");
    const double hi = io::scalar_quantity(n[1], r.file(), io::Quantity::length, "mm");
    if (!(hi >= lo)) io::fail_at(m.mark(axis), "expected min <= max");
    return std::pair{lo, hi};
  };
  const auto [x0, x1] = range("x");
  const auto [y0, y1] = range("y");
  m.finish();
  return {gs::Vec2(x0, y0), gs::Vec2(x1, y1)};
}

gs::PathConstraints read_constraints(io::MapReader& r) {
  gs::PathConstraints c;
  if (!r.has("constraints")) return c;
  io::MapReader m = r.map("constraints");
  const std::string type = m.choice("grashof", {"crank", "crank-rocker", "double-crank", "any"}, "crank");
  c.grashof = type == "crank-rocker"   ? gs::GrashofType::crank_rocker
              : type == "double-crank" ? gs::GrashofType::double_crank
              : type == "any"          ? gs::GrashofType::any
                                       : gs::GrashofType::crank;
  c.min_transmission = m.quantity_or("min_transmission", io::Quantity::angle, "deg", c.min_transmission);
  c.max_link_ratio = m.optional_number("max_link_ratio").value_or(c.max_link_ratio);
  if (const auto n = m.optional_node("link_length")) {
    if (!n->IsSequence() || n->size() != 2) io::fail_at(m.mark("link_length"), "expected link_length: [min, max]");
    c.min_link = io::scalar_quantity((*n)[0], r.file(), io::Quantity::length, "mm");
    c.max_link = io::scalar_quantity((*n)[1], r.file(), io::Quantity::length, "mm");
    if (!(*c.min_link > 0 && *c.max_link > *c.min_link)) io::fail_at(m.mark("link_length"), "expected 0 < min < max");
  }
  if (m.has("O2_region")) c.O2_region = read_region(m, "O2_region");
  if (m.has("O4_region")) c.O4_region = read_region(m, "O4_region");
  m.finish();
  return c;
}

void read_budget(io::MapReader& r, gs::PathTask& t, const Overrides& o) {
  t.budget.evaluations = gs::default_path_evaluations(t.points.size());
  if (r.has("optimiser")) {
    io::MapReader m = r.map("optimiser");
    if (const auto e = m.optional_integer("evaluations")) t.budget.evaluations = static_cast<long>(std::clamp<long long>(*e, 0, 1LL << 40));
    if (const auto e = m.optional_integer("restarts")) t.budget.restarts = static_cast<int>(std::clamp<long long>(*e, 0, 1 << 20));
    if (const auto e = m.optional_integer("seed")) t.budget.seed = static_cast<unsigned>(std::clamp<long long>(*e, 0, 4294967295LL));
    m.finish();
  }
  if (o.evaluations) t.budget.evaluations = *o.evaluations;
  if (o.restarts) t.budget.restarts = *o.restarts;
  if (o.seed) t.budget.seed = *o.seed;
  const long points = static_cast<long>(t.points.size());
  if (t.budget.evaluations < 1000 || t.budget.evaluations > gs::kMaxEvaluations || t.budget.evaluations * points > gs::kMaxPointEvaluations) {
    const std::string m = fmt::format("expected evaluations 1000..{} with evaluations x points <= {}, found {} x {}",
                                      gs::kMaxEvaluations, gs::kMaxPointEvaluations, t.budget.evaluations, points);
    if (o.evaluations) io::fail_option("--evaluations", m);
    io::fail_at(r.mark("optimiser"), m);
  }
  if (t.budget.restarts < 1 || t.budget.restarts > gs::kMaxRestarts) {
    const std::string m = fmt::format("expected restarts 1..{}, found {}", gs::kMaxRestarts, t.budget.restarts);
    if (o.restarts) io::fail_option("--restarts", m);
    io::fail_at(r.mark("optimiser"), m);
  }
}

void add_targets_table(const gs::PathTask& t, const gs::PathResult& r, Output& out) {
  io::Table tab{"Targets", {"#", "target [mm]", "coupler point [mm]", "distance [mm]", "crank theta2 [deg]"}, {}};
  nlohmann::json j = nlohmann::json::array();
  for (std::size_t k = 0; k < t.points.size(); ++k) {
    const gs::Vec2 &T = t.points[k], &C = r.reached[k];
    tab.add_row({std::to_string(k + 1), fmt::format("({}, {})", mm(T.x()), mm(T.y())), fmt::format("({}, {})", mm(C.x()), mm(C.y())),
                 mm((C - T).norm()), deg(r.theta2[k])});
    j.push_back({{"target_mm", {T.x() * 1000, T.y() * 1000}}, {"reached_mm", {C.x() * 1000, C.y() * 1000}},
                 {"distance_mm", (C - T).norm() * 1000}, {"theta2_deg", r.theta2[k] * 180 / pi}});
  }
  out.report.tables.push_back(std::move(tab));
  out.report.json["targets"] = j;
  out.report.json["tracking_error_mm2"] = r.error * 1e6;
  out.report.json["max_distance_mm"] = r.max_distance * 1000;
  out.report.json["evaluations"] = r.evaluations;
  out.report.json["restarts"] = r.restarts;
  out.report.json["seed"] = t.budget.seed;
  out.report.notes.push_back(fmt::format("Tracking error sum of squared distances {:.6g} mm^2, largest distance {} mm, after {} "
                                         "evaluations in {} restarts (seed {}).", r.error * 1e6, mm(r.max_distance), r.evaluations,
                                         r.restarts, t.budget.seed));
}

}  // namespace

Output run_path_task(const io::YamlDocument& doc, const Overrides& overrides) {
  io::MapReader r(doc.root, doc.file, "path-generation task");
  gs::PathTask t;
  const std::string title = r.optional_string("synthesis").value_or("");
  for (const YAML::Node& n : r.sequence("points")) t.points.push_back(read_point(n, doc.file));
  if (t.points.size() < 3 || t.points.size() > static_cast<std::size_t>(gs::kMaxPathPoints))
    io::fail_at(r.mark("points"), fmt::format("expected 3..{} points, found {}", gs::kMaxPathPoints, t.points.size()));
  if (r.has("timing")) t.timing = read_angles(r.node("timing"), doc.file);
  t.constraints = read_constraints(r);
  read_budget(r, t, overrides);
  r.finish();
  const gs::PathResult res = gs::synthesize_path(t);
  Output out;
  out.report.title = title.empty() ? fmt::format("Path generator through {} points", t.points.size()) : title;
  out.report.json["task"] = "path";
  add_targets_table(t, res, out);
  add_four_bar_tables(res.linkage, res.defects, res.transmission, out.report);
  const bool full = gs::crank_turns_fully(res.linkage);
  const double travel = full ? 2 * pi : res.defects.travel;
  add_four_bar_summary(res.linkage, res.theta2[0], travel, res.defects.direction, overrides.min_transmission_angle,
                       res.defects.ok(), out.report);
  gs::MechanismSketch sketch = gs::four_bar_sketch(res.linkage, res.theta2[0], travel, res.defects.direction, out.report.title);
  sketch.comments = {fmt::format("Path generator: the coupler point P passes near {} target points (gearkit synth, seed {}).",
                                 t.points.size(), t.budget.seed)};
  out.mechanism_yaml = gs::to_mechanism_yaml(sketch);
  std::vector<Checkpoint> checks;
  for (std::size_t k = 0; k < t.points.size(); ++k)
    checks.push_back({unwrapped(res.theta2[0], res.theta2[k], res.defects.direction), res.reached[k], std::nullopt, "", false});
  verify_with_solver(out.mechanism_yaml, checks, out.report);
  draw_four_bar(res.linkage, res.theta2, travel, res.defects.direction, out.drawing);
  double span = 0;
  for (const gs::Vec2& p : t.points) span = std::max(span, (p - t.points[0]).norm());
  draw_targets(t.points, span / 80, out.drawing);
  out.plot = transmission_plot(res.linkage, res.theta2[0], travel, res.defects.direction, out.report.title);
  return out;
}

}  // namespace gearkit::plugins::synth
