// `gearkit synth motion FILE`: a four-bar that guides its coupler through 2 to 5 poses — two
// and three positions by the textbook constructions with the free choices as options (or
// searched), four and five positions by Burmester theory.
#include "synth_output.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/synth/burmester.hpp>
#include <gearkit/synth/motion_generation.hpp>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace gearkit::plugins::synth {

namespace {

constexpr double pi = std::numbers::pi;

struct MotionFile {
  std::string title;
  std::vector<gs::Pose> poses;
  bool from_points = false;           // poses given as C/D pairs: C1, D1 are the default moving pivots
  std::vector<gs::Vec2> C1D1;
  bool require_crank = false;
  double max_link_ratio = 10;
  std::optional<int> grid, samples;
};

gs::Pose read_pose(const YAML::Node& node, const std::string& file, MotionFile& f) {
  io::MapReader r(node, file, "position");
  gs::Pose p;
  if (r.has("C")) {
    const gs::Vec2 C = read_point(r.node("C"), file), D = read_point(r.node("D"), file);
    if ((D - C).norm() == 0) io::fail_at(r.mark("D"), "expected D apart from C");
    p = gs::pose_from_points(C, D);
    f.from_points = true;
    if (f.C1D1.empty()) f.C1D1 = {C, D};
  } else {
    p.point = read_point(r.node("point"), file);
    p.angle = r.quantity("angle", io::Quantity::angle, "deg");
  }
  r.finish();
  return p;
}

std::pair<gs::Vec2, gs::Vec2> read_two_points(io::MapReader& r, const std::string& key, const char* a, const char* b) {
  io::MapReader m = r.map(key);
  const auto out = std::pair{read_point(m.node(a), r.file()), read_point(m.node(b), r.file())};
  m.finish();
  return out;
}

// Two positions: the moving pivots (given, or C1 and D1) and the bisector offsets (given or searched).
gs::MotionCandidate two_positions(io::MapReader& r, const MotionFile& f, Output& out) {
  std::pair<gs::Vec2, gs::Vec2> m;
  if (r.has("moving_pivots")) m = read_two_points(r, "moving_pivots", "A", "B");
  else if (f.from_points) m = {f.C1D1[0], f.C1D1[1]};
  else io::fail_at(r.mark(), "expected 'moving_pivots: {A: [x, y], B: [x, y]}' (pose 1) for two positions given by point and angle");
  if (const auto n = r.optional_node("bisector_offsets")) {
    if (!n->IsSequence() || n->size() != 2) io::fail_at(r.mark("bisector_offsets"), "expected [offset A, offset B]");
    const double sa = io::scalar_quantity((*n)[0], r.file(), io::Quantity::length, "mm");
    const double sb = io::scalar_quantity((*n)[1], r.file(), io::Quantity::length, "mm");
    out.report.notes.push_back(fmt::format("Free choices: ground pivots {} mm and {} mm along the perpendicular bisectors.", mm(sa), mm(sb)));
    return gs::four_bar_from_dyads(f.poses, gs::dyad_two_positions(f.poses[0], f.poses[1], m.first, sa),
                                   gs::dyad_two_positions(f.poses[0], f.poses[1], m.second, sb), f.require_crank);
  }
  out.report.notes.push_back("Free choices: the ground pivots' places on the perpendicular bisectors were searched for the best transmission angle.");
  return gs::best_two_position(f.poses, m.first, m.second, f.grid.value_or(41), f.max_link_ratio, f.require_crank);
}

gs::MotionCandidate three_positions(io::MapReader& r, const MotionFile& f, Output& out) {
  const int given = r.has("moving_pivots") + r.has("fixed_pivots") + r.has("rotations");
  if (given > 1) io::fail_at(r.mark(), "expected one of 'moving_pivots', 'fixed_pivots' or 'rotations', not several");
  if (r.has("moving_pivots")) {
    const auto [A, B] = read_two_points(r, "moving_pivots", "A", "B");
    out.report.notes.push_back("Free choices: the moving pivots (Norton's three-position synthesis with specified moving pivots).");
    return gs::four_bar_from_dyads(f.poses, gs::dyad_from_moving_pivot(f.poses, A), gs::dyad_from_moving_pivot(f.poses, B), f.require_crank);
  }
  if (r.has("fixed_pivots")) {
    const auto [O2, O4] = read_two_points(r, "fixed_pivots", "O2", "O4");
    out.report.notes.push_back("Free choices: the fixed pivots (Norton's three-position synthesis with specified fixed pivots, by inversion).");
    return gs::four_bar_from_dyads(f.poses, gs::dyad_from_ground_pivot(f.poses, O2), gs::dyad_from_ground_pivot(f.poses, O4), f.require_crank);
  }
  if (r.has("rotations")) {
    io::MapReader m = r.map("rotations");
    const auto in = read_angles(m.node("input"), r.file()), o = read_angles(m.node("output"), r.file());
    m.finish();
    if (in.size() != 2 || o.size() != 2) io::fail_at(r.mark("rotations"), "expected input: [beta2, beta3] and output: [gamma2, gamma3]");
    out.report.notes.push_back(fmt::format("Free choices: beta2 = {}, beta3 = {}, gamma2 = {}, gamma3 = {} deg (Norton's analytical three-position synthesis).",
                                           deg(in[0]), deg(in[1]), deg(o[0]), deg(o[1])));
    return gs::four_bar_from_dyads(f.poses, gs::dyad_from_rotations(f.poses, in[0], in[1]), gs::dyad_from_rotations(f.poses, o[0], o[1]), f.require_crank);
  }
  out.report.notes.push_back("Free choices: the moving pivots were searched over a grid for a defect-free linkage with the best transmission angle.");
  return gs::best_three_position(f.poses, f.grid.value_or(16), f.max_link_ratio, f.require_crank);
}

// Runs of consecutive samples of the Burmester curves as polylines (mm), kept within five
// times the poses' spread of their centre (the curves run off to infinity).
void draw_burmester_curves(const std::vector<gs::Pose>& poses, const std::vector<gs::BurmesterDyad>& family, io::Drawing& d) {
  d.layers.push_back({"centre_point_curve", 3, "#2ca02c", false});
  d.layers.push_back({"circle_point_curve", 6, "#9467bd", true});
  gs::Vec2 middle(0, 0);
  double spread = 0;
  for (const gs::Pose& p : poses) middle += p.point / static_cast<double>(poses.size());
  for (const gs::Pose& p : poses) spread = std::max(spread, (p.point - middle).norm());
  const double reach = 5 * std::max(spread, 1e-9);
  io::Polyline centre{"centre_point_curve", {}, false}, circle{"circle_point_curve", {}, false};
  for (std::size_t k = 0; k < family.size(); ++k) {
    const gs::Dyad& g = family[k].dyad;
    const bool outside = (g.ground_pivot - middle).norm() > reach || (g.moving_pivot - middle).norm() > reach;
    const bool jump = outside || (k > 0 && ((family[k - 1].dyad.ground_pivot - g.ground_pivot).norm() > 0.2 * reach ||
                                            family[k - 1].closure != family[k].closure));
    if (jump) {
      if (centre.vertices.size() > 1) d.polylines.push_back(centre);
      if (circle.vertices.size() > 1) d.polylines.push_back(circle);
      centre.vertices.clear();
      circle.vertices.clear();
    }
    if (outside) continue;
    centre.vertices.push_back({g.ground_pivot.x() * 1000, g.ground_pivot.y() * 1000, 0});
    circle.vertices.push_back({g.moving_pivot.x() * 1000, g.moving_pivot.y() * 1000, 0});
  }
  if (centre.vertices.size() > 1) d.polylines.push_back(centre);
  if (circle.vertices.size() > 1) d.polylines.push_back(circle);
}

gs::MotionCandidate four_positions(io::MapReader& r, const MotionFile& f, Output& out) {
  const auto family = gs::burmester_curves(f.poses, f.samples.value_or(180));
  draw_burmester_curves(f.poses, family, out.drawing);
  out.report.json["burmester_curve_samples"] = family.size();
  if (r.has("burmester")) {
    io::MapReader m = r.map("burmester");
    const auto dyad = [&](const char* side) {
      io::MapReader d = m.map(side);
      const double beta2 = d.quantity("beta2", io::Quantity::angle, "deg");
      const long long closure = d.optional_integer("closure").value_or(0);
      if (closure != 0 && closure != 1) io::fail_at(d.mark("closure"), "expected closure 0 or 1");
      d.finish();
      out.report.notes.push_back(fmt::format("Free choice: the {} dyad is the Burmester dyad at beta2 = {} deg, closure {}.",
                                             side, deg(beta2), closure));
      return gs::burmester_dyad(f.poses, beta2, static_cast<int>(closure)).dyad;
    };
    const gs::Dyad in = dyad("input"), o = dyad("output");
    m.finish();
    return gs::four_bar_from_dyads(f.poses, in, o, f.require_crank);
  }
  // At most 400 dyads enter the pair search (160 000 pairs), however finely the curves are drawn.
  std::vector<gs::Dyad> dyads;
  const std::size_t stride = (family.size() + 399) / 400;
  for (std::size_t k = 0; k < family.size(); k += std::max<std::size_t>(stride, 1)) dyads.push_back(family[k].dyad);
  out.report.notes.push_back(fmt::format("Free choices: two of {} dyads sampled on the Burmester curves, searched for the best "
                                         "defect-free linkage.", dyads.size()));
  return gs::best_pair_of_dyads(f.poses, dyads, f.max_link_ratio, f.require_crank);
}

gs::MotionCandidate five_positions(io::MapReader& r, const MotionFile& f, Output& out) {
  const auto points = gs::burmester_points(f.poses, f.samples.value_or(720));
  io::Table t{"Burmester points", {"#", "centre point (ground pivot) [mm]", "circle point (moving pivot, pose 1) [mm]"}, {}};
  nlohmann::json j = nlohmann::json::array();
  for (std::size_t k = 0; k < points.size(); ++k) {
    const gs::Dyad& d = points[k].dyad;
    t.add_row({std::to_string(k + 1), fmt::format("({}, {})", mm(d.ground_pivot.x()), mm(d.ground_pivot.y())),
               fmt::format("({}, {})", mm(d.moving_pivot.x()), mm(d.moving_pivot.y()))});
    j.push_back({{"centre_point_mm", {d.ground_pivot.x() * 1000, d.ground_pivot.y() * 1000}},
                 {"circle_point_mm", {d.moving_pivot.x() * 1000, d.moving_pivot.y() * 1000}}});
  }
  out.report.tables.push_back(std::move(t));
  out.report.json["burmester_points"] = j;
  if (points.size() < 2) throw gs::NoSolution(fmt::format("these five poses have {} real Burmester points: no four-bar passes through all five", points.size()));
  if (const auto n = r.optional_node("pair")) {
    const bool two = n->IsSequence() && n->size() == 2;
    const auto number = [&](int i) { return two ? std::llround(io::scalar_quantity((*n)[i], r.file(), io::Quantity::dimensionless, "")) : 0LL; };
    const long long a = number(0), b = number(1);
    const auto count = static_cast<long long>(points.size());
    if (a < 1 || b < 1 || a > count || b > count || a == b)
      io::fail_at(r.mark("pair"), fmt::format("expected two different Burmester point numbers 1..{}", count));
    return gs::four_bar_from_dyads(f.poses, points[a - 1].dyad, points[b - 1].dyad, f.require_crank);
  }
  std::vector<gs::Dyad> dyads;
  for (const auto& b : points) dyads.push_back(b.dyad);
  out.report.notes.push_back("Free choice: the pair of Burmester points giving the best defect-free linkage.");
  return gs::best_pair_of_dyads(f.poses, dyads, f.max_link_ratio, f.require_crank);
}

void add_positions_table(const MotionFile& f, const gs::MotionCandidate& c, Output& out) {
  io::Table t{"Positions", {"#", "P [mm]", "coupler angle [deg]", "crank theta2 [deg]", "branch"}, {}};
  nlohmann::json j = nlohmann::json::array();
  for (std::size_t k = 0; k < f.poses.size(); ++k) {
    const gs::Pose& p = f.poses[k];
    t.add_row({std::to_string(k + 1), fmt::format("({}, {})", mm(p.point.x()), mm(p.point.y())), deg(p.angle),
               deg(c.theta2[k]), std::to_string(c.branches[k])});
    j.push_back({{"P_mm", {p.point.x() * 1000, p.point.y() * 1000}}, {"angle_deg", p.angle * 180 / pi},
                 {"theta2_deg", c.theta2[k] * 180 / pi}, {"branch", c.branches[k]}});
  }
  out.report.tables.push_back(std::move(t));
  out.report.json["positions"] = j;
}

// The mechanism file and its solver check: P and the coupler angle at every pose.
void write_mechanism(const MotionFile& f, const gs::MotionCandidate& c, Output& out) {
  const gs::FourBar& fb = c.linkage;
  const int direction = c.defects.direction;
  const double travel = c.defects.order_defect ? 0.0 : c.defects.travel;
  gs::MechanismSketch sketch = gs::four_bar_sketch(fb, c.theta2[0], std::max(travel, 1e-3), direction, out.report.title);
  sketch.comments = {fmt::format("Motion generator through {} coupler poses, synthesised by gearkit synth.", f.poses.size()),
                     "The coupler point P passes through the poses' points; theta2 sweeps from pose 1 to the last."};
  if (!c.defects.ok()) sketch.comments.push_back("DEFECTIVE: " + c.defects.notes.front());
  out.mechanism_yaml = gs::to_mechanism_yaml(sketch);
  const double theta3_1 = gs::pose_at(fb, c.theta2[0])->theta3;
  std::vector<Checkpoint> checks;
  for (std::size_t k = 0; k < f.poses.size(); ++k) {
    const double t2 = unwrapped(c.theta2[0], c.theta2[k], direction);
    checks.push_back({t2, f.poses[k].point, std::nullopt, "", false});
    checks.push_back({t2, {}, theta3_1 + f.poses[k].angle - f.poses[0].angle, "theta3", true});
  }
  if (c.defects.ok()) verify_with_solver(out.mechanism_yaml, checks, out.report);
}

void draw_poses(const std::vector<gs::Pose>& poses, double size, io::Drawing& d) {
  for (const gs::Pose& p : poses) {
    const gs::Vec2 u(std::cos(p.angle), std::sin(p.angle));
    const gs::Vec2 a = p.point - size * u, b = p.point + size * u;
    d.lines.push_back({"targets", a.x() * 1000, a.y() * 1000, b.x() * 1000, b.y() * 1000});
  }
}

}  // namespace

Output run_motion_task(const io::YamlDocument& doc, const Overrides& overrides) {
  io::MapReader r(doc.root, doc.file, "motion-generation task");
  MotionFile f;
  f.title = r.optional_string("synthesis").value_or("");
  for (const YAML::Node& n : r.sequence("positions")) f.poses.push_back(read_pose(n, doc.file, f));
  if (f.poses.size() < 2 || f.poses.size() > 5) io::fail_at(r.mark("positions"), fmt::format("expected 2 to 5 positions, found {}", f.poses.size()));
  f.require_crank = r.boolean_or("require_crank", false);
  f.max_link_ratio = r.optional_number("max_link_ratio").value_or(10);
  if (!(f.max_link_ratio > 1)) io::fail_at(r.mark("max_link_ratio"), "expected a ratio above 1");
  const int max_grid = f.poses.size() == 2 ? gs::kMaxTwoPositionGrid : gs::kMaxThreePositionGrid;
  if (const auto g = r.optional_integer("search_grid")) {
    if (*g < 2 || *g > max_grid) io::fail_at(r.mark("search_grid"), fmt::format("expected a search grid of 2..{}", max_grid));
    f.grid = static_cast<int>(*g);
  }
  if (const auto s = r.optional_integer("samples")) {
    if (*s < 8 || *s > gs::kMaxBurmesterSamples) io::fail_at(r.mark("samples"), fmt::format("expected samples 8..{}", gs::kMaxBurmesterSamples));
    f.samples = static_cast<int>(*s);
  }
  Output out;
  out.report.title = f.title.empty() ? fmt::format("Motion generator through {} positions", f.poses.size()) : f.title;
  out.report.json["task"] = "motion";
  using Step = gs::MotionCandidate (*)(io::MapReader&, const MotionFile&, Output&);
  const Step steps[] = {two_positions, three_positions, four_positions, five_positions};
  const gs::MotionCandidate c = steps[f.poses.size() - 2](r, f, out);
  r.finish();
  add_positions_table(f, c, out);
  add_four_bar_tables(c.linkage, c.defects, c.transmission, out.report);
  add_four_bar_summary(c.linkage, c.theta2[0], c.defects.order_defect ? 0.0 : c.defects.travel, c.defects.direction,
                       overrides.min_transmission_angle, c.defects.ok(), out.report);
  write_mechanism(f, c, out);
  draw_four_bar(c.linkage, c.theta2, c.defects.order_defect ? 0.0 : c.defects.travel, c.defects.direction, out.drawing);
  draw_poses(f.poses, 0.08 * std::max(c.linkage.coupler, c.linkage.ground()), out.drawing);
  out.plot = transmission_plot(c.linkage, c.theta2[0], std::max(c.defects.travel, 1e-3), c.defects.direction, out.report.title);
  return out;
}

}  // namespace gearkit::plugins::synth
