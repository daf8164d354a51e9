#include "gear_rating_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <optional>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

std::string num(double v, int digits = 4, const char* infinite = "unlimited") {
  if (std::isinf(v)) return infinite;
  return std::isfinite(v) ? io::fixed(v, digits) : std::string("-");
}

std::string factor_cell(const gg::PairRating& r, gg::Factor f, double v) {
  return r.imposed.has(f) ? num(v) + " (imposed)" : num(v);
}

const char* method_title(gg::RatingMethod m) {
  switch (m) {
    case gg::RatingMethod::iso6336: return "ISO 6336:2019, method B (K_Hbeta method C)";
    case gg::RatingMethod::agma: return "AGMA 2101-D (Shigley chapter 14)";
    case gg::RatingMethod::lewis_hertz: return "Lewis bending and Hertz contact";
  }
  return "";
}

// The face-load inputs are shown only when they differ from the plain pinion on a centred shaft,
// so that ratings without them read as before.
bool face_load_given(const gg::RatingInput& in) {
  const gg::FaceLoadInput& f = in.face_load;
  return in.method == gg::RatingMethod::iso6336 &&
         (f.model != gg::FaceLoadModel::pinion_shaft || f.has_shaft() || f.torque_percent != 100.0 ||
          f.modification != gg::iso6336::HelixModification::none);
}

void face_load_rows(io::Table& t, const gg::RatingInput& in, const gg::PairRating& r) {
  if (!face_load_given(in)) return;
  auto row = [&t](std::string name, std::string v) { t.add_row({std::move(name), std::move(v)}); };
  const gg::FaceLoadInput& f = in.face_load;
  std::string model = gg::to_string(f.model);
  if (f.model == gg::FaceLoadModel::sun) model += fmt::format(" ({} planets)", f.planets);
  if (f.model == gg::FaceLoadModel::pinion_shaft && f.has_shaft()) {
    model += fmt::format(" (arrangement {}, l = {:g} mm, s = {:g} mm, d_sh = {:g} mm)", gg::iso6336::to_string(f.arrangement), f.l, f.s, f.d_sh);
  }
  row("face load model", model);
  row("helix modification (B_1, B_2)", fmt::format("{} ({:g}, {:g})", gg::iso6336::to_string(f.modification),
                                                   gg::iso6336::misalignment_constants(f.modification).B_1,
                                                   gg::iso6336::misalignment_constants(f.modification).B_2));
  if (std::isfinite(r.K_prime)) row("shaft constant K'", num(r.K_prime));
  if (std::isfinite(r.B_star)) row("torsion constant B*", num(r.B_star));
  if (std::isfinite(r.f_sh)) row("shaft misalignment f_sh [um]", num(r.f_sh, 3));
}

void pair_rows(io::Table& t, const gg::PairRating& r) {
  auto row = [&t](std::string name, std::string v) { t.add_row({std::move(name), std::move(v)}); };
  const bool iso = r.method == gg::RatingMethod::iso6336;
  row("pinion torque T_1 [N m]", num(r.T_1, 2));
  row("pinion speed n_1 [1/min]", num(r.n_1, 2));
  row("nominal tangential load F_t [N]", num(r.F_t, 1));
  row("pitch-line speed v [m/s]", num(r.v));
  row("application factor K_A", num(r.K_A));
  if (iso) row("mesh load factor K_gamma", num(r.K_gamma));
  row("dynamic factor K_v", factor_cell(r, gg::Factor::K_v, r.K_v));
  if (iso) {
    row("single stiffness c' [N/(mm um)]", num(r.c_prime));
    row("mesh stiffness c_gamma_alpha [N/(mm um)]", num(r.c_gamma_alpha));
    row("resonance speed n_E1 [1/min]", num(r.n_E1, 0));
    row(fmt::format("resonance ratio N ({})", gg::iso6336::to_string(r.range)), num(r.N));
    if (std::isfinite(r.F_betax)) row("initial misalignment F_betax [um]", num(r.F_betax, 2));
    if (std::isfinite(r.F_betay)) row("effective misalignment F_betay [um]", num(r.F_betay, 2));
  }
  row(iso ? "face load factor K_Hbeta" : "load distribution factor K_m", factor_cell(r, gg::Factor::K_Hbeta, r.K_Hbeta));
  if (iso) {
    row("face load factor K_Fbeta", factor_cell(r, gg::Factor::K_Fbeta, r.K_Fbeta));
    row("transverse load factor K_Halpha", factor_cell(r, gg::Factor::K_Halpha, r.K_Halpha));
    row("transverse load factor K_Falpha", factor_cell(r, gg::Factor::K_Falpha, r.K_Falpha));
    row("zone factor Z_H", factor_cell(r, gg::Factor::Z_H, r.Z_H));
  }
  row(iso ? "elasticity factor Z_E [sqrt(MPa)]" : "elastic coefficient C_p [sqrt(MPa)]", factor_cell(r, gg::Factor::Z_E, r.Z_E));
  if (iso) {
    row("contact ratio factor Z_epsilon", factor_cell(r, gg::Factor::Z_epsilon, r.Z_epsilon));
    row("helix angle factor Z_beta", factor_cell(r, gg::Factor::Z_beta, r.Z_beta));
    row("nominal contact stress sigma_H0 [MPa]", num(r.sigma_H0, 1));
    if (std::isfinite(r.T_eq)) row("equivalent torque of the spectrum T_eq [N m]", num(r.T_eq, 1));
  }
  for (const auto& [name, v] : r.extra) row(name, num(v));
}

void gear_rows(io::Table& t, const gg::PairRating& r) {
  const auto& a = r.gear[0];
  const auto& b = r.gear[1];
  auto both = [&](std::string name, double gg::GearRating::*f, int digits = 4, const char* infinite = "unlimited") {
    if (std::isnan(a.*f) && std::isnan(b.*f)) return;
    t.add_row({std::move(name), num(a.*f, digits, infinite), num(b.*f, digits, infinite)});
  };
  const bool iso = r.method == gg::RatingMethod::iso6336;
  both("speed relative to the carrier n [1/min]", &gg::GearRating::n, 2);
  both("load cycles N_L", &gg::GearRating::N_L, 0);
  if (iso) {
    both("single pair factor Z_B / Z_D", &gg::GearRating::Z_B_or_D);
    for (auto [name, f] : {std::pair{"life factor Z_NT", &gg::GearRating::Z_NT}, {"lubricant factor Z_L", &gg::GearRating::Z_L},
                           {"velocity factor Z_v", &gg::GearRating::Z_v}, {"roughness factor Z_R", &gg::GearRating::Z_R},
                           {"work hardening factor Z_W", &gg::GearRating::Z_W}}) {
      both(name, f);
    }
  }
  both("contact stress sigma_H [MPa]", &gg::GearRating::sigma_H, 1);
  both("permissible contact stress sigma_HP [MPa]", &gg::GearRating::sigma_HP, 1);
  both("pitting safety S_H", &gg::GearRating::S_H, 3);
  if (iso) {
    for (auto [name, f] : {std::pair{"root chord s_Fn [mm]", &gg::GearRating::s_Fn}, {"root radius rho_F [mm]", &gg::GearRating::rho_F},
                           {"bending arm h_Fe [mm]", &gg::GearRating::h_Fe}, {"form factor Y_F", &gg::GearRating::Y_F},
                           {"stress correction factor Y_S", &gg::GearRating::Y_S}, {"helix angle factor Y_beta", &gg::GearRating::Y_beta},
                           {"rim factor Y_B", &gg::GearRating::Y_B}, {"notch sensitivity Y_deltarelT", &gg::GearRating::Y_deltarelT},
                           {"surface factor Y_RrelT", &gg::GearRating::Y_RrelT}, {"size factor Y_X", &gg::GearRating::Y_X},
                           {"life factor Y_NT", &gg::GearRating::Y_NT}, {"mean stress factor Y_M", &gg::GearRating::Y_M}}) {
      both(name, f);
    }
    t.add_row({"load direction alpha_Fen [deg]", num(a.alpha_Fen * kDeg), num(b.alpha_Fen * kDeg)});
    both("nominal root stress sigma_F0 [MPa]", &gg::GearRating::sigma_F0, 1);
  }
  both("root stress sigma_F [MPa]", &gg::GearRating::sigma_F, 1);
  both("permissible root stress sigma_FP [MPa]", &gg::GearRating::sigma_FP, 1);
  both("bending safety S_F", &gg::GearRating::S_F, 3);
  if (iso) {
    both("pitting life at S_Hmin [h]", &gg::GearRating::life_H_h, 0);
    both("bending life at S_Fmin [h]", &gg::GearRating::life_F_h, 0);
    both("pitting damage sum", &gg::GearRating::damage_H, 4, "above static limit");
    both("bending damage sum", &gg::GearRating::damage_F, 4, "above static limit");
  }
  for (std::size_t k = 0; k < a.extra.size() && k < b.extra.size(); ++k) {
    t.add_row({a.extra[k].first, num(a.extra[k].second), num(b.extra[k].second)});
  }
}

// NaN is left out (a factor the method does not use); infinity is a named "unlimited".
void put(nlohmann::json& j, const std::string& key, double v) {
  if (std::isfinite(v)) j[key] = v;
}

nlohmann::json gear_rating_json(const gg::GearRating& g) {
  nlohmann::json j = nlohmann::json::object();
  const std::pair<const char*, double> values[] = {
      {"n_rpm", g.n}, {"N_L", g.N_L}, {"Z_B_or_D", g.Z_B_or_D}, {"sigma_H_MPa", g.sigma_H}, {"sigma_HP_MPa", g.sigma_HP},
      {"S_H", g.S_H}, {"Z_NT", g.Z_NT}, {"Z_L", g.Z_L}, {"Z_v", g.Z_v}, {"Z_R", g.Z_R}, {"Z_W", g.Z_W}, {"Z_X", g.Z_X},
      {"s_Fn_mm", g.s_Fn}, {"rho_F_mm", g.rho_F}, {"h_Fe_mm", g.h_Fe}, {"alpha_Fen_deg", g.alpha_Fen * kDeg},
      {"Y_F", g.Y_F}, {"Y_S", g.Y_S}, {"Y_beta", g.Y_beta}, {"Y_B", g.Y_B}, {"Y_DT", g.Y_DT}, {"Y_deltarelT", g.Y_deltarelT},
      {"Y_RrelT", g.Y_RrelT}, {"Y_X", g.Y_X}, {"Y_M", g.Y_M}, {"Y_NT", g.Y_NT}, {"sigma_F0_MPa", g.sigma_F0},
      {"sigma_F_MPa", g.sigma_F}, {"sigma_FP_MPa", g.sigma_FP}, {"S_F", g.S_F}, {"damage_H", g.damage_H}, {"damage_F", g.damage_F}};
  for (const auto& [k, v] : values) put(j, k, v);
  const double life = std::min(g.life_H_h, g.life_F_h);
  j["life_unlimited"] = std::isinf(life);
  j["life_h"] = std::isfinite(life) ? nlohmann::json(life) : nlohmann::json(nullptr);
  put(j, "life_H_h", g.life_H_h);
  put(j, "life_F_h", g.life_F_h);
  const double damage = std::max(g.damage_H, g.damage_F);
  j["static_limit_exceeded"] = std::isinf(damage);
  j["damage"] = std::isfinite(damage) ? nlohmann::json(damage) : nlohmann::json(nullptr);
  for (const auto& [k, v] : g.extra) put(j, k, v);
  return j;
}

// The integral temperature rating of the mesh (ISO/TS 6336-21), docs/rating.md "Scuffing".
void scuffing_rows(io::Table& t, const gg::RatingInput& in, const gg::ScuffingRating& s) {
  namespace iso = gg::iso6336;
  const gg::ScuffingInput& oil = in.scuffing;
  auto row = [&t](std::string name, std::string v) { t.add_row({std::move(name), std::move(v)}); };
  row("oil", fmt::format("{}, nu_40 = {:g}, nu_100 = {:g} mm^2/s, rho_15 = {:g} kg/dm^3, FZG A/8.3/90 stage {}", iso::to_string(oil.oil),
                         in.nu_40, oil.nu_100, oil.rho_15, *oil.fzg_stage));
  row("oil temperature theta_oil [C]", num(oil.theta_oil, 1));
  row(fmt::format("lubrication ({}) X_S", iso::to_string(oil.lubrication)), num(s.X_S, 2));
  row("pinion of the standard (index 1)", fmt::format("gear {}", s.pinion + 1));
  row("addendum contact ratios eps_1 / eps_2", num(s.eps_1) + " / " + num(s.eps_2));
  row("helical load factor K_Bgamma", num(s.K_Bgamma));
  row("transverse unit load w_Bt [N/mm]", num(s.w_Bt, 2));
  row("relative radius at the pitch point rho_redC [mm]", num(s.rho_redC, 3));
  row("oil viscosity at theta_oil nu [mm^2/s] / eta [mPa s]", num(s.nu_oil, 2) + " / " + num(s.eta_oil, 2));
  for (auto [name, v] : {std::pair{"roughness factor X_R", s.X_R}, {"lubricant factor X_L", s.X_L}, {"mean friction coefficient mu_mC", s.mu_mC},
                         {"running-in factor X_E", s.X_E}, {"thermo-elastic factor X_M", s.X_M}, {"pressure angle factor X_alphabeta", s.X_alphabeta},
                         {"geometry factor X_BE", s.X_BE}, {"approach factor X_Q", s.X_Q}}) {
    row(name, num(v));
  }
  row("tip relief C_a / effective C_eff [um]", num(s.C_a, 2) + " / " + num(s.C_eff, 2));
  row("tip relief factor X_Ca", num(s.X_Ca));
  row("contact ratio factor X_eps", num(s.X_eps));
  row("flash temperature at the pinion tip theta_flaE [K]", num(s.theta_flaE, 2));
  row("mean flash temperature theta_flaint [K]", num(s.theta_flaint, 2));
  row("bulk temperature theta_M [C]", num(s.theta_M, 2));
  row("integral temperature theta_int [C]", num(s.theta_int, 2));
  row("FZG test torque T_1T [N m]", num(s.T_1T, 1));
  row("relative welding factor X_WrelT", num(s.X_WrelT));
  row("scuffing integral temperature theta_intS [C]", num(s.theta_intS, 2));
  row("scuffing safety S_intS", num(s.S_intS, 3));
  row("safety on the transmitted load S_SL", num(s.S_SL, 3));
}

nlohmann::json scuffing_json(const gg::RatingInput& in, const gg::ScuffingRating& s) {
  const gg::ScuffingInput& oil = in.scuffing;
  nlohmann::json j = {{"method", "ISO/TS 6336-21 integral temperature"}, {"fzg_stage", *oil.fzg_stage},
                      {"oil_type", gg::iso6336::to_string(oil.oil)}, {"lubrication", gg::iso6336::to_string(oil.lubrication)},
                      {"pinion_gear", s.pinion + 1}};
  const std::pair<const char*, double> values[] = {
      {"theta_oil_C", oil.theta_oil}, {"nu_40_mm2_s", in.nu_40}, {"nu_100_mm2_s", oil.nu_100}, {"rho_15_kg_dm3", oil.rho_15},
      {"eps_1", s.eps_1}, {"eps_2", s.eps_2}, {"K_Bgamma", s.K_Bgamma}, {"w_Bt_N_mm", s.w_Bt}, {"v_SigmaC_m_s", s.v_SigmaC},
      {"rho_redC_mm", s.rho_redC}, {"nu_oil_mm2_s", s.nu_oil}, {"eta_oil_mPa_s", s.eta_oil}, {"X_R", s.X_R}, {"X_L", s.X_L},
      {"mu_mC", s.mu_mC}, {"X_E", s.X_E}, {"X_M", s.X_M}, {"X_alphabeta", s.X_alphabeta}, {"X_BE", s.X_BE}, {"X_Q", s.X_Q},
      {"C_a_um", s.C_a}, {"C_eff_um", s.C_eff}, {"X_Ca", s.X_Ca}, {"X_eps", s.X_eps}, {"X_S", s.X_S}, {"X_WrelT", s.X_WrelT},
      {"theta_flaE_K", s.theta_flaE}, {"theta_flaint_K", s.theta_flaint}, {"theta_M_C", s.theta_M}, {"theta_int_C", s.theta_int},
      {"T_1T_Nm", s.T_1T}, {"theta_MT_C", s.theta_MT}, {"theta_flaintT_K", s.theta_flaintT}, {"theta_intS_C", s.theta_intS},
      {"S_intS", s.S_intS}, {"S_SL", s.S_SL}, {"S_Smin", oil.S_Smin}};
  for (const auto& [k, v] : values) put(j, k, v);
  return j;
}

}  // namespace

nlohmann::json rating_json(const gg::RatingInput& in, const gg::PairRating& r) {
  nlohmann::json factors = {{"K_A", r.K_A}, {"K_gamma", r.K_gamma}, {"K_v", r.K_v}, {"K_Hbeta", r.K_Hbeta},
                            {"K_Halpha", r.K_Halpha}, {"K_Fbeta", r.K_Fbeta}, {"K_Falpha", r.K_Falpha}};
  nlohmann::json imposed = nlohmann::json::array();
  for (int f = 0; f < gg::kFactorCount; ++f) {
    if (r.imposed.has(static_cast<gg::Factor>(f))) imposed.push_back(std::string(gg::factor_name(static_cast<gg::Factor>(f))));
  }
  factors["imposed"] = imposed;
  nlohmann::json j = {{"method", gg::to_string(r.method)}, {"T_1_Nm", r.T_1}, {"n_1_rpm", r.n_1}, {"F_t_N", r.F_t},
                      {"v_m_s", r.v}, {"factors", factors}, {"Z_H", r.Z_H}, {"Z_E", r.Z_E}, {"Z_epsilon", r.Z_epsilon},
                      {"Z_beta", r.Z_beta}, {"sigma_H0_MPa", r.sigma_H0}, {"S_Hmin", in.S_Hmin}, {"S_Fmin", in.S_Fmin},
                      {"materials", {in.material[0].name, in.material[1].name}},
                      {"iso1328_grade", in.quality ? nlohmann::json(*in.quality) : nlohmann::json(nullptr)},
                      {"iso1328_edition", gg::to_string(in.iso1328_edition)}};
  for (const auto& [k, v] : std::initializer_list<std::pair<const char*, double>>{
           {"c_th", r.c_th}, {"c_prime", r.c_prime}, {"c_gamma_alpha", r.c_gamma_alpha}, {"c_gamma_beta", r.c_gamma_beta},
           {"n_E1_rpm", r.n_E1}, {"N", r.N}, {"F_betax_um", r.F_betax}, {"F_betay_um", r.F_betay}, {"T_eq_Nm", r.T_eq}}) {
    put(j, k, v);
  }
  if (r.method == gg::RatingMethod::iso6336) j["resonance_range"] = gg::iso6336::to_string(r.range);
  if (face_load_given(in)) {
    j["face_load"] = {{"model", gg::to_string(in.face_load.model)},
                      {"helix_modification", gg::iso6336::to_string(in.face_load.modification)}};
    for (const auto& [k, v] : std::initializer_list<std::pair<const char*, double>>{{"K_prime", r.K_prime}, {"B_star", r.B_star}, {"f_sh_um", r.f_sh}}) {
      put(j["face_load"], k, v);
    }
  }
  for (const auto& [k, v] : r.extra) put(j, k, v);
  j["gears"] = {gear_rating_json(r.gear[0]), gear_rating_json(r.gear[1])};
  // Not rated (no oil FZG stage given): no key rather than null, which would read as a failed number.
  if (r.method == gg::RatingMethod::iso6336 && r.scuffing) j["scuffing"] = scuffing_json(in, *r.scuffing);
  return j;
}

void add_rating_report(io::Report& report, const gg::RatingInput& in, const gg::PairRating& r) {
  io::Table pair{fmt::format("Load capacity: {}", method_title(r.method)), {"quantity", "value"}, {}};
  pair_rows(pair, r);
  face_load_rows(pair, in, r);
  io::Table gears{"Load capacity of the gears", {"quantity", "gear 1", "gear 2"}, {}};
  gear_rows(gears, r);
  report.tables.push_back(std::move(pair));
  report.tables.push_back(std::move(gears));
  if (r.scuffing) {
    io::Table scuffing{"Scuffing: ISO/TS 6336-21, integral temperature", {"quantity", "value"}, {}};
    scuffing_rows(scuffing, in, *r.scuffing);
    report.tables.push_back(std::move(scuffing));
  }
  report.notes.push_back(fmt::format("Materials: gear 1 {} (sigma_Hlim {:g} MPa, sigma_Flim {:g} MPa), gear 2 {} ({:g}, {:g} MPa); "
                                     "required S_Hmin = {:g}, S_Fmin = {:g}.",
                                     in.material[0].name, in.material[0].sigma_Hlim, in.material[0].sigma_Flim,
                                     in.material[1].name, in.material[1].sigma_Hlim, in.material[1].sigma_Flim, in.S_Hmin, in.S_Fmin));
  if (r.method == gg::RatingMethod::iso6336) {
    report.notes.push_back(in.quality ? fmt::format("Accuracy: {} grade {} (deviations not given from its tolerances).",
                                                    gg::to_string(in.iso1328_edition), *in.quality)
                                      : std::string("Accuracy: no ISO 1328 grade given (deviations as given; deep tooth factor Y_DT = 1)."));
  }
  if (r.method == gg::RatingMethod::iso6336 && in.root_shift == gg::RootShift::generating && (in.A_sne[0] || in.A_sne[1])) {
    auto mm = [](const std::optional<double>& A) { return A ? fmt::format("{:.4f}", *A) : std::string("table"); };
    report.notes.push_back(fmt::format("Tooth root (Y_F, Y_S): generating shift x_E = x + A_sne/(2 m_n tan alpha_n) from the upper "
                                       "tooth thickness allowances A_sne = {} / {} mm of the inspection.", mm(in.A_sne[0]), mm(in.A_sne[1])));
  }
  if (r.method == gg::RatingMethod::iso6336 && !r.scuffing) {
    report.notes.push_back("Scuffing (ISO/TS 6336-21): not rated; it needs the oil's FZG load stage, its viscosity at 100 C and the oil "
                           "temperature (docs/rating.md, \"Scuffing\").");
  }
  for (const auto& w : r.warnings) report.warnings.push_back(w);
  report.json["rating"] = rating_json(in, r);
  if (in.A_sne[0] || in.A_sne[1]) {
    for (int i = 0; i < 2; ++i) report.json["rating"]["gears"][static_cast<std::size_t>(i)]["A_sne_mm"] = in.A_sne[i] ? nlohmann::json(*in.A_sne[i]) : nlohmann::json(nullptr);
  }
  if (in.T_2 > 0.0) report.json["rating"]["T_2_Nm"] = in.T_2;
}

}  // namespace gearkit::plugins::gear
