#include "gear_tolerance_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;

namespace {

std::string mm(double v) { return std::isfinite(v) ? io::fixed(v, 4) : std::string("-"); }
std::string um(double v) { return std::isfinite(v) ? fmt::format("{:g}", v) : std::string("-"); }
nlohmann::json jnum(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

using Row = std::vector<std::string>;

// One row of both gears: f(gear inspection) as text.
template <class F>
Row both(std::string name, const gg::InspectionResult& r, F f) {
  return {std::move(name), f(r.gear[0]), f(r.gear[1])};
}

template <class F>
std::string tol(const gg::GearInspection& g, F f) {
  return g.tolerances ? um(f(*g.tolerances)) : std::string("-");
}

io::Table tolerance_table(const gg::InspectionResult& r) {
  io::Table t{"Accuracy (flank tolerances, um)", {"quantity", "gear 1", "gear 2"}, {}};
  auto add = [&](std::string name, double gg::FlankTolerances::*m) {
    t.add_row(both(std::move(name), r, [m](const gg::GearInspection& g) { return tol(g, [m](const auto& ft) { return ft.*m; }); }));
  };
  t.add_row(both("accuracy grade", r, [](const gg::GearInspection& g) {
    return g.tolerances ? fmt::format("{} ({})", g.tolerances->grade, gg::to_string(g.tolerances->edition)) : std::string("-");
  }));
  add("single pitch f_pT", &gg::FlankTolerances::f_pT);
  add("total cumulative pitch F_pT", &gg::FlankTolerances::F_pT);
  add("profile slope f_HalphaT (+-)", &gg::FlankTolerances::f_HalphaT);
  add("profile form f_falphaT", &gg::FlankTolerances::f_falphaT);
  add("total profile F_alphaT", &gg::FlankTolerances::F_alphaT);
  add("helix slope f_HbetaT (+-)", &gg::FlankTolerances::f_HbetaT);
  add("helix form f_fbetaT", &gg::FlankTolerances::f_fbetaT);
  add("total helix F_betaT", &gg::FlankTolerances::F_betaT);
  add("runout F_rT", &gg::FlankTolerances::F_rT);
  add("radial composite total F_id'' (ISO 1328-2:1997)", &gg::FlankTolerances::F_idT);
  add("radial composite tooth-to-tooth f_id''", &gg::FlankTolerances::f_idT);
  return t;
}

io::Table thickness_table(const gg::InspectionResult& r) {
  io::Table t{"Tooth thickness and inspection", {"quantity", "gear 1", "gear 2"}, {}};
  using G = const gg::GearInspection&;
  t.add_row(both("thickness allowances from", r, [](G g) {
    return g.din3967.empty() ? std::string(gg::to_string(g.source)) : fmt::format("DIN 3967 {}", g.din3967);
  }));
  t.add_row(both("upper allowance A_sne [mm]", r, [](G g) { return mm(g.allowances.A_sne); }));
  t.add_row(both("lower allowance A_sni [mm]", r, [](G g) { return mm(g.allowances.A_sni); }));
  t.add_row(both("thickness tolerance T_sn [mm]", r, [](G g) { return mm(g.T_sn); }));
  t.add_row(both("radial infeed tolerance b_r [um]", r, [](G g) { return um(g.b_r); }));
  t.add_row(both("teeth spanned k", r, [](G g) { return g.k > 0 ? std::to_string(g.k) : std::string("-"); }));
  t.add_row(both("span W_k max [mm]", r, [](G g) { return mm(g.W_k_max); }));
  t.add_row(both("span W_k min [mm]", r, [](G g) { return mm(g.W_k_min); }));
  t.add_row(both("anvil contact diameter d_W [mm]", r, [](G g) {
    return g.k > 0 ? fmt::format("{}..{}", io::fixed(g.d_W_min, 3), io::fixed(g.d_W_max, 3)) : std::string("-");
  }));
  if (r.gear[0].b_min_span > 0.0 || r.gear[1].b_min_span > 0.0) {
    t.add_row(both("face width needed W_k sin beta_b [mm]", r, [](G g) { return mm(g.b_min_span); }));
  }
  t.add_row(both("pin (ball) diameter D_M [mm]", r, [](G g) { return mm(g.D_M); }));
  t.add_row(both("usable pin diameters [mm]", r, [](G g) {
    return std::isfinite(g.D_M_min) ? fmt::format("{}..{}", io::fixed(g.D_M_min, 3), io::fixed(g.D_M_max, 3)) : std::string("-");
  }));
  t.add_row(both("M_d max [mm]", r, [](G g) { return mm(g.M_d_max); }));
  t.add_row(both("M_d min [mm]", r, [](G g) { return mm(g.M_d_min); }));
  return t;
}

io::Table backlash_table(const gg::PairInspection& p) {
  io::Table t{"Backlash", {"quantity", "value"}, {}};
  t.add_row({"centre distance allowances", p.centre_distance_field});
  t.add_row({"upper centre distance allowance A_ae [mm]", mm(p.A_ae)});
  t.add_row({"lower centre distance allowance A_ai [mm]", mm(p.A_ai)});
  if (std::isfinite(p.j_bn_min_target)) t.add_row({"required minimum normal backlash [mm]", mm(p.j_bn_min_target)});
  t.add_row({"circumferential backlash j_t min..max [mm]", fmt::format("{}..{}", mm(p.range.min.j_t), mm(p.range.max.j_t))});
  t.add_row({"normal backlash j_n min..max [mm]", fmt::format("{}..{}", mm(p.range.min.j_n), mm(p.range.max.j_n))});
  if (p.operating) {
    t.add_row({"operating j_t min..max [mm]", fmt::format("{}..{}", mm(p.operating->min.j_t), mm(p.operating->max.j_t))});
    t.add_row({"operating j_n min..max [mm]", fmt::format("{}..{}", mm(p.operating->min.j_n), mm(p.operating->max.j_n))});
  }
  return t;
}

nlohmann::json tolerances_json(const gg::FlankTolerances& t) {
  return {{"edition", gg::to_string(t.edition)},
          {"grade", t.grade},
          {"f_pT_um", t.f_pT},
          {"F_pT_um", t.F_pT},
          {"f_HalphaT_um", t.f_HalphaT},
          {"f_falphaT_um", t.f_falphaT},
          {"F_alphaT_um", t.F_alphaT},
          {"f_HbetaT_um", jnum(t.f_HbetaT)},
          {"f_fbetaT_um", jnum(t.f_fbetaT)},
          {"F_betaT_um", jnum(t.F_betaT)},
          {"F_rT_um", t.F_rT},
          {"F_id_um", jnum(t.F_idT)},
          {"f_id_um", jnum(t.f_idT)},
          {"radial_composite_standard", "ISO 1328-2:1997"},
          {"outside_scope", t.outside_scope}};
}

void gear_json(nlohmann::json& j, const gg::GearInspection& g) {
  j["tolerances"] = g.tolerances ? tolerances_json(*g.tolerances) : nlohmann::json(nullptr);
  j["thickness_allowances_from"] = gg::to_string(g.source);
  j["din3967"] = g.din3967.empty() ? nlohmann::json(nullptr) : nlohmann::json(g.din3967);
  j["A_sne_mm"] = g.allowances.A_sne;
  j["A_sni_mm"] = g.allowances.A_sni;
  j["T_sn_mm"] = g.T_sn;
  j["b_r_um"] = jnum(g.b_r);
  j["acceptance_band"] = g.acceptance_band;
  j["W_k_max_mm"] = jnum(g.W_k_max);
  j["W_k_min_mm"] = jnum(g.W_k_min);
  j["d_W_max_mm"] = jnum(g.d_W_max);
  j["d_W_min_mm"] = jnum(g.d_W_min);
  j["face_width_for_span_mm"] = jnum(g.b_min_span);
  j["M_d_max_mm"] = jnum(g.M_d_max);
  j["M_d_min_mm"] = jnum(g.M_d_min);
  j["pin_diameter_min_mm"] = jnum(g.D_M_min);
  j["pin_diameter_max_mm"] = jnum(g.D_M_max);
}

nlohmann::json backlash_json(const gg::BacklashRange& r) {
  return {{"j_n_min_mm", r.min.j_n}, {"j_n_max_mm", r.max.j_n}, {"j_t_min_mm", r.min.j_t}, {"j_t_max_mm", r.max.j_t}};
}

void pair_json(nlohmann::json& j, const gg::PairInspection& p) {
  nlohmann::json b = backlash_json(p.range);
  b["j_n_min_required_mm"] = jnum(p.j_bn_min_target);
  b["operating"] = p.operating ? backlash_json(*p.operating) : nlohmann::json(nullptr);
  j["backlash"] = b;
  j["centre_distance_allowances"] = {{"field", p.centre_distance_field}, {"A_ae_mm", p.A_ae}, {"A_ai_mm", p.A_ai}};
}

void notes(io::Report& report, const gg::InspectionResult& r) {
  report.notes.push_back(
      "Flank tolerances by ISO 1328-1 (2013: formulas of 5.3 rounded by 5.2.3; 1995: tabulated ranges); radial "
      "composite tolerances by ISO 1328-2:1997 (grades 4..12, m_n 0.2..10 mm, d 5..1000 mm), runout 2013: 0.9 F_pT.");
  if (r.gear[0].source == gg::AllowanceSource::iso_tr_10064_2 || r.gear[1].source == gg::AllowanceSource::iso_tr_10064_2) {
    report.notes.push_back(
        "ISO/TR 10064-2 allowances: upper allowances leave the minimum backlash at the least favourable centre distance "
        "(and operating temperatures); T_sn = 2 tan(alpha_n) sqrt(F_r^2 + b_r^2), b_r the radial infeed tolerance.");
  }
  report.notes.push_back("W_k and M_d limits are for measuring on the teeth: the DIN 3967 runout term 0.72 F_r tan(alpha_n) "
                         "is taken off the thickness allowances when a grade is given; backlash without tooth deviations.");
}

}  // namespace

void add_inspection_report(io::Report& report, const gg::InspectionResult& r) {
  report.tables.push_back(tolerance_table(r));
  report.tables.push_back(thickness_table(r));
  report.tables.push_back(backlash_table(r.pair));
  notes(report, r);
  report.warnings.insert(report.warnings.end(), r.warnings.begin(), r.warnings.end());
  for (int i = 0; i < 2; ++i) gear_json(report.json["gears"][i], r.gear[i]);
  pair_json(report.json["pair"], r.pair);
}

}  // namespace gearkit::plugins::gear
