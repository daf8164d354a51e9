// `gearkit synth crank-rocker FILE` (rocker swing and time ratio, quick return) and
// `gearkit synth dwell FILE` (single-dwell six-bar from a coupler curve's near-circular arc).
#include "synth_output.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/synth/dwell.hpp>
#include <gearkit/synth/quick_return.hpp>

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace gearkit::plugins::synth {

namespace {

constexpr double pi = std::numbers::pi;

io::Plot rocker_plot(const gs::FourBar& f, double start, const std::string& title) {
  io::Series rocker{"rocker theta4 [deg]", {}, {}, ""}, mu{"transmission angle [deg]", {}, {}, ""};
  for (int k = 0; k <= 720; ++k) {
    const double t2 = start + 2 * pi * k / 720;
    const auto pose = gs::pose_at(f, t2);
    rocker.x.push_back(t2 * 180 / pi);
    rocker.y.push_back(pose ? pose->theta4 * 180 / pi : std::numeric_limits<double>::quiet_NaN());
    mu.x.push_back(t2 * 180 / pi);
    mu.y.push_back(pose ? gs::transmission_angle(*pose, f) * 180 / pi : std::numeric_limits<double>::quiet_NaN());
  }
  return {title, "crank angle theta2 [deg]", {{"rocker angle [deg]", {rocker}, {}}, {"transmission angle [deg]", {mu}, {}}}, 800, 220};
}

void add_quick_return_table(const gs::QuickReturnTask& t, const gs::QuickReturnResult& r, Output& out) {
  const double slow = std::max(r.ccw_stroke, 2 * pi - r.ccw_stroke), fast = 2 * pi - slow;
  io::Table tab{"Quick return", {"quantity", "value"}, {}};
  tab.add_row({"rocker swing [deg]", deg(t.swing)});
  tab.add_row({"time ratio Q (slow / fast stroke)", io::fixed(slow / fast, 4)});
  tab.add_row({"delta = angle B1 O2 B2 [deg]", deg(r.delta)});
  tab.add_row({"crank at the extended limit [deg]", deg(r.theta2_extended)});
  tab.add_row({"crank at the folded limit [deg]", deg(r.theta2_folded)});
  tab.add_row({"crank turning ccw, extended -> folded [deg]", deg(r.ccw_stroke)});
  tab.add_row({"crank turning ccw, folded -> extended [deg]", deg(2 * pi - r.ccw_stroke)});
  out.report.tables.push_back(std::move(tab));
  out.report.json["quick_return"] = {{"swing_deg", t.swing * 180 / pi}, {"time_ratio", slow / fast}, {"delta_deg", r.delta * 180 / pi},
                                     {"theta2_extended_deg", r.theta2_extended * 180 / pi},
                                     {"theta2_folded_deg", r.theta2_folded * 180 / pi}, {"ccw_stroke_deg", r.ccw_stroke * 180 / pi}};
  out.report.notes.push_back(fmt::format("Turning counter-clockwise, the crank takes {} deg from the extended to the folded limit "
                                         "and {} deg back.", deg(r.ccw_stroke), deg(2 * pi - r.ccw_stroke)));
}

gs::FourBar read_four_bar(io::MapReader& r) {
  io::MapReader m = r.map("four_bar");
  gs::FourBar f;
  f.O4 = gs::Vec2(m.quantity("ground", io::Quantity::length, "mm"), 0);
  f.crank = m.quantity("crank", io::Quantity::length, "mm");
  f.coupler = m.quantity("coupler", io::Quantity::length, "mm");
  f.rocker = m.quantity("rocker", io::Quantity::length, "mm");
  f.coupler_point = read_point(m.node("coupler_point"), r.file());
  const long long branch = m.optional_integer("branch").value_or(1);
  if (branch != 1 && branch != -1) io::fail_at(m.mark("branch"), "expected branch 1 or -1");
  f.branch = static_cast<int>(branch);
  for (const char* k : {"ground", "crank", "coupler", "rocker"})
    if (!(m.quantity(k, io::Quantity::length, "mm") > 0)) io::fail_at(m.mark(k), "expected a positive length");
  m.finish();
  return f;
}

void add_dwell_table(const gs::DwellTask& t, const gs::DwellResult& r, Output& out) {
  io::Table tab{"Dwell", {"quantity", "value"}, {}};
  tab.add_row({"dwell window, crank [deg]", fmt::format("{} .. {}", deg(r.window_start), deg(r.window_start + t.dwell))});
  tab.add_row({"arc centre D [mm]", fmt::format("({}, {})", mm(r.D.x()), mm(r.D.y()))});
  tab.add_row({"arc radius R = link 5 P D [mm]", mm(r.radius)});
  tab.add_row({"arc deviation from the circle [mm]", mm(r.arc_deviation)});
  tab.add_row({"output pivot O6 [mm]", fmt::format("({}, {})", mm(r.O6.x()), mm(r.O6.y()))});
  tab.add_row({"output rocker O6 D [mm]", mm(r.output_rocker)});
  tab.add_row({"output swing [deg]", deg(r.swing)});
  tab.add_row({"output motion during the dwell [deg]", deg(r.dwell_motion)});
  out.report.tables.push_back(std::move(tab));
  out.report.json["dwell"] = {{"window_start_deg", r.window_start * 180 / pi}, {"window_deg", t.dwell * 180 / pi},
                              {"D_mm", {r.D.x() * 1000, r.D.y() * 1000}}, {"radius_mm", r.radius * 1000},
                              {"arc_deviation_mm", r.arc_deviation * 1000}, {"O6_mm", {r.O6.x() * 1000, r.O6.y() * 1000}},
                              {"output_rocker_mm", r.output_rocker * 1000}, {"swing_deg", r.swing * 180 / pi},
                              {"dwell_motion_deg", r.dwell_motion * 180 / pi}};
  if (r.dwell_motion > 0.05 * r.swing)
    out.report.warnings.push_back(fmt::format("the output still moves {} deg during the dwell ({:.1f} % of its swing)",
                                              deg(r.dwell_motion), 100 * r.dwell_motion / r.swing));
}

io::Plot dwell_plot(const gs::DwellResult& r, const std::string& title) {
  io::Series s{"output rocker theta6 [deg]", {}, {}, ""};
  for (int k = 0; k <= 720; ++k) {
    const double t2 = r.window_start + 2 * pi * k / 720;
    const auto a = gs::output_angle(r, t2);
    s.x.push_back(t2 * 180 / pi);
    s.y.push_back(a ? *a * 180 / pi : std::numeric_limits<double>::quiet_NaN());
  }
  return {title, "crank angle theta2 [deg]", {{"output angle [deg]", {s}, {}}}, 800, 260};
}

void draw_dwell(const gs::DwellTask& t, const gs::DwellResult& r, io::Drawing& d) {
  draw_four_bar(r.four_bar, {r.window_start, r.window_start + t.dwell}, 2 * pi, 1, d);
  const double a0 = std::atan2(gs::pose_at(r.four_bar, r.window_start)->P.y() - r.D.y(), gs::pose_at(r.four_bar, r.window_start)->P.x() - r.D.x());
  const double a1 = std::atan2(gs::pose_at(r.four_bar, r.window_start + t.dwell)->P.y() - r.D.y(), gs::pose_at(r.four_bar, r.window_start + t.dwell)->P.x() - r.D.x());
  d.arcs.push_back({"targets", r.D.x() * 1000, r.D.y() * 1000, r.radius * 1000, std::min(a0, a1) * 180 / pi, std::max(a0, a1) * 180 / pi});
  const gs::Vec2 P = gs::pose_at(r.four_bar, r.window_start)->P;
  d.polylines.push_back({"linkage", {{P.x() * 1000, P.y() * 1000, 0}, {r.D.x() * 1000, r.D.y() * 1000, 0}, {r.O6.x() * 1000, r.O6.y() * 1000, 0}}, false});
  const double size = r.output_rocker * 1000 / 25;
  d.circles.push_back({"pivots", r.O6.x() * 1000, r.O6.y() * 1000, size});
  d.circles.push_back({"linkage", r.D.x() * 1000, r.D.y() * 1000, size / 2});
  d.texts.push_back({"pivots", r.O6.x() * 1000 + 1.5 * size, r.O6.y() * 1000, 2 * size, "O6"});
  d.texts.push_back({"linkage", r.D.x() * 1000 + size, r.D.y() * 1000 + size, 2 * size, "D"});
}

/// Refuses, at the key's file:line:column, a task value the synthesis would refuse (the library
/// checks them too, without knowing where they came from).
void require(bool ok, const io::MapReader& r, const std::string& key, std::string_view expected, std::string_view found) {
  if (!ok) io::fail_at(r.mark(key), fmt::format("'{}': expected {}, found {}", key, expected, found));
}

}  // namespace

Output run_crank_rocker_task(const io::YamlDocument& doc, const Overrides& overrides) {
  io::MapReader r(doc.root, doc.file, "crank-rocker task");
  gs::QuickReturnTask t;
  const std::string title = r.optional_string("synthesis").value_or("");
  t.swing = r.quantity("swing", io::Quantity::angle, "deg");
  t.time_ratio = r.optional_number("time_ratio").value_or(1.0);
  t.rocker = r.quantity_or("rocker", io::Quantity::length, "mm", 0.1);
  t.ground = r.optional_quantity("ground", io::Quantity::length, "mm");
  r.finish();
  // The ranges of gs::synthesize_quick_return (gearkit/synth/quick_return.hpp).
  require(t.swing > 0 && t.swing < pi, r, "swing", "a rocker swing between 0 and 180 deg", fmt::format("{} deg", deg(t.swing)));
  require(t.time_ratio >= 1 && t.time_ratio < 10, r, "time_ratio", "a time ratio Q with 1 <= Q < 10",
          fmt::format("{:g}", t.time_ratio));
  require(t.rocker > 0, r, "rocker", "a length > 0", fmt::format("{:g} mm", t.rocker * 1000));
  require(!t.ground || *t.ground > 0, r, "ground", "a length > 0", fmt::format("{:g} mm", t.ground.value_or(0) * 1000));
  const gs::QuickReturnResult res = gs::synthesize_quick_return(t);
  Output out;
  out.report.title = title.empty() ? fmt::format("Crank-rocker: {} deg swing, time ratio {:g}", deg(t.swing), t.time_ratio) : title;
  out.report.json["task"] = "crank-rocker";
  add_quick_return_table(t, res, out);
  add_four_bar_tables(res.linkage, {}, gs::transmission_range(res.linkage, res.theta2_extended, 2 * pi, 1), out.report);
  add_four_bar_summary(res.linkage, res.theta2_extended, 2 * pi, 1, overrides.min_transmission_angle, true, out.report);
  gs::MechanismSketch sketch = gs::four_bar_sketch(res.linkage, res.theta2_extended, 2 * pi, 1, out.report.title);
  sketch.comments = {fmt::format("Crank-rocker for a {} deg rocker swing with time ratio {:g} (gearkit synth); drawn at the "
                                 "extended limit position.", deg(t.swing), t.time_ratio)};
  out.mechanism_yaml = gs::to_mechanism_yaml(sketch);
  const double folded = unwrapped(res.theta2_extended, res.theta2_folded, 1);
  verify_with_solver(out.mechanism_yaml, {{res.theta2_extended, {}, gs::pose_at(res.linkage, res.theta2_extended)->theta4, "theta4", true},
                                          {folded, {}, gs::pose_at(res.linkage, res.theta2_folded)->theta4, "theta4", true}}, out.report);
  draw_four_bar(res.linkage, {res.theta2_extended, res.theta2_folded}, 2 * pi, 1, out.drawing);
  out.plot = rocker_plot(res.linkage, res.theta2_extended, out.report.title);
  return out;
}

Output run_dwell_task(const io::YamlDocument& doc, const Overrides& overrides) {
  io::MapReader r(doc.root, doc.file, "dwell task");
  gs::DwellTask t;
  const std::string title = r.optional_string("synthesis").value_or("");
  t.four_bar = read_four_bar(r);
  t.dwell = r.quantity_or("dwell", io::Quantity::angle, "deg", t.dwell);
  t.output_rocker = r.optional_quantity("output_rocker", io::Quantity::length, "mm");
  if (r.has("output_pivot")) t.output_pivot = read_point(r.node("output_pivot"), doc.file);
  if (const auto s = r.optional_integer("samples")) t.samples = static_cast<int>(std::clamp<long long>(*s, 0, 1 << 30));
  r.finish();
  // The ranges of gs::synthesize_dwell (gearkit/synth/dwell.hpp).
  require(t.dwell >= 5 * pi / 180 && t.dwell <= pi, r, "dwell", "a dwell of 5 to 180 deg of crank",
          fmt::format("{} deg", deg(t.dwell)));
  require(t.samples >= 72 && t.samples <= 7200, r, "samples", "72 to 7200 samples", fmt::format("{}", t.samples));
  require(!t.output_rocker || *t.output_rocker > 0, r, "output_rocker", "a length > 0",
          fmt::format("{:g} mm", t.output_rocker.value_or(0) * 1000));
  const gs::DwellResult res = gs::synthesize_dwell(t);
  Output out;
  out.report.title = title.empty() ? fmt::format("Single-dwell six-bar: {} deg dwell", deg(t.dwell)) : title;
  out.report.json["task"] = "dwell";
  add_four_bar_tables(res.four_bar, {}, gs::transmission_range(res.four_bar, res.window_start, 2 * pi, 1), out.report);
  add_four_bar_summary(res.four_bar, res.window_start, 2 * pi, 1, overrides.min_transmission_angle, true, out.report);
  add_dwell_table(t, res, out);
  gs::MechanismSketch sketch = gs::dwell_sketch(res, out.report.title);
  sketch.comments = {fmt::format("Single-dwell six-bar (gearkit synth): rocker6 rests while the crank turns {} deg from its drawn "
                                 "angle.", deg(t.dwell))};
  out.mechanism_yaml = gs::to_mechanism_yaml(sketch);
  std::vector<Checkpoint> checks;
  for (int k = 0; k <= 12; ++k)
    if (const auto a = gs::output_angle(res, res.window_start + 2 * pi * k / 12))
      checks.push_back({res.window_start + 2 * pi * k / 12, {}, *a, "theta6", true});
  verify_with_solver(out.mechanism_yaml, checks, out.report);
  draw_dwell(t, res, out.drawing);
  out.plot = dwell_plot(res, out.report.title);
  return out;
}

}  // namespace gearkit::plugins::synth
