#include "gear_types_drawing.hpp"

#include "gear_drawing.hpp"

#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/rack.hpp>
#include <gearkit/gear/tooth_form.hpp>
#include <gearkit/io/drawing_annotation.hpp>
#include <gearkit/io/report.hpp>

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
constexpr double kPi = std::numbers::pi;
constexpr int kMaxRackTeeth = 2000;  // a longer rack is drawn with this many teeth (about 100 kB of SVG)

std::string mm(double v) { return std::isfinite(v) ? io::fixed(v, 3) : std::string("-"); }
std::string deg(double rad) { return io::fixed(rad * kDeg, 3) + "°"; }

std::vector<io::Layer> layers() {
  std::vector<io::Layer> l = gear_drawing_layers();
  l.push_back({"rack", 1, "#b02020", false});
  l.push_back({"worm", 5, "#1f4e9a", false});
  l.push_back({"datum_line", 3, "#2a7f2a", true});
  l.push_back({"line_of_action", 4, "#008080", true});
  l.push_back({"outside_circle", 8, "#707070", true});
  return l;
}

// A straight-flank rack profile as heights u above its datum line at increasing x from x0 to x1:
// teeth of thickness s on the datum line centred at offset + k p, addendum h_a, dedendum h_f,
// flanks inclined by alpha (tan_a) to the datum line's normal. The worm's axial section is such
// a profile too.
struct ProfilePoint {
  double x = 0, u = 0;
};
std::vector<ProfilePoint> rack_profile(double x0, double x1, double offset, double p, double s, double h_a, double h_f, double tan_a) {
  std::vector<ProfilePoint> corners;
  const long k0 = static_cast<long>(std::floor((x0 - offset) / p)) - 1, k1 = static_cast<long>(std::ceil((x1 - offset) / p)) + 1;
  const double root = std::min(0.5 * s + h_f * tan_a, 0.5 * p);  // roots of neighbours meet at most in the space's middle
  for (long k = k0; k <= k1; ++k) {
    const double c = offset + static_cast<double>(k) * p;
    corners.push_back({c - root, -h_f});
    corners.push_back({c - 0.5 * s + h_a * tan_a, h_a});
    corners.push_back({c + 0.5 * s - h_a * tan_a, h_a});
    corners.push_back({c + root, -h_f});
  }
  auto u_at = [&](double x) {
    for (std::size_t i = 1; i < corners.size(); ++i) {
      if (corners[i].x < x) continue;
      const ProfilePoint& a = corners[i - 1];
      const ProfilePoint& b = corners[i];
      return b.x == a.x ? b.u : a.u + (b.u - a.u) * (x - a.x) / (b.x - a.x);
    }
    return -h_f;
  };
  std::vector<ProfilePoint> out{{x0, u_at(x0)}};
  for (const ProfilePoint& c : corners)
    if (c.x > x0 && c.x < x1) out.push_back(c);
  out.push_back({x1, u_at(x1)});
  return out;
}

gg::GearResult circles_of(double d_a, double d, double d_b, double d_f) {
  gg::GearResult g;
  g.d_a = d_a;
  g.d = d;
  g.d_b = d_b;
  g.d_f = d_f;
  return g;
}

io::TextTable rack_data(const gg::RackPinionInput& in, const gg::RackPinionResult& r) {
  io::TextTable t;
  t.title = "Rack and pinion data (ISO 1340), mm";
  t.header = {"", "symbol", "pinion", "rack"};
  const std::string hand = in.beta > 0.0 ? " right" : in.beta < 0.0 ? " left" : " (spur)";
  t.rows = {{"number of teeth", "z", std::to_string(in.z1), in.travel ? std::to_string(r.rack_teeth) : "-"},
            {"normal module", "m_n", mm(in.m_n), mm(in.m_n)},
            {"normal pressure angle", "α_n", deg(in.alpha_n), deg(in.alpha_n)},
            {"helix angle, hand", "β", deg(std::fabs(in.beta)) + hand, deg(std::fabs(in.beta))},
            {"basic rack h_aP*/h_fP*/ρ_fP*", "", fmt::format("{}/{}/{}", io::fixed(in.h_aP, 3), io::fixed(in.h_fP, 3), io::fixed(in.rho_fP, 3)), "-"},
            {"profile shift coefficient", "x", io::fixed(r.x1, 4), "-"},
            {"reference diameter; rack pitch", "d; p_t", mm(r.d), mm(r.p_t)},
            {"tip diameter; rack addendum", "d_a; h_a", mm(r.d_a), mm(r.h_a2)},
            {"root diameter; rack dedendum", "d_f; h_f", mm(r.d_f), mm(r.h_f2)},
            {"span", "W_k", fmt::format("k = {}: {}", r.k_span, mm(r.W_k_actual)), "-"},
            {"over pins; over a pin from the datum line", "M", fmt::format("D_M {}: {}", mm(r.pin_diameter1), mm(r.M_d_actual)),
             fmt::format("D_M {}: {}", mm(r.pin_diameter2), mm(r.M_r_actual))},
            {"datum line from the pinion axis", "H_0", mm(r.H_0), ""},
            {"rack back from the pinion axis", "", mm(r.a_back), in.rack_height ? "H = " + mm(*in.rack_height) : "-"},
            {"rack length (travel)", "L", "", in.travel ? fmt::format("{} ({})", mm(r.rack_length), mm(*in.travel)) : "-"},
            {"transverse contact ratio", "ε_α", io::fixed(r.eps_alpha, 3), ""}};
  return t;
}

void title(io::Drawing& d, const std::string& what, const std::string& views, double x, double y_top, double h) {
  io::TextTable t;
  t.title = what;
  t.rows = {{"drawing", views}, {"units", "lengths mm, angles deg"}};
  io::add_table(d, t, x, y_top, h, "title_block", "frame");
}

// The rack below the pinion (frame of rack_pinion.hpp), teeth centred on x = 0 or, for an even
// number, on x = +-p/2, so that the rack ends in a space's middle; returns the rack's extent in x.
std::pair<double, double> draw_rack(io::Drawing& d, const gg::RackPinionInput& in, const gg::RackPinionResult& r, bool& tooth_at_zero) {
  const int wanted = in.travel ? r.rack_teeth : static_cast<int>(std::ceil(1.6 * r.d_a / r.p_t));
  const int n = std::clamp(wanted, 3, kMaxRackTeeth);
  tooth_at_zero = n % 2 == 1;
  const double x0 = -0.5 * n * r.p_t, x1 = -x0, y0 = -r.H_0;
  const double y_back = y0 - (in.rack_height ? *in.rack_height : r.h_f2 + 2.0 * in.m_n);
  io::Polyline pl{"rack", {}, true};
  pl.vertices.push_back({x0, y_back});
  for (const ProfilePoint& p : rack_profile(x0, x1, tooth_at_zero ? 0.0 : 0.5 * r.p_t, r.p_t, 0.5 * r.p_t, r.h_a2, r.h_f2, std::tan(r.alpha_t)))
    pl.vertices.push_back({p.x, y0 + p.u});
  pl.vertices.push_back({x1, y_back});
  d.polylines.push_back(std::move(pl));
  return {x0, x1};
}

void worm_thread(io::Drawing& d, const gg::WormInput& in, const gg::WormResult& w, double x0, double x1) {
  const double s = 0.5 * w.p_x, h_a = in.h_aP * in.m_x, h_f = in.h_fP * in.m_x, tan_a = std::tan(w.alpha_x);
  // The opposite side of the axial section is half a lead further along the axis.
  const double far_offset = std::fmod(0.5 * w.p_z, w.p_x);
  io::Polyline pl{"worm", {}, true};
  for (const ProfilePoint& p : rack_profile(x0, x1, 0.0, w.p_x, s, h_a, h_f, tan_a)) pl.vertices.push_back({p.x, w.a - 0.5 * w.d_m1 - p.u});
  const auto far = rack_profile(x0, x1, far_offset, w.p_x, s, h_a, h_f, tan_a);
  for (auto it = far.rbegin(); it != far.rend(); ++it) pl.vertices.push_back({it->x, w.a + 0.5 * w.d_m1 + it->u});
  d.polylines.push_back(std::move(pl));
  const double L = x1 - x0, r_s = 0.4 * w.d_f1;  // shaft stubs beyond the thread
  for (double sign : {-1.0, 1.0}) {
    const double xa = sign < 0 ? x0 - 0.25 * L : x1, xb = sign < 0 ? x0 : x1 + 0.25 * L;
    d.polylines.push_back({"worm", {{xa, w.a - r_s}, {xb, w.a - r_s}, {xb, w.a + r_s}, {xa, w.a + r_s}}, true});
  }
  d.lines.push_back({"centres", x0 - 0.25 * L - 2.0 * in.m_x, w.a, x1 + 0.25 * L + 2.0 * in.m_x, w.a});
  for (double sign : {-1.0, 1.0}) d.lines.push_back({"reference_circle", x0, w.a + sign * 0.5 * w.d_m1, x1, w.a + sign * 0.5 * w.d_m1});
}

// The section through the wheel's axis (right view): rim with face width b2 and the throat, an
// arc of radius r_k about the worm axis; the worm's circles; centre lines; labels.
void wheel_section(io::Drawing& d, const gg::WormInput& in, const gg::WormResult& w, double X, double h) {
  const double half_b = 0.5 * w.b2, r_e = 0.5 * w.d_e2, y_body = std::max(0.5 * w.d_f2 - 2.5 * in.m_x, 0.25 * w.d_f2);
  io::Polyline rim{"gear2", {{X - half_b, y_body}, {X + half_b, y_body}}, true};
  const double w_e = std::sqrt(std::max(0.0, w.r_k * w.r_k - (w.a - r_e) * (w.a - r_e)));  // where the throat meets d_e2
  const double half = std::min(half_b, w_e);
  const double y_side = w.a - std::sqrt(std::max(0.0, w.r_k * w.r_k - half * half));
  const double bulge = -std::tan(std::asin(std::min(1.0, half / w.r_k)) / 2.0);  // clockwise through the throat's bottom
  if (half_b > w_e) {
    rim.vertices.push_back({X + half_b, r_e});
    rim.vertices.push_back({X + half, y_side, bulge});
    rim.vertices.push_back({X - half, y_side});
    rim.vertices.push_back({X - half_b, r_e});
  } else {
    rim.vertices.push_back({X + half_b, y_side, bulge});
    rim.vertices.push_back({X - half_b, y_side});
  }
  d.polylines.push_back(std::move(rim));
  for (const auto& [layer, R] : {std::pair{"root_circle", w.a - 0.5 * w.d_f2}, std::pair{"reference_circle", w.a - 0.5 * w.d2}}) {
    const double phi = std::asin(std::min(1.0, half_b / R)) * kDeg;
    d.arcs.push_back({layer, X, w.a, R, 270.0 - phi, 270.0 + phi});
  }
  d.circles.push_back({"tip_circle", X, w.a, 0.5 * w.d_a1});
  d.circles.push_back({"reference_circle", X, w.a, 0.5 * w.d_m1});
  d.circles.push_back({"root_circle", X, w.a, 0.5 * w.d_f1});
  d.lines.push_back({"centres", X - half_b - 2.0 * h, 0.0, X + half_b + 2.0 * h, 0.0});
  d.lines.push_back({"centres", X, y_body - h, X, w.a + 0.5 * w.d_a1 + h});
  draw_centre_mark(d, X, w.a, in.m_x);
  const double tx = X + std::max(half_b, 0.5 * w.d_a1) + 3.0 * h;
  io::add_label(d, X + half_b, 0.5 * (y_body + y_side), tx, y_body + h, fmt::format("b2 = {}", mm(w.b2)), h, "labels");
  io::add_label(d, X, w.a - w.r_k, tx, w.a - w.r_k - 1.5 * h, fmt::format("r_k = {} (throat, about the worm axis)", mm(w.r_k)), h, "labels");
  io::add_label(d, X + 0.5 * w.d_a1 * std::cos(0.8), w.a + 0.5 * w.d_a1 * std::sin(0.8), tx, w.a + 0.5 * w.d_a1 + h,
                fmt::format("d_a1 = {}, d_m1 = {}, d_f1 = {}", mm(w.d_a1), mm(w.d_m1), mm(w.d_f1)), h, "labels");
  d.texts.push_back({"labels", X - half_b, w.a + 0.5 * w.d_a1 + 3.0 * h, h, "section through the wheel axis"});
}

io::TextTable worm_data(const gg::WormInput& in, const gg::WormResult& w) {
  io::TextTable t;
  t.title = "Worm pair data (DIN 3975), mm";
  t.header = {"", "symbol", "worm", "wheel"};
  const std::string hand = in.right_hand ? "right" : "left";
  t.rows = {{"threads; teeth", "z", std::to_string(in.z1), std::to_string(in.z2)},
            {"flank form; hand", "", std::string(gg::to_string(in.flank)) + ", " + hand, hand},
            {"axial module", "m_x", mm(in.m_x), mm(in.m_x)},
            {"pressure angle axial; normal", "α_x; α_n", deg(w.alpha_x), deg(w.alpha_n)},
            {"diameter quotient", "q", io::fixed(w.q, 4), ""},
            {"lead angle", "γ", deg(w.gamma), ""},
            {"axial pitch; lead", "p_x; p_z", mm(w.p_x), mm(w.p_z)},
            {"profile shift coefficient", "x", "", io::fixed(w.x2, 4)},
            {"reference diameter", "d", mm(w.d_m1), mm(w.d2)},
            {"tip; throat diameter", "d_a", mm(w.d_a1), mm(w.d_a2)},
            {"root diameter", "d_f", mm(w.d_f1), mm(w.d_f2)},
            {"outside diameter", "d_e2", "", mm(w.d_e2)},
            {"throat radius", "r_k", "", mm(w.r_k)},
            {"thread length; face width", "b", mm(w.b1 + w.p_x), mm(w.b2)},
            {"centre distance", "a", mm(w.a), ""}};
  return t;
}

}  // namespace

io::Drawing rack_drawing(const gg::RackPinionInput& in, const gg::RackPinionResult& r, double tolerance) {
  io::Drawing d;
  d.layers = layers();
  bool tooth_at_zero = true;
  const auto [x0, x1] = draw_rack(d, in, r, tooth_at_zero);
  const double h = io::text_height_for(std::max(x1 - x0, r.d_a));
  gg::ToothFormSpec s;
  s.z = in.z1;
  s.m_n = in.m_n;
  s.beta = in.beta;
  s.x = r.x1;
  s.d_a = r.d_a;
  s.rack = gg::Rack{in.alpha_n, in.h_aP, in.h_fP, in.rho_fP};
  s.tolerance = tolerance;
  // gear_outline puts a space at +y: turn it half a turn (a space at the bottom for the rack's
  // tooth at x = 0), or half a pitch more (a tooth at the bottom).
  const double turn = kPi + (tooth_at_zero ? 0.0 : kPi / in.z1);
  d.polylines.push_back(outline_polyline(gg::placed(gg::gear_outline(s), turn, 0.0, 0.0), "gear1"));
  draw_gear_circles(d, circles_of(r.d_a, r.d, r.d_b, r.d_f), 0.0, 0.0, -1.0, h);
  draw_centre_mark(d, 0.0, 0.0, in.m_n);
  const double y0 = -r.H_0, r1 = 0.5 * r.d, ext = 2.0 * in.m_n;
  d.lines.push_back({"datum_line", x0 - ext, y0, x1 + ext, y0});
  io::add_label(d, x1 + ext, y0, x1 + ext + 2.0 * h, y0 - 1.5 * h, fmt::format("datum line, H_0 = {}", mm(r.H_0)), h, "labels");
  if (std::fabs(r.x1) > 1e-9) {
    d.lines.push_back({"working_pitch", x0 - ext, -r1, x1 + ext, -r1});
    io::add_label(d, x1 + ext, -r1, x1 + ext + 2.0 * h, -r1 + 1.5 * h, fmt::format("pitch line, x m_n = {} from the datum", mm(r.x1 * in.m_n)), h, "labels");
  }
  const double sa = std::sin(r.alpha_t), ca = std::cos(r.alpha_t);
  const double Tx = r1 * sa * ca, Ty = -r1 * ca * ca;  // tangent point on the base circle
  d.lines.push_back({"line_of_action", Tx, Ty, -Tx, -2.0 * r1 - Ty});
  // Its label left of the rack, clear of the teeth.
  io::add_label(d, -Tx, -2.0 * r1 - Ty, x0 - ext - h, y0 - 1.5 * h, fmt::format("line of action, α_t = {}", deg(r.alpha_t)), h, "labels");
  const io::Box box = io::drawing_box(d);
  const double x = box.xmax + 4.0 * h;
  const io::Size block = io::add_table(d, rack_data(in, r), x, box.ymax, h, "data_block", "frame");
  title(d, "gearkit gear rack", in.beta != 0.0 ? "pinion and rack, transverse section" : "pinion and rack", x, box.ymax - block.height - 2.0 * h, h);
  io::add_frame(d, 2.0 * h, "frame");
  return d;
}

io::Drawing worm_drawing(const gg::WormInput& in, const gg::WormResult& w, double tolerance) {
  io::Drawing d;
  d.layers = layers();
  const double h = io::text_height_for(std::max(w.d_e2 + w.b2, w.a + w.d_a1));
  gg::ToothFormSpec s;
  s.z = in.z2;
  s.m_n = in.m_x;
  s.x = w.x2;
  s.d_a = w.d_a2;
  s.rack = gg::Rack{w.alpha_x, in.h_aP, in.h_fP, 0.0};
  s.rack.rho_fP = std::min(0.2, gg::max_fillet_radius_coefficient(s.rack));
  s.tolerance = tolerance;
  d.polylines.push_back(outline_polyline(gg::gear_outline(s), "gear2"));  // a space at +y, under the worm's thread at x = 0
  draw_gear_circles(d, circles_of(w.d_a2, w.d2, w.d2 * std::cos(w.alpha_x), w.d_f2), 0.0, 0.0, -1.0, h);
  d.circles.push_back({"outside_circle", 0.0, 0.0, 0.5 * w.d_e2});
  const double r_e = 0.5 * w.d_e2;
  draw_centre_mark(d, 0.0, 0.0, in.m_x);
  const int n = std::max(3, static_cast<int>(std::ceil((w.b1 + w.p_x) / w.p_x)));
  const double x0 = -0.5 * n * w.p_x, x1 = -x0;
  worm_thread(d, in, w, x0, x1);
  draw_centre_mark(d, 0.0, w.a, in.m_x);
  const double tx = std::max(x1 + 0.25 * (x1 - x0), r_e) + 3.0 * h;
  io::add_label(d, r_e * std::cos(-0.6), r_e * std::sin(-0.6), tx, -0.5 * r_e, fmt::format("d_e2 = {} (outside)", mm(w.d_e2)), h, "labels");
  io::add_label(d, x1, w.a - 0.5 * w.d_m1, tx, w.a - 0.5 * w.d_m1 - 2.0 * h, fmt::format("worm d_m1 = {}, γ = {}", mm(w.d_m1), deg(w.gamma)), h, "labels");
  io::add_label(d, x1 + 0.25 * (x1 - x0), w.a, tx, w.a + 2.0 * h, fmt::format("worm axis, a = {}", mm(w.a)), h, "labels");
  d.texts.push_back({"labels", x0, w.a + 0.5 * w.d_a1 + 3.0 * h, h, "wheel mid-plane, worm in axial section"});
  const io::Box left = io::drawing_box(d);
  const double X = left.xmax + 4.0 * h + std::max(0.5 * w.b2, 0.5 * w.d_a1);
  wheel_section(d, in, w, X, h);
  const io::Box box = io::drawing_box(d);
  const double x = box.xmax + 4.0 * h;
  const io::Size block = io::add_table(d, worm_data(in, w), x, box.ymax, h, "data_block", "frame");
  title(d, "gearkit gear worm", "wheel mid-plane and worm axial section; section through the wheel axis", x, box.ymax - block.height - 2.0 * h, h);
  io::add_frame(d, 2.0 * h, "frame");
  return d;
}

}  // namespace gearkit::plugins::gear
