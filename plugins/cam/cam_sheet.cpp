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

// Labels go beyond the outermost curve of the cam (profile, walls, pitch curve, tool paths,
// circles about the centre), where no curve of the cam crosses them; the follower stays out.
double outer_radius(const io::Drawing& d) {
  double r = 0.0;
  for (const io::Polyline& p : d.polylines)
    if (p.layer != "follower")
      for (const io::Vertex& v : p.vertices) r = std::max(r, std::hypot(v.x, v.y));
  for (const io::Circle& c : d.circles)
    if (c.layer != "follower") r = std::max(r, std::hypot(c.cx, c.cy) + c.r);
  return r;
}

// The text of a label whose leader comes from the centre along `phi`, at `at` mm: to the right of
// the point on the right half, ending at it on the left.
io::Text radial_text(const std::string& layer, double phi, double at, const std::string& text, double h) {
  const double ux = std::cos(phi), uy = std::sin(phi);
  const double x = at * ux + (ux >= 0 ? 0.0 : -io::text_width(text, h));
  return {layer, x, at * uy - 0.4 * h, h, text};
}

// The cam angle of each segment join as a radial tick from just beyond the pitch curve to beyond
// the cam, at the point the follower touches then, with the angle written past the tick's end;
// cam angle 0 as a long line from the centre (the zero mark), named inside the cam. Texts take
// the first position (along their line, then a little farther) where nothing crosses them.
std::vector<double> angle_marks(io::Drawing& d, const CamModel& model, double turn, double r_out, double h) {
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
    const double from = zero ? 0.0 : rho + 0.5 * h, to = std::max(rho + (zero ? 4.0 : 2.0) * h, r_out + h);
    d.lines.push_back({"angle_marks", from * ux, from * uy, to * ux, to * uy});
    const std::string text = zero ? "cam angle 0°" : fmt::format("{}°", io::fixed(angle_deg(theta), 1));
    std::vector<io::Drawing> spots;
    if (zero) {  // inside the cam beside the line, clear of the follower drawn past its end
      for (double f : {0.55, 0.35, 0.75, 0.2})
        for (double side : {1.0, -1.0}) {
          io::Drawing s;
          const double at = f * design.base_radius, nx = -uy * side, ny = ux * side;
          const double x = at * ux + 0.6 * h * nx - (nx < 0 ? io::text_width(text, h) : 0.0);
          s.texts.push_back({"angle_marks", x, at * uy + 0.6 * h * ny - 0.4 * h, h, text});
          spots.push_back(std::move(s));
        }
    }
    for (double extra : {0.6, 1.6, 2.6, 3.6}) {
      io::Drawing s;
      s.texts.push_back(radial_text("angle_marks", phi, to + extra * h, text, h));
      spots.push_back(std::move(s));
    }
    io::place_first_fitting(d, spots);
  }
  return directions;
}

// Directions on a 5 deg grid to try for a dimension: those at least 20 deg from every direction
// taken (angle marks, follower, other dimensions), nearest the preferred one first, then the rest
// by their distance from the taken ones.
std::vector<double> directions_to_try(const std::vector<double>& taken, double preferred) {
  std::vector<std::pair<double, double>> free, crowded;  // (sort key, direction)
  for (int k = 0; k < 72; ++k) {
    const double a = k * kPi / 36.0;
    double gap = kPi;
    for (double t : taken) gap = std::min(gap, std::abs(std::remainder(a - t, 2 * kPi)));
    if (gap >= 20.0 * kPi / 180.0) free.emplace_back(std::abs(std::remainder(a - preferred, 2 * kPi)), a);
    else crowded.emplace_back(-gap, a);
  }
  std::sort(free.begin(), free.end());
  std::sort(crowded.begin(), crowded.end());
  std::vector<double> out;
  for (const auto& list : {free, crowded})
    for (const auto& [key, a] : list) out.push_back(a);
  return out;
}

// A radius dimension of the circle (cx, cy, r) along `dir`: the line from the centre with its
// arrow at the circle, and a leader on to an elbow at `r_label` from the centre in the direction
// dir + shift, with the text beyond it.
io::Drawing radius_dimension(double cx, double cy, double r, double dir, double shift, double r_label,
                             const std::string& text, double h) {
  io::Drawing a;
  const double ex = cx + r * std::cos(dir), ey = cy + r * std::sin(dir);
  a.lines.push_back({"dimensions", cx, cy, ex, ey});
  io::add_arrow_head(a, ex, ey, dir, 1.2 * h, "dimensions");
  const double tx = cx + r_label * std::cos(dir + shift), ty = cy + r_label * std::sin(dir + shift);
  io::add_label(a, ex, ey, tx, ty, text, h, "dimensions");
  return a;
}

// The first direction, and label shift, at which the dimension's text meets no text or curve and
// its lines run through no text. Returns the direction used.
double place_radius(io::Drawing& d, double cx, double cy, double r, const std::vector<double>& dirs, double r_label,
                    const std::string& text, double h) {
  std::vector<io::Drawing> candidates;
  std::vector<double> used;
  for (double dir : dirs)
    for (double shift_deg : {0.0, 6.0, -6.0, 12.0, -12.0, 20.0, -20.0}) {
      candidates.push_back(radius_dimension(cx, cy, r, dir, shift_deg * kPi / 180.0, r_label, text, h));
      used.push_back(dir);
    }
  return used[io::place_first_fitting(d, candidates)];
}

// An arc arrow about the centre in the sense of rotation, spanning 50 deg from `a0`, with its
// text in two lines ("rotation:" over the sense; one line of 27 characters ran into the base
// circle of a 40 mm cam) centred on (tx, ty).
io::Drawing rotation_arrow(const CamModel& model, double a0_deg, double tx, double ty, double h) {
  io::Drawing a;
  const bool ccw = model.design.rotation == gc::Rotation::ccw;
  const double r = std::max(0.35 * model.design.base_radius, 3.0 * h), a1_deg = a0_deg + 50.0;
  a.arcs.push_back({"dimensions", 0.0, 0.0, r, a0_deg, a1_deg});
  const double tip = (ccw ? a1_deg : a0_deg) * kPi / 180.0;
  io::add_arrow_head(a, r * std::cos(tip), r * std::sin(tip), tip + (ccw ? 0.5 : -0.5) * kPi, 1.2 * h, "dimensions");
  const std::string sense = ccw ? "counter-clockwise" : "clockwise";
  const double x = tx - 0.5 * io::text_width(sense, h);
  a.texts.push_back({"dimensions", x, ty + 0.35 * h, h, "rotation:"});
  a.texts.push_back({"dimensions", x, ty - 1.15 * h, h, sense});
  return a;
}

// The arrow in the first of four places (lower left first) with its text on a grid of text
// heights around the point beyond the arc's middle, nearest first, where nothing crosses the text
// and the arc crosses no text. Returns the arrow's middle direction.
double place_rotation_arrow(io::Drawing& d, const CamModel& model, double h) {
  const double r = std::max(0.35 * model.design.base_radius, 3.0 * h);
  std::vector<std::pair<int, int>> grid;
  for (int i = -8; i <= 8; ++i)
    for (int j = -8; j <= 8; ++j) grid.emplace_back(i, j);
  std::stable_sort(grid.begin(), grid.end(), [](auto a, auto b) { return a.first * a.first + a.second * a.second < b.first * b.first + b.second * b.second; });
  std::vector<io::Drawing> candidates;
  std::vector<double> middle;
  for (double a0 : {200.0, 290.0, 20.0, 110.0}) {
    const double m = (a0 + 25.0) * kPi / 180.0, cx = 1.6 * r * std::cos(m), cy = 1.6 * r * std::sin(m);
    for (const auto& [i, j] : grid) {
      candidates.push_back(rotation_arrow(model, a0, cx + i * h, cy + j * h, h));
      middle.push_back(m);
    }
  }
  return middle[io::place_first_fitting(d, candidates)];
}

// The largest radius's direction: at its cam angle, or mid-dwell when it lies on a dwell (a
// circle there).
double max_radius_direction(const CamModel& model, const CamResult& result, double turn) {
  const gc::ValueAt& rmax = result.checks.radius_max;
  double theta_max = rmax.theta;
  for (const gc::Segment& seg : model.design.program.segments()) {
    const double into = std::fmod(std::fmod(rmax.theta - seg.start, 2 * kPi) + 2 * kPi, 2 * kPi);
    const bool on = into <= seg.end - seg.start + 1e-4 || into >= 2 * kPi - 1e-4;  // the sampled maximum may sit at a join
    if (seg.kind == gc::SegmentKind::dwell && on) theta_max = 0.5 * (seg.start + seg.end);
  }
  const gc::Vec2 p = turned(gc::contact_at(model.design, theta_max).contact, turn);
  return std::atan2(p.y, p.x);
}

// Largest, base and prime radii and the roller, each with a radius dimension whose text lies
// beyond the cam, and the rotation arrow; in that order, each placed clear of what is drawn.
void radii(io::Drawing& d, const CamModel& model, const CamResult& result, double turn, double r_out, double h,
           std::vector<double> taken) {
  const gc::CamDesign& design = model.design;
  const double rb = design.base_radius, r_label = r_out + 1.5 * h;
  const double rmax = result.checks.radius_max.value, max_dir = max_radius_direction(model, result, turn);
  place_radius(d, 0, 0, rmax, {max_dir}, r_label, fmt::format("R_max = {}", io::fixed(rmax, 3)), h);
  taken.push_back(max_dir);
  const double arrow = place_rotation_arrow(d, model, h);
  for (double a : {-25.0, 0.0, 25.0}) taken.push_back(arrow + a * kPi / 180.0);
  taken.push_back(place_radius(d, 0, 0, rb, directions_to_try(taken, 300.0 * kPi / 180.0), r_label,
                               fmt::format("R_b = {} (base)", io::fixed(rb, 3)), h));
  const gc::Follower& f = design.follower;
  if (f.contact != gc::Contact::roller) return;
  const double rp = rb + f.roller_radius;
  d.circles.push_back({"prime_circle", 0, 0, rp});
  place_radius(d, 0, 0, rp, directions_to_try(taken, 330.0 * kPi / 180.0), r_label,
               fmt::format("R_p = {} (prime)", io::fixed(rp, 3)), h);
  const gc::Vec2 c = gc::contact_at(design, model.follower_at).follower_point;
  std::vector<double> around;
  for (double a : {45.0, 135.0, 0.0, 180.0, 20.0, 160.0, 315.0, 225.0}) around.push_back(a * kPi / 180.0);
  place_radius(d, c.x, c.y, f.roller_radius, around, f.roller_radius + 2.0 * h,
               fmt::format("r_r = {}", io::fixed(f.roller_radius, 3)), h);
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
  const double r_max = result.checks.radius_max.value;
  const double h = io::text_height_for(2.0 * r_max);
  const double r_out = std::max(outer_radius(d), r_max);
  std::vector<double> taken = angle_marks(d, at, turn, r_out, h);
  const gc::Vec2 follower = gc::contact_at(model.design, follower_at).follower_point;
  taken.push_back(std::atan2(follower.y, follower.x));
  radii(d, at, result, turn, r_out, h, taken);
  const io::Box box = io::drawing_box(d);
  const double x = box.xmax + 4.0 * h;
  double y = box.ymax;
  y -= io::add_legend(d, legend(d, at), x, y, h, "legend").height + 2.0 * h;
  for (const char* title : {"Motion program", "Checks"}) {
    const io::TextTable t = text_table(report, title);
    if (!t.rows.empty()) y -= io::add_table(d, t, x, y, h, "tables", "frame").height + 2.0 * h;
  }
  title_block(d, at, report, x, y, h);
  io::add_frame(d, 2.0 * h, "frame");  // what "fit to page" fits: labels at the edge stay on the page
  return d;
}

}  // namespace gearkit::plugins::cam
