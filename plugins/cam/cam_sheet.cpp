#include "cam_sheet.hpp"

#include "cam_export.hpp"
#include "cam_text.hpp"

#include <gearkit/io/drawing_annotation.hpp>
#include <gearkit/io/version.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gearkit::plugins::cam {

namespace gc = gearkit::cam;

namespace {

constexpr double kPi = std::numbers::pi;

const std::vector<io::Layer> kAnnotationLayers = {
    {"prime_circle", 4, "#22a0a0", true}, {"angle_marks", 8, "#555555", false}, {"dimensions", 7, "#000000", false},
    {"legend", 7, "#000000", false},       {"tables", 7, "#000000", false},      {"title_block", 7, "#000000", false},
    {"frame", 7, "#000000", false}};

bool layer_used(const io::Drawing& d, const std::string& layer) {
  const auto on = [&](const auto& v) { return std::any_of(v.begin(), v.end(), [&](const auto& e) { return e.layer == layer; }); };
  return on(d.polylines) || on(d.circles) || on(d.lines) || on(d.arcs);
}

gc::Vec2 turned(gc::Vec2 p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * p.x - s * p.y, s * p.x + c * p.y};
}

// The cam angle of each segment join as a radial tick just beyond the pitch curve, at the point
// the follower touches then; cam angle 0 as a long line from the centre (the zero mark).
std::vector<double> angle_marks(io::Drawing& d, const CamModel& model, double turn, double h) {
  const gc::CamDesign& design = model.design;
  std::vector<double> angles;
  for (const gc::Segment& s : design.program.segments()) angles.push_back(s.start);
  if (std::none_of(angles.begin(), angles.end(), [](double a) { return std::abs(std::remainder(a, 2 * kPi)) < 1e-9; }))
    angles.push_back(0.0);
  std::vector<double> directions;
  for (double theta : angles) {
    const gc::Vec2 p = turned(gc::contact_at(design, theta).pitch, turn);
    const double phi = std::atan2(p.y, p.x), ux = std::cos(phi), uy = std::sin(phi);
    directions.push_back(phi);
    const bool zero = std::abs(std::remainder(theta, 2 * kPi)) < 1e-9;
    const double rho = std::hypot(p.x, p.y) + (model.design.follower.contact == gc::Contact::roller ? 0.0 : 0.5 * h);
    const double from = zero ? 0.0 : rho + 0.5 * h, to = rho + (zero ? 4.0 : 2.0) * h;
    d.lines.push_back({"angle_marks", from * ux, from * uy, to * ux, to * uy});
    const std::string text = zero ? "cam angle 0°" : fmt::format("{}°", io::fixed(angle_deg(theta), 1));
    // The zero mark's text sits inside the cam, clear of the follower drawn there.
    const double at = zero ? 0.55 * model.design.base_radius : to + 0.6 * h;
    const double tx = at * ux + (zero ? 0.6 * h : 0.0), ty = at * uy - 0.4 * h;
    d.texts.push_back({"angle_marks", ux >= 0 || zero ? tx : tx - io::text_width(text, h), ty, h, text});
  }
  return directions;
}

// The direction (from a 5 deg grid) farthest from every direction already used, the preferred
// one among equals: dimensions do not run into the angle marks, the follower or each other.
double free_direction(const std::vector<double>& taken, double preferred) {
  double best = preferred, best_gap = -1.0;
  for (int k = 0; k < 72; ++k) {
    const double a = k * kPi / 36.0;
    double gap = kPi;
    for (double t : taken) gap = std::min(gap, std::abs(std::remainder(a - t, 2 * kPi)));
    const double closer = std::abs(std::remainder(a - preferred, 2 * kPi)) < std::abs(std::remainder(best - preferred, 2 * kPi));
    if (gap > best_gap + 1e-9 || (std::abs(gap - best_gap) <= 1e-9 && closer)) best = a, best_gap = gap;
  }
  return best;
}

// An arc arrow about the centre in the sense of rotation.
void rotation_arrow(io::Drawing& d, const CamModel& model, double h) {
  const bool ccw = model.design.rotation == gc::Rotation::ccw;
  const double r = std::max(0.35 * model.design.base_radius, 3.0 * h), a0 = 200.0, a1 = 250.0;
  d.arcs.push_back({"dimensions", 0.0, 0.0, r, a0, a1});
  const double tip = (ccw ? a1 : a0) * kPi / 180.0;
  io::add_arrow_head(d, r * std::cos(tip), r * std::sin(tip), tip + (ccw ? 0.5 : -0.5) * kPi, 1.2 * h, "dimensions");
  const std::string text = ccw ? "rotation: counter-clockwise" : "rotation: clockwise";
  d.texts.push_back({"dimensions", -0.5 * io::text_width(text, h), -r - 2.0 * h, h, text});
}

// Base and prime circles, the largest radius and the roller, each with a radius dimension.
void radii(io::Drawing& d, const CamModel& model, const CamResult& result, double turn, double h,
           std::vector<double> taken) {
  const gc::CamDesign& design = model.design;
  const double rb = design.base_radius;
  // The largest radius: at its cam angle, or mid-dwell when it lies on a dwell (a circle there).
  const gc::ValueAt& rmax = result.checks.radius_max;
  double theta_max = rmax.theta;
  for (const gc::Segment& seg : design.program.segments()) {
    const double into = std::fmod(std::fmod(rmax.theta - seg.start, 2 * kPi) + 2 * kPi, 2 * kPi);
    const bool on = into <= seg.end - seg.start + 1e-4 || into >= 2 * kPi - 1e-4;  // the sampled maximum may sit at a join
    if (seg.kind == gc::SegmentKind::dwell && on) theta_max = 0.5 * (seg.start + seg.end);
  }
  const gc::Vec2 p = turned(gc::contact_at(design, theta_max).contact, turn);
  const double max_dir = std::atan2(p.y, p.x);
  io::add_radius_dimension(d, 0, 0, rmax.value, max_dir, fmt::format("R_max = {}", io::fixed(rmax.value, 3)), h, "dimensions");
  taken.push_back(max_dir);
  const double base_dir = free_direction(taken, 300.0 * kPi / 180.0);
  io::add_radius_dimension(d, 0, 0, rb, base_dir, fmt::format("R_b = {} (base)", io::fixed(rb, 3)), h, "dimensions");
  taken.push_back(base_dir);
  const gc::Follower& f = design.follower;
  if (f.contact == gc::Contact::roller) {
    const double rp = rb + f.roller_radius;
    d.circles.push_back({"prime_circle", 0, 0, rp});
    io::add_radius_dimension(d, 0, 0, rp, free_direction(taken, 330.0 * kPi / 180.0),
                             fmt::format("R_p = {} (prime)", io::fixed(rp, 3)), h, "dimensions");
  }
  if (f.contact == gc::Contact::roller) {
    const gc::Vec2 c = gc::contact_at(design, model.follower_at).follower_point;
    io::add_radius_dimension(d, c.x, c.y, f.roller_radius, 0.25 * kPi, fmt::format("r_r = {}", io::fixed(f.roller_radius, 3)),
                             h, "dimensions");
  }
}

// The legend's line samples sit on copies of the curves' layers ("legend_profile", same colour
// and dash), so that the profile layers hold the cam's curves and nothing else.
std::vector<io::LegendEntry> legend(io::Drawing& d, const CamModel& model) {
  const std::vector<io::LegendEntry> all = {
      {"profile", "cam profile"},
      {"outer_wall", "groove outer wall"},
      {"conjugate_profile", "conjugate cam profile"},
      {"pitch_curve", "pitch curve (roller centre)"},
      {"tool_path", model.cutter_radius_mm ? fmt::format("tool path (cutter centre, R {})", io::fixed(*model.cutter_radius_mm, 3))
                                           : "tool path (cutter centre)"},
      {"base_circle", "base circle"},
      {"prime_circle", "prime circle"},
      {"follower", fmt::format("follower at cam angle {}°", io::fixed(angle_deg(model.follower_at), 1))}};
  std::vector<io::LegendEntry> used;
  for (const io::LegendEntry& e : all) {
    if (!layer_used(d, e.layer)) continue;
    io::Layer style{"legend_" + e.layer};
    for (const io::Layer& l : d.layers)
      if (l.name == e.layer) style = {"legend_" + e.layer, l.aci_color, l.svg_color, l.dashed};
    d.layers.push_back(style);
    used.push_back({style.name, e.text});
  }
  return used;
}

io::TextTable text_table(const io::Report& report, const std::string& title) {
  for (const io::Table& t : report.tables)
    if (t.title == title) return {t.title, t.header, t.rows};
  return {};
}

// The angle the sheet shows the cam at: the SVG turns the profile with the follower (follower_at),
// so a sheet that said "cam angle 0" there misstated the picture; at 0 the profile layers are the
// cutting position (the DXF's, always).
std::string drawn_angle(double follower_at) {
  const std::string angle = io::fixed(angle_deg(follower_at), 1);
  if (std::abs(std::remainder(follower_at, 2 * kPi)) < 1e-12) return "cam angle 0.0° (profile layers as cut)";
  return fmt::format("cam angle {}° (cam turned {}° from the cutting position)", angle, angle);
}

void title_block(io::Drawing& d, const CamModel& model, const io::Report& report, double x, double y_top, double h) {
  const gc::Follower& f = model.design.follower;
  const std::string follower = fmt::format(
      "{} {}", f.motion == gc::FollowerMotion::oscillating ? "oscillating" : "translating",
      f.contact == gc::Contact::roller ? "roller" : f.contact == gc::Contact::flat_face ? "flat face" : "knife edge");
  io::TextTable t;
  t.title = "gearkit cam";
  t.rows = {{"drawing", report.title},
            {"follower", follower},
            {"units", "lengths mm, angles deg"},
            {"cam angle drawn", drawn_angle(model.follower_at)},
            {"made by", fmt::format("gearkit {}", io::version())}};
  io::add_table(d, t, x, y_top, h, "title_block", "frame");
}

}  // namespace

io::Drawing cam_sheet(const CamModel& model, const CamResult& result, const io::Report& report, double follower_at) {
  CamModel at = model;
  at.follower_at = follower_at;
  const gc::CamProfile* second = result.second_profile ? &*result.second_profile : nullptr;
  io::Drawing d = cam_drawing(at, result.profile, true, second);
  d.layers.insert(d.layers.end(), kAnnotationLayers.begin(), kAnnotationLayers.end());
  const double turn = gc::rotation_sign(model.design.rotation) * follower_at;
  const double r_out = result.checks.radius_max.value;
  const double h = io::text_height_for(2.0 * r_out);
  std::vector<double> taken = angle_marks(d, at, turn, h);
  const gc::Vec2 follower = gc::contact_at(model.design, follower_at).follower_point;
  taken.push_back(std::atan2(follower.y, follower.x));
  for (double a = 200.0; a <= 250.0; a += 25.0) taken.push_back(a * kPi / 180.0);  // the rotation arrow
  radii(d, at, result, turn, h, taken);
  rotation_arrow(d, at, h);
  const io::Box box = io::drawing_box(d);
  const double x = box.xmax + 4.0 * h;
  double y = box.ymax;
  y -= io::add_legend(d, legend(d, at), x, y, h, "legend").height + 2.0 * h;
  for (const char* title : {"Motion program", "Checks"}) {
    const io::TextTable t = text_table(report, title);
    if (!t.rows.empty()) y -= io::add_table(d, t, x, y, h, "tables", "frame").height + 2.0 * h;
  }
  title_block(d, at, report, x, y, h);
  return d;
}

}  // namespace gearkit::plugins::cam
