#include "gear_bevel_drawing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

const std::vector<io::Layer> kLayers = {
    {"gear1", 5, "#1f4e9a", false},      {"gear2", 1, "#b02020", false},    {"axes", 8, "#808080", true},
    {"pitch_cone", 3, "#2a7f2a", true},  {"back_cone", 8, "#707070", true}, {"labels", 7, "#000000", false},
    {"data_block", 7, "#000000", false}, {"frame", 7, "#000000", false}};

struct P2 {
  double x = 0, y = 0;
};
P2 operator+(P2 a, P2 b) { return {a.x + b.x, a.y + b.y}; }
P2 operator*(double s, P2 a) { return {s * a.x, s * a.y}; }
double dot(P2 a, P2 b) { return a.x * b.x + a.y * b.y; }

std::string mm(double v) { return io::fixed(v, 3); }
std::string deg(double rad) { return io::fixed(rad * kDeg, 4); }

// The section of one gear on the meshing side of its axis, in the drawing plane: tooth zone
// (outer tip, inner tip, inner root, outer root) and a plain blank (front face at the inner root,
// bore, back face through the back cone below the outer root).
struct GearSection {
  std::vector<P2> tooth, blank;
};

GearSection section(const gg::BevelPairResult& r, const gg::BevelGearResult& g, P2 gen, P2 c, P2 axis, double m) {
  GearSection s;
  const P2 tip_o = r.R_e * gen + g.h_ae * c, tip_i = r.R_i * gen + g.h_ai * c;
  const P2 root_i = r.R_i * gen + (-g.h_fi) * c, root_o = r.R_e * gen + (-g.h_fe) * c;
  s.tooth = {tip_o, tip_i, root_i, root_o};
  // Radial unit of this side: the part of c across the axis.
  const P2 radial = c + (-dot(c, axis)) * axis;
  const double rl = std::hypot(radial.x, radial.y);
  const P2 rad = (1.0 / rl) * radial;
  const P2 back = r.R_e * gen + (-(g.h_fe + 1.5 * m)) * c;  // on the back cone, below the root
  auto radius = [&](P2 p) { return dot(p, rad); };
  auto at = [&](double axial, double rr) { return axial * axis + rr * rad; };
  const double r_bore = 0.45 * std::max(0.0, std::min(radius(root_i), radius(back)));
  s.blank = {root_i, at(dot(root_i, axis), r_bore), at(dot(back, axis), r_bore), back, root_o};
  return s;
}

// The same points mirrored across the gear's axis (the other side of the section).
std::vector<P2> mirrored(const std::vector<P2>& pts, P2 axis) {
  std::vector<P2> out;
  for (const P2& p : pts) out.push_back((2.0 * dot(p, axis)) * axis + (-1.0) * p);
  return out;
}

void polyline(io::Drawing& d, const std::vector<P2>& pts, const char* layer, bool closed) {
  io::Polyline pl{layer, {}, closed};
  for (const P2& p : pts) pl.vertices.push_back({p.x, p.y, 0.0});
  d.polylines.push_back(std::move(pl));
}

void draw_gear(io::Drawing& d, const gg::BevelPairResult& r, int i, P2 gen, P2 c, P2 axis, double m) {
  const char* layer = i == 0 ? "gear1" : "gear2";
  const GearSection s = section(r, r.gear[i], gen, c, axis, m);
  polyline(d, s.tooth, layer, true);
  polyline(d, s.blank, layer, false);
  polyline(d, mirrored(s.tooth, axis), layer, true);
  polyline(d, mirrored(s.blank, axis), layer, false);
  const P2 pe = r.R_e * gen;
  // Pitch cone (apex to the outer pitch point, both sides), back cone, axis.
  polyline(d, {{0, 0}, pe}, "pitch_cone", false);
  polyline(d, {{0, 0}, mirrored({pe}, axis)[0]}, "pitch_cone", false);
  const P2 foot = dot(pe, axis) * axis;
  polyline(d, {pe, foot, mirrored({pe}, axis)[0]}, "back_cone", false);
  const double reach = dot(s.blank[2], axis) + 3.0 * m;
  polyline(d, {(-3.0 * m) * axis, reach * axis}, "axes", false);
}

void angle_arc(io::Drawing& d, double radius, double from, double to, const std::string& text, double h) {
  d.arcs.push_back({"labels", 0.0, 0.0, radius, from * kDeg, to * kDeg});
  const double mid = 0.5 * (from + to);
  d.texts.push_back({"labels", (radius + 0.8 * h) * std::cos(mid), (radius + 0.8 * h) * std::sin(mid) - 0.5 * h, h, text});
}

}  // namespace

io::TextTable bevel_data_table(const gg::BevelPairInput& in, const gg::BevelPairResult& r) {
  io::TextTable t;
  t.title = fmt::format("Bevel gear data ({} {}, {} depth)", to_string(in.system), to_string(in.type), to_string(in.taper));
  t.header = {"quantity", "symbol", "gear 1", "gear 2"};
  const auto& a = r.gear[0];
  const auto& b = r.gear[1];
  t.rows = {{"number of teeth", "z", std::to_string(a.z), std::to_string(b.z)},
            {"outer transverse module", "m_et", mm(in.m_et), mm(in.m_et)},
            {"normal pressure angle", "alpha_n", deg(in.alpha_n), deg(in.alpha_n)},
            {"shaft angle", "Sigma", deg(in.Sigma), deg(in.Sigma)}};
  if (in.type == gg::BevelType::spiral)
    t.rows.push_back({"mean spiral angle, hand", "beta_m", deg(in.beta_m) + " " + to_string(a.hand), deg(in.beta_m) + " " + to_string(b.hand)});
  const std::vector<std::vector<std::string>> rows = {
      {"face width", "b", mm(in.b), mm(in.b)},
      {"outer cone distance", "R_e", mm(r.R_e), mm(r.R_e)},
      {"pitch cone angle", "delta", deg(a.delta), deg(b.delta)},
      {"face angle", "delta_a", deg(a.delta_a), deg(b.delta_a)},
      {"root angle", "delta_f", deg(a.delta_f), deg(b.delta_f)},
      {"outer pitch diameter", "d_e", mm(a.d_e), mm(b.d_e)},
      {"outer tip diameter", "d_ae", mm(a.d_ae), mm(b.d_ae)},
      {"outer addendum", "h_ae", mm(a.h_ae), mm(b.h_ae)},
      {"outer dedendum", "h_fe", mm(a.h_fe), mm(b.h_fe)},
      {"crown to crossing point", "t_xo", mm(a.t_xo), mm(b.t_xo)},
      {"axial face width (tip)", "b_x", mm(a.b_x), mm(b.b_x)},
      {"inner tip diameter", "d_ai", mm(a.d_ai), mm(b.d_ai)}};
  t.rows.insert(t.rows.end(), rows.begin(), rows.end());
  return t;
}

io::Drawing bevel_drawing(const gg::BevelPairInput& in, const gg::BevelPairResult& r) {
  io::Drawing d;
  d.layers = kLayers;
  const double d1 = r.gear[0].delta;
  const P2 gen{std::cos(d1), std::sin(d1)}, c1{-std::sin(d1), std::cos(d1)};
  const P2 a1{1.0, 0.0}, a2{std::cos(in.Sigma), std::sin(in.Sigma)};
  const double h = io::text_height_for(2.0 * r.R_e);
  draw_gear(d, r, 0, gen, c1, a1, in.m_et);
  draw_gear(d, r, 1, gen, (-1.0) * c1, a2, in.m_et);
  angle_arc(d, 0.30 * r.R_e, 0.0, d1, fmt::format("delta1 = {}°", deg(d1)), h);
  angle_arc(d, 0.45 * r.R_e, d1, in.Sigma, fmt::format("delta2 = {}°", deg(r.gear[1].delta)), h);
  angle_arc(d, 0.18 * r.R_e, 0.0, in.Sigma, fmt::format("Sigma = {}°", deg(in.Sigma)), h);
  // Face width along the pitch cone, and the outer tip diameters at the crowns.
  // The face width at gear 1's tooth on the far side of its axis, where nothing else is drawn.
  const P2 mid{r.R_m * gen.x, -r.R_m * gen.y};
  io::add_label(d, mid.x, mid.y, mid.x + 3.0 * h, mid.y - 8.0 * h, fmt::format("b = {} mm, R_e = {} mm", mm(in.b), mm(r.R_e)), h, "labels");
  for (int i = 0; i < 2; ++i) {
    const P2 axis = i == 0 ? a1 : a2, c = i == 0 ? c1 : (-1.0) * c1;
    const P2 crown = r.R_e * gen + r.gear[i].h_ae * c;
    const P2 away = crown + (3.0 * h) * (i == 0 ? c : axis);
    io::add_label(d, crown.x, crown.y, away.x + 2.0 * h, away.y, fmt::format("d_ae{} = {} mm", i + 1, mm(r.gear[i].d_ae)), h, "labels");
  }
  const io::Box box = io::drawing_box(d);
  io::add_table(d, bevel_data_table(in, r), box.xmax + 4.0 * h, box.ymax, h, "data_block", "frame");
  io::add_frame(d, 2.0 * h, "frame");
  return d;
}

}  // namespace gearkit::plugins::gear
