#include "gear_drawing.hpp"

#include <gearkit/gear/accuracy.hpp>
#include <gearkit/io/drawing_annotation.hpp>
#include <gearkit/io/error.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

std::string mm(double v) { return std::isfinite(v) ? io::fixed(v, 3) : std::string("-"); }

std::string helix(double beta, gg::HelixHand hand) {
  if (hand == gg::HelixHand::spur) return "0° (spur)";
  return fmt::format("{}° {}", io::fixed(std::fabs(beta) * kDeg, 3), gg::to_string(hand));
}

// Whether span() and pins() show a max / min pair (an inspection with an acceptance band).
bool has_span_limits(const gg::GearResult& g, const gg::GearInspection* gi) {
  return g.k_span > 0 && std::isfinite(g.W_k) && gi && gi->acceptance_band && std::isfinite(gi->W_k_max);
}
bool has_pin_limits(const gg::GearResult& g, const gg::GearInspection* gi) {
  return std::isfinite(g.M_d) && gi && gi->acceptance_band && std::isfinite(gi->M_d_max);
}

std::string span(const gg::GearResult& g, const gg::GearInspection* gi) {
  if (g.k_span <= 0 || !std::isfinite(g.W_k)) return "-";
  if (gi && !gi->acceptance_band) return fmt::format("k = {}: no acceptance band", g.k_span);
  if (gi && std::isfinite(gi->W_k_max)) return fmt::format("k = {}: {} / {}", g.k_span, mm(gi->W_k_max), mm(gi->W_k_min));
  return fmt::format("k = {}: {}", g.k_span, mm(g.A_sn != 0.0 ? g.W_k_actual : g.W_k));
}

std::string pins(const gg::GearResult& g, const gg::GearInspection* gi) {
  if (!std::isfinite(g.M_d)) return "-";
  if (gi && !gi->acceptance_band) return fmt::format("D_M {}: no acceptance band", mm(gi->D_M));
  if (gi && std::isfinite(gi->M_d_max)) return fmt::format("D_M {}: {} / {}", mm(gi->D_M), mm(gi->M_d_max), mm(gi->M_d_min));
  return fmt::format("D_M {}: {}", mm(g.pin_diameter), mm(g.A_sn != 0.0 ? g.M_d_actual : g.M_d));
}

std::string centre_distance(const gg::GearPairResult& r, const gg::InspectionResult* insp) {
  if (!insp) return mm(r.pair.a);
  const auto& p = insp->pair;
  const std::string field = p.centre_distance_field == "given" ? "" : p.centre_distance_field + " ";
  return fmt::format("{} {}({:+.3f} / {:+.3f})", mm(r.pair.a), field, p.A_ae, p.A_ai);
}

using Cell = std::function<std::string(int)>;

void add_row(io::TextTable& t, const std::vector<int>& which, std::string name, std::string symbol, const Cell& cell) {
  std::vector<std::string> row{std::move(name), std::move(symbol)};
  for (int i : which) row.push_back(cell(i));
  t.rows.push_back(std::move(row));
}

void inspection_rows(io::TextTable& t, const std::vector<int>& which, const gg::InspectionResult& insp) {
  add_row(t, which, "thickness allowances", "A_sne / A_sni", [&](int i) {
    const auto& a = insp.gear[i].allowances;
    const std::string din = insp.gear[i].din3967.empty() ? "" : " (DIN 3967 " + insp.gear[i].din3967 + ")";
    return fmt::format("{:+.3f} / {:+.3f}{}", a.A_sne, a.A_sni, din);
  });
  add_row(t, which, "accuracy grade", "", [&](int i) {
    const auto& tol = insp.gear[i].tolerances;
    return tol ? fmt::format("{} class {}", gg::to_string(tol->edition), tol->grade) : std::string("-");
  });
}

}  // namespace

io::TextTable gear_data_table(const gg::GearPairInput& in, const gg::GearPairResult& r, const gg::InspectionResult* insp,
                              const std::vector<int>& which) {
  io::TextTable t;
  t.title = "Gear data (ISO 1340), mm";
  t.header = {"", "symbol"};
  for (int i : which) t.header.push_back(i == 0 ? "gear 1" : (r.gear[1].internal ? "gear 2 (ring)" : "gear 2"));
  auto g = [&](int i) -> const gg::GearResult& { return r.gear[static_cast<std::size_t>(i)]; };
  auto gi = [&](int i) { return insp ? &insp->gear[static_cast<std::size_t>(i)] : nullptr; };
  add_row(t, which, "number of teeth", "z", [&](int i) { return std::to_string(g(i).z); });
  add_row(t, which, "normal module", "m_n", [&](int i) { return mm(g(i).m_n); });
  add_row(t, which, "normal pressure angle", "α_n", [&](int i) { return io::fixed(g(i).alpha_n * kDeg, 3) + "°"; });
  add_row(t, which, "helix angle, hand", "β", [&](int i) { return helix(g(i).beta, gg::helix_hand(in, i)); });
  add_row(t, which, "basic rack h_aP*/h_fP*/ρ_fP*", "", [&](int i) {
    const gg::Rack tool = gg::tool_rack(in, i, g(i).alpha_n);
    return fmt::format("{}/{}/{}", io::fixed(tool.h_aP, 3), io::fixed(tool.h_fP, 3), io::fixed(tool.rho_fP, 3));
  });
  add_row(t, which, "profile shift coefficient", "x", [&](int i) { return io::fixed(g(i).x, 4); });
  add_row(t, which, "reference diameter", "d", [&](int i) { return mm(g(i).d); });
  add_row(t, which, "base diameter", "d_b", [&](int i) { return mm(g(i).d_b); });
  add_row(t, which, "tip diameter", "d_a", [&](int i) { return mm(g(i).d_a); });
  add_row(t, which, "root diameter", "d_f", [&](int i) { return mm(g(i).d_f); });
  // "max / min" only where a cell shows the two limits; without inspection it is one nominal value.
  const bool span_limits = std::any_of(which.begin(), which.end(), [&](int i) { return has_span_limits(g(i), gi(i)); });
  const bool pin_limits = std::any_of(which.begin(), which.end(), [&](int i) { return has_pin_limits(g(i), gi(i)); });
  add_row(t, which, span_limits ? "span max / min" : "span", "W_k", [&](int i) { return span(g(i), gi(i)); });
  add_row(t, which, pin_limits ? "over (ring: between) pins max / min" : "over (ring: between) pins", "M_d",
          [&](int i) { return pins(g(i), gi(i)); });
  if (insp) inspection_rows(t, which, *insp);
  add_row(t, which, "mating gear: teeth", "z", [&](int i) { return std::to_string(g(1 - i).z); });
  add_row(t, which, "centre distance", "a", [&](int) { return centre_distance(r, insp); });
  return t;
}

namespace {

const std::vector<io::Layer> kLayers = {
    {"gear1", 5, "#1f4e9a", false},        {"gear2", 1, "#b02020", false},
    {"reference_circle", 3, "#2a7f2a", true}, {"base_circle", 30, "#b06000", true},
    {"tip_circle", 8, "#707070", false},    {"root_circle", 8, "#707070", false},
    {"working_pitch", 6, "#a000a0", true},  {"centres", 8, "#808080", false},
    {"labels", 7, "#000000", false},        {"data_block", 7, "#000000", false},
    {"title_block", 7, "#000000", false},   {"frame", 7, "#000000", false}};

io::Polyline to_polyline(const std::vector<gg::ProfileVertex>& outline, std::string layer) {
  io::Polyline pl;
  pl.layer = std::move(layer);
  pl.closed = true;
  pl.vertices.reserve(outline.size());
  for (const auto& v : outline) pl.vertices.push_back({v.x, v.y, v.bulge});
  return pl;
}

void centre_mark(io::Drawing& d, double cx, double cy, double size) {
  d.lines.push_back({"centres", cx - size, cy, cx + size, cy});
  d.lines.push_back({"centres", cx, cy - size, cx, cy + size});
}

// The four circles of gear i centred at (cx, cy), each labelled with its diameter by a leader to a
// column of labels beside the gear (left for side < 0, right for side > 0).
void circles(io::Drawing& d, const gg::GearResult& g, double cx, double cy, double side, double h) {
  struct Named {
    const char* layer;
    const char* symbol;
    const char* name;
    double diameter;
  };
  const Named list[] = {{"tip_circle", "d_a", "tip", g.d_a},
                        {"reference_circle", "d", "reference", g.d},
                        {"base_circle", "d_b", "base", g.d_b},
                        {"root_circle", "d_f", "root", g.d_f}};
  const double r_out = 0.5 * std::max(g.d_a, g.d_f);
  for (int k = 0; k < 4; ++k) {
    const Named& c = list[k];
    const double r = 0.5 * c.diameter;
    d.circles.push_back({c.layer, cx, cy, r});
    const double angle = (side < 0 ? 120.0 + 9.0 * k : 60.0 - 9.0 * k) / kDeg;
    const double px = cx + r * std::cos(angle), py = cy + r * std::sin(angle);
    const double tx = cx + side * (r_out + 3.0 * h), ty = cy + r_out + 2.0 * h - 2.0 * h * k;
    io::add_label(d, px, py, tx, ty, fmt::format("{} = {} ({})", c.symbol, mm(c.diameter), c.name), h, "labels");
  }
}

void title_block(io::Drawing& d, const gg::GearPairInput& in, const GearCommandOptions& o, double x, double y_top, double h) {
  io::TextTable t;
  t.title = "gearkit gear";
  t.rows = {{"drawing", o.draw == "pair" ? "gear pair in mesh" : (o.draw == "gear1" ? "gear 1" : "gear 2")},
            {"pair", fmt::format("z1 = {}, z2 = {}{}, m_n = {} mm", in.z1, in.z2, in.internal ? " (ring)" : "", mm(in.module))},
            {"units", "lengths mm, angles deg"},
            {"tooth outline", fmt::format("within {} mm of the generated form", io::fixed(o.tolerance, 4))},
            {"section", in.helix_angle != 0.0 ? "transverse" : "plane of rotation"},
#ifdef GEARKIT_VERSION_STRING
            {"made by", "gearkit " GEARKIT_VERSION_STRING},
#endif
  };
  io::add_table(d, t, x, y_top, h, "title_block", "frame");
}

gg::ShaperCutter checked_cutter(const gg::GearPairInput& in, const gg::GearPairResult& r, const GearCommandOptions& o,
                                gg::RingCutting* cutting) {
  if (!in.internal) return o.cutter;
  gg::ToothFormSpec spec = gg::tooth_form_spec(in, r, 1);
  spec.cutter = o.cutter;
  try {
    const gg::RingCutting c = gg::ring_cutting(spec);
    if (cutting) *cutting = c;
  } catch (const std::invalid_argument& e) {
    // The tip radius is to blame only when the user gave one and it does not fit; everything else
    // is the cutter's size (the message names the z_0 it tried, the user's or the default).
    const std::string what = e.what();
    const bool rounding = o.cutter.rho_a0 >= 0.0 && what.find("does not fit") != std::string::npos;
    io::fail_option(rounding ? "--cutter-tip-radius" : "--cutter-teeth", what);
  }
  return o.cutter;
}

}  // namespace

io::Drawing gear_drawing(const gg::GearPairInput& in, const gg::GearPairResult& r, const GearCommandOptions& o,
                         const gg::InspectionResult* insp) {
  io::Drawing d;
  d.layers = kLayers;
  const gg::ShaperCutter cutter = checked_cutter(in, r, o, nullptr);
  const double size = 0.5 * std::max(r.gear[0].d_a, std::max(r.gear[1].d_a, r.gear[1].d_f));
  const double h = io::text_height_for(o.draw == "pair" ? 2.0 * size + r.pair.a : size * 2.0);
  std::vector<int> which;
  if (o.draw == "pair") {
    auto outlines = gg::pair_outlines(in, r, o.tolerance, cutter);
    d.polylines.push_back(to_polyline(outlines[0], "gear1"));
    d.polylines.push_back(to_polyline(outlines[1], "gear2"));
    const gg::Point2 c2 = gg::second_gear_centre(in, r);
    d.circles.push_back({"working_pitch", 0.0, 0.0, 0.5 * r.gear[0].d_w});
    d.circles.push_back({"working_pitch", c2.x, c2.y, 0.5 * r.gear[1].d_w});
    circles(d, r.gear[0], 0.0, 0.0, in.internal ? 1.0 : -1.0, h);
    circles(d, r.gear[1], c2.x, c2.y, in.internal ? -1.0 : 1.0, h);
    centre_mark(d, 0.0, 0.0, r.gear[0].m_n);
    centre_mark(d, c2.x, c2.y, r.gear[1].m_n);
    which = {0, 1};
  } else {
    const int i = o.draw == "gear1" ? 0 : 1;
    gg::ToothFormSpec spec = gg::tooth_form_spec(in, r, i);
    spec.tolerance = o.tolerance;
    spec.cutter = cutter;
    d.polylines.push_back(to_polyline(gg::gear_outline(spec), i == 0 ? "gear1" : "gear2"));
    circles(d, r.gear[i], 0.0, 0.0, -1.0, h);
    centre_mark(d, 0.0, 0.0, r.gear[i].m_n);
    which = {i};
  }
  const io::Box box = io::drawing_box(d);
  const double x = box.xmax + 4.0 * h;
  const io::Size block = io::add_table(d, gear_data_table(in, r, insp, which), x, box.ymax, h, "data_block", "frame");
  title_block(d, in, o, x, box.ymax - block.height - 2.0 * h, h);
  io::add_frame(d, 2.0 * h, "frame");  // what "fit to page" fits: labels at the edge stay on the page
  return d;
}

void add_ring_cutting_report(io::Report& report, const gg::GearPairInput& in, const gg::GearPairResult& r,
                             const GearCommandOptions& o) {
  if (!in.internal) return;
  gg::RingCutting c;
  checked_cutter(in, r, o, &c);
  io::Table t{"Ring shaper cutter (root fillet of the drawing)", {"quantity", "value"}, {}};
  t.add_row({"cutter teeth z_0", std::to_string(c.z_0)});
  t.add_row({"cutter shift x_0", io::fixed(c.x_0, 4)});
  t.add_row({"cutter tip rounding rho_a0 [mm]", io::fixed(c.rho_a0, 4)});
  t.add_row({"cutter tip diameter d_a0 [mm]", io::fixed(c.d_a0, 4)});
  t.add_row({"generating centre distance a_0 [mm]", io::fixed(c.a_0, 4)});
  t.add_row({"generating pressure angle alpha_w0 [deg]", io::fixed(c.alpha_w0 * kDeg, 4)});
  t.add_row({"involute interference [mm]", io::fixed(c.involute_interference, 4)});
  t.add_row({"tip interference [mm]", io::fixed(c.tip_interference, 4)});
  report.tables.push_back(std::move(t));
  report.json["ring_cutter"] = {{"z_0", c.z_0}, {"x_0", c.x_0}, {"rho_a0_mm", c.rho_a0}, {"d_a0_mm", c.d_a0},
                                {"a_0_mm", c.a_0}, {"alpha_w0_deg", c.alpha_w0 * kDeg},
                                {"involute_interference_mm", c.involute_interference},
                                {"tip_interference_mm", c.tip_interference}};
  if (c.involute_interference > 0.0) {
    report.warnings.push_back(fmt::format("the ring's tips reach {:.4f} mm past the cutter's interference point: the "
                                          "z_0 = {} cutter cuts them back (involute interference)", c.involute_interference, c.z_0));
  }
  if (c.tip_interference > o.tolerance) {
    report.warnings.push_back(fmt::format("the z_0 = {} cutter's tips cut {:.4f} mm into the ring teeth when leaving the "
                                          "mesh (tip interference): use fewer cutter teeth", c.z_0, c.tip_interference));
  }
}

const std::vector<io::Layer>& gear_drawing_layers() { return kLayers; }

io::Polyline outline_polyline(const std::vector<gg::ProfileVertex>& outline, std::string layer) {
  return to_polyline(outline, std::move(layer));
}

void draw_centre_mark(io::Drawing& d, double cx, double cy, double size) { centre_mark(d, cx, cy, size); }

void draw_gear_circles(io::Drawing& d, const gg::GearResult& g, double cx, double cy, double side, double h) {
  circles(d, g, cx, cy, side, h);
}

}  // namespace gearkit::plugins::gear
