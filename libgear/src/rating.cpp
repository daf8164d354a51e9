// The ISO 6336 chain (parts 1, 2, 3, 6) for a computed gear table, and the common front door
// for the three methods. The formulas live in iso6336_*.cpp; here they are put in order.
#include <gearkit/gear/rating.hpp>

#include "rating_detail.hpp"

#include <gearkit/gear/accuracy.hpp>
#include <gearkit/gear/iso6336_pitting.hpp>
#include <gearkit/gear/iso6336_root.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gearkit::gear {

namespace iso = iso6336;

RatingError::RatingError(std::string field, const std::string& message)
    : std::invalid_argument(message), field_(std::move(field)) {}

const char* to_string(FaceLoadModel model) { return model == FaceLoadModel::sun ? "sun" : "pinion-shaft"; }

const char* to_string(RatingMethod method) {
  switch (method) {
    case RatingMethod::iso6336: return "iso6336";
    case RatingMethod::agma: return "agma";
    case RatingMethod::lewis_hertz: return "lewis-hertz";
  }
  return "iso6336";
}

namespace detail {

Mesh mesh_of(const GearPairInput& in, const GearPairResult& r) {
  Mesh m;
  const GearResult& g1 = r.gear[0];
  const GearResult& g2 = r.gear[1];
  m.z = {g1.z, g2.z};
  m.internal = g2.internal;
  m.m_n = g1.m_n;
  m.alpha_n = g1.alpha_n;
  m.alpha_t = g1.alpha_t;
  m.beta = g1.beta;
  m.beta_b = g1.beta_b;
  m.alpha_wt = r.pair.alpha_wt;
  m.d = {g1.d, g2.d};
  m.d_b = {g1.d_b, g2.d_b};
  m.d_a = {g1.d_a, g2.d_a};
  m.d_Na = m.d_a;
  m.d_f = {g1.d_f, g2.d_f};
  m.d_w = {g1.d_w, g2.d_w};
  m.x = {g1.x, g2.x};
  m.A_sn = {g1.A_sn, g2.A_sn};
  m.z_n = {g1.z_n, g2.z_n};
  m.u = r.pair.u;
  m.b = common_face_width(in);
  m.b_F = {root_face_width(in, 0, g1.m_n), root_face_width(in, 1, g1.m_n)};
  for (int i = 0; i < 2; ++i) {
    const Rack tool = tool_rack(in, i, g1.alpha_n);
    m.h_fP[i] = tool.h_fP;
    m.rho_fP[i] = tool.rho_fP;
  }
  m.eps_alpha = r.pair.eps_alpha;
  m.eps_beta = r.pair.eps_beta;
  m.eps_gamma = r.pair.eps_gamma;
  return m;
}

bool surface_hardened(MaterialClass k) {
  return k == MaterialClass::case_carburized || k == MaterialClass::induction_hardened || k == MaterialClass::nitrided ||
         k == MaterialClass::nitrided_through_hardened || k == MaterialClass::nitrocarburized;
}

bool cast_iron(MaterialClass k) { return k == MaterialClass::grey_cast_iron; }

double imposed_or(const ImposedFactors& f, Factor which, double computed) { return f.has(which) ? f.get(which) : computed; }

Factor per_gear(Factor first, int i) { return static_cast<Factor>(static_cast<int>(first) + i); }

double hours_for_cycles(double N, double n, double cycles_per_rev) {
  if (std::isinf(N)) return N;
  return N / (60.0 * n * cycles_per_rev);
}

}  // namespace detail

namespace {

using detail::Mesh;

// The message is formatted only on failure: validation runs on every rating.
template <class Message>
void require(bool ok, const char* field, Message message) {
  if (!ok) throw RatingError(field, message());
}

void require_deviation(double value, const char* field, const char* what) {
  require(std::isfinite(value) && value >= 0.0, field, [&] {
    return fmt::format("the {} needs {} (um, >= 0): give it or an ISO 1328 accuracy grade, or impose the factor", what, field);
  });
}

// K_v, method B (ISO 6336-1:2019 6.5.9).
void dynamic_factor(const Mesh& m, const RatingInput& in, PairRating& r) {
  const double F_per_b = in.K_A * r.F_t / m.b;
  const double z_n2 = m.internal ? std::numeric_limits<double>::infinity() : m.z_n[1];
  r.c_th = iso::theoretical_single_stiffness(iso::minimum_flank_deformation(m.z_n[0], z_n2, m.x[0], m.x[1]));
  // Two tools: C_B = 0.5 (C_B1 + C_B2), ISO 6336-1's rule for pinion and wheel of different basic racks.
  const double C_B = m.h_fP[0] == m.h_fP[1] ? iso::basic_rack_factor(m.h_fP[0], m.alpha_n)
                                            : 0.5 * (iso::basic_rack_factor(m.h_fP[0], m.alpha_n) + iso::basic_rack_factor(m.h_fP[1], m.alpha_n));
  r.c_prime = iso::single_stiffness(r.c_th, 0.8, 1.0, C_B, m.beta, F_per_b);
  r.c_gamma_alpha = iso::mesh_stiffness_alpha(r.c_prime, m.eps_alpha);
  r.c_gamma_beta = iso::mesh_stiffness_beta(r.c_gamma_alpha);
  const double d_m1 = 0.5 * (m.d_a[0] + m.d_f[0]);
  const double rho2_term = m.internal ? 1e300 : in.material[1].density;  // a ring acts as an infinite mass
  r.m_red = iso::reduced_mass(d_m1, m.d_b[0], 0.0, 0.0, in.material[0].density, rho2_term, m.u);
  r.n_E1 = iso::resonance_speed(m.z[0], r.c_gamma_alpha, r.m_red);
  r.N = r.n_1 / r.n_E1;
  r.N_S = iso::resonance_lower_limit(F_per_b);
  r.range = iso::resonance_range(r.N, r.N_S);
  if (in.factors.has(Factor::K_v)) {
    r.K_v = in.factors.get(Factor::K_v);
    return;
  }
  require_deviation(in.f_pb, "f_pb", "dynamic factor K_v");
  require_deviation(in.f_falpha, "f_falpha", "dynamic factor K_v");
  auto y = [&](double f, int i) {
    const MaterialClass k = in.material[i].kind;
    return iso::running_in_allowance_alpha(f, in.material[i].sigma_Hlim, detail::surface_hardened(k), detail::cast_iron(k), r.v);
  };
  r.y_alpha = 0.5 * (y(in.f_pb, 0) + y(in.f_pb, 1));
  const double y_f = 0.5 * (y(in.f_falpha, 0) + y(in.f_falpha, 1));
  const double C_a = std::isnan(in.C_a) ? iso::mesh_tip_relief_by_running_in(in.material[0].sigma_Hlim, in.material[1].sigma_Hlim)
                                        : in.C_a;
  const auto B = iso::deviation_terms(r.c_prime, in.f_pb - r.y_alpha, in.f_falpha - y_f, C_a, F_per_b);
  r.K_v = iso::dynamic_factor(r.N, r.N_S, iso::dynamic_coefficients(m.eps_gamma), B);
}

// f_sh by Eq. 43/44 (7.6.4) from the face-load input: the pinion on its shaft with K', l, s, d_sh
// and B* of the power split, or the sun of a planetary stage (B* = planets, no bending term).
double shaft_misalignment(const Mesh& m, const FaceLoadInput& f, double F_m_per_b, PairRating& r) {
  if (f.model == FaceLoadModel::sun) {
    r.K_prime = 0.0;
    r.B_star = f.planets;
    return iso::shaft_deflection_misalignment(F_m_per_b, m.b, m.d[0], 0.0, 0.0, 0.0, 0.0, r.B_star);
  }
  r.B_star = iso::power_split_factor(f.torque_percent);
  r.K_prime = 0.0;
  if (!f.has_shaft()) return iso::shaft_deflection_misalignment(F_m_per_b, m.b, m.d[0], 0.0, 0.0, 0.0, 0.0, r.B_star);
  const bool stiffening = f.stiffening.value_or(m.d[0] / f.d_sh >= 1.15);
  r.K_prime = std::isnan(f.K_prime) ? iso::shaft_constant_K_prime(f.arrangement, stiffening) : f.K_prime;
  return iso::shaft_deflection_misalignment(F_m_per_b, m.b, m.d[0], r.K_prime, f.l, f.s, f.d_sh, r.B_star);
}

// K_Hbeta by method C and K_Fbeta (ISO 6336-1:2019 7.6, 7.7).
void face_load_factors(const Mesh& m, const RatingInput& in, PairRating& r) {
  const double F_m_per_b = r.F_t * in.K_A * r.K_gamma * r.K_v / m.b;
  if (in.factors.has(Factor::K_Hbeta)) {
    r.K_Hbeta = in.factors.get(Factor::K_Hbeta);
  } else {
    if (std::isfinite(in.F_betax)) {
      require(in.F_betax >= 0.0, "F_betax", [&] { return fmt::format("expected F_betax >= 0 um, found {}", in.F_betax); });
      r.F_betax = in.F_betax;
    } else {
      require_deviation(in.f_ma, "f_ma", "face load factor K_Hbeta (method C)");
      r.f_sh = std::isfinite(in.f_sh) ? in.f_sh : shaft_misalignment(m, in.face_load, F_m_per_b, r);
      r.F_betax = iso::initial_equivalent_misalignment(r.f_sh, in.f_ma, F_m_per_b, in.f_Hbeta,
                                                      iso::misalignment_constants(in.face_load.modification));
    }
    double y_beta = 0.0;
    for (int i = 0; i < 2; ++i) {
      const MaterialClass k = in.material[i].kind;
      y_beta += 0.5 * iso::running_in_allowance_beta(r.F_betax, in.material[i].sigma_Hlim, detail::surface_hardened(k),
                                                     detail::cast_iron(k), r.v);
    }
    r.F_betay = std::max(0.0, r.F_betax - y_beta);
    r.K_Hbeta = iso::face_load_factor_H(r.c_gamma_beta, r.F_betay, F_m_per_b);
  }
  const double h1 = 0.5 * (m.d_a[0] - m.d_f[0]);
  const double h2 = 0.5 * std::fabs(m.d_a[1] - m.d_f[1]);
  const double N_F = iso::face_load_exponent(std::min(m.b / h1, m.b / h2));
  r.K_Fbeta = detail::imposed_or(in.factors, Factor::K_Fbeta, iso::face_load_factor_F(r.K_Hbeta, N_F));
}

// K_Halpha, K_Falpha (ISO 6336-1:2019 8.3, method B).
void transverse_load_factors(const Mesh& m, const RatingInput& in, PairRating& r) {
  if (in.factors.has(Factor::K_Halpha) && in.factors.has(Factor::K_Falpha)) {
    r.K_Halpha = in.factors.get(Factor::K_Halpha);
    r.K_Falpha = in.factors.get(Factor::K_Falpha);
    return;
  }
  require_deviation(in.f_pb, "f_pb", "transverse load factor K_Halpha");
  if (std::isnan(r.y_alpha)) {
    r.y_alpha = 0.0;
    for (int i = 0; i < 2; ++i) {
      const MaterialClass k = in.material[i].kind;
      r.y_alpha += 0.5 * iso::running_in_allowance_alpha(in.f_pb, in.material[i].sigma_Hlim, detail::surface_hardened(k),
                                                         detail::cast_iron(k), r.v);
    }
  }
  const double F_tH_per_b = r.F_t * r.K_gamma * in.K_A * r.K_v * r.K_Hbeta / m.b;
  const double K = iso::transverse_load_factor(m.eps_gamma, r.c_gamma_alpha, in.f_pb - r.y_alpha, F_tH_per_b);
  r.K_Halpha = detail::imposed_or(in.factors, Factor::K_Halpha, iso::limit_K_Halpha(K, m.eps_gamma, m.eps_alpha, r.Z_epsilon));
  r.K_Falpha = detail::imposed_or(in.factors, Factor::K_Falpha, iso::limit_K_Falpha(K, m.eps_gamma, m.eps_alpha));
}

// Factors of ISO 6336-2 common to both gears.
void pair_contact_factors(const Mesh& m, const RatingInput& in, PairRating& r) {
  const auto& f = in.factors;
  r.Z_H = detail::imposed_or(f, Factor::Z_H, iso::zone_factor(m.beta_b, m.alpha_t, m.alpha_wt));
  r.Z_E = detail::imposed_or(f, Factor::Z_E, iso::elasticity_factor(in.material[0].E, in.material[0].nu, in.material[1].E,
                                                                     in.material[1].nu));
  r.Z_epsilon = detail::imposed_or(f, Factor::Z_epsilon, iso::contact_ratio_factor(m.eps_alpha, m.eps_beta));
  r.Z_beta = detail::imposed_or(f, Factor::Z_beta, iso::helix_angle_factor_H(m.beta));
}

// Deviations not given, from the tolerances of the accuracy grade in its ISO 1328-1 edition
// (accuracy.hpp), the larger of both gears: the mesh sees the worse one.
void deviations_of_quality(const Mesh& m, RatingInput& in) {
  FlankTolerances t[2];
  for (int i = 0; i < 2; ++i) t[i] = flank_tolerances({m.d[i], m.m_n, m.b, m.z[i], m.beta, *in.quality, in.iso1328_edition});
  auto larger = [&](double FlankTolerances::*f) { return std::max(t[0].*f, t[1].*f); };
  if (std::isnan(in.f_pb)) in.f_pb = larger(&FlankTolerances::f_pT) * std::cos(m.alpha_t);
  if (std::isnan(in.f_falpha)) in.f_falpha = larger(&FlankTolerances::f_falphaT);
  if (in.f_Hbeta == 0.0) in.f_Hbeta = larger(&FlankTolerances::f_HbetaT);
  if (std::isnan(in.f_ma)) in.f_ma = larger(&FlankTolerances::f_HbetaT);
}

}  // namespace

namespace {

void validate_face_load(const FaceLoadInput& f) {
  const bool lengths = std::isfinite(f.l) && f.l >= 0.0 && std::isfinite(f.s) && f.s >= 0.0 && std::isfinite(f.d_sh) && f.d_sh >= 0.0;
  require(lengths, "face_load", [&] {
    return fmt::format("expected a bearing span l >= 0 mm, a pinion offset s >= 0 mm and a shaft diameter d_sh >= 0 mm, found {}, {}, {}",
                       f.l, f.s, f.d_sh);
  });
  require(!f.has_shaft() || (f.l > 0.0 && f.d_sh > 0.0), "face_load", [&] {
    return fmt::format("the pinion shaft needs its bearing span l > 0 mm and its diameter d_sh > 0 mm, found {} and {}", f.l, f.d_sh);
  });
  require(std::isnan(f.K_prime) || std::isfinite(f.K_prime), "face_load", [&] { return fmt::format("expected a finite K', found {}", f.K_prime); });
  require(std::isfinite(f.torque_percent) && f.torque_percent > 0.0 && f.torque_percent <= 100.0, "face_load", [&] {
    return fmt::format("expected the percentage k of the pinion torque on this mesh in (0, 100], found {}", f.torque_percent);
  });
  require(f.planets >= 1, "face_load", [&] { return fmt::format("expected at least 1 planet on the sun, found {}", f.planets); });
}

void validate_scuffing(const RatingInput& in) {
  const ScuffingInput& s = in.scuffing;
  if (!s.fzg_stage) return;
  require(*s.fzg_stage >= 1 && *s.fzg_stage <= 14, "fzg_stage", [&] { return fmt::format("expected an FZG load stage 1..14, found {}", *s.fzg_stage); });
  require(std::isfinite(s.theta_oil), "theta_oil", [&] { return std::string("the scuffing rating needs the oil temperature (deg C)"); });
  require(s.theta_oil > -40.0 && s.theta_oil < 200.0, "theta_oil", [&] { return fmt::format("expected an oil temperature in (-40, 200) deg C, found {}", s.theta_oil); });
  require(std::isfinite(s.nu_100), "nu_100", [&] { return std::string("the scuffing rating needs the oil's kinematic viscosity at 100 C (mm^2/s)"); });
  require(s.nu_100 > 0.0 && s.nu_100 < in.nu_40, "nu_100", [&] {
    return fmt::format("expected a viscosity at 100 C > 0 and below the one at 40 C ({} mm^2/s), found {}", in.nu_40, s.nu_100);
  });
  require(std::isfinite(s.rho_15) && s.rho_15 > 0.5 && s.rho_15 < 2.0, "rho_15", [&] { return fmt::format("expected an oil density in (0.5, 2) kg/dm^3, found {}", s.rho_15); });
  require(std::isfinite(s.S_Smin) && s.S_Smin > 0.0, "S_Smin", [&] { return fmt::format("expected S_Smin > 0, found {}", s.S_Smin); });
}

}  // namespace

void validate(const RatingInput& in) {
  validate_face_load(in.face_load);
  require(std::isfinite(in.T_1) && in.T_1 > 0.0, "T_1", [&] { return fmt::format("expected a torque > 0 N m, found {}", in.T_1); });
  require(std::isfinite(in.n_1) && in.n_1 > 0.0, "n_1", [&] { return fmt::format("expected a speed > 0 1/min, found {}", in.n_1); });
  require(std::isfinite(in.K_A) && in.K_A >= 1.0, "K_A", [&] { return fmt::format("expected an application factor >= 1, found {}", in.K_A); });
  require(std::isfinite(in.K_gamma) && in.K_gamma >= 1.0, "K_gamma", [&] { return fmt::format("expected K_gamma >= 1, found {}", in.K_gamma); });
  require(!in.quality || (*in.quality >= min_grade(in.iso1328_edition) && *in.quality <= max_grade(in.iso1328_edition)), "quality", [&] {
    return fmt::format("expected an {} grade {}..{}, found {}", to_string(in.iso1328_edition), min_grade(in.iso1328_edition),
                       max_grade(in.iso1328_edition), *in.quality);
  });
  require(std::isfinite(in.life_h) && in.life_h > 0.0, "life_h", [&] { return fmt::format("expected a life > 0 h, found {}", in.life_h); });
  require(std::isfinite(in.nu_40) && in.nu_40 > 0.0, "nu_40", [&] { return fmt::format("expected a viscosity > 0 mm^2/s, found {}", in.nu_40); });
  validate_scuffing(in);
  require(std::isfinite(in.S_Hmin) && in.S_Hmin > 0.0, "S_Hmin", [&] { return fmt::format("expected S_Hmin > 0, found {}", in.S_Hmin); });
  require(std::isfinite(in.S_Fmin) && in.S_Fmin > 0.0, "S_Fmin", [&] { return fmt::format("expected S_Fmin > 0, found {}", in.S_Fmin); });
  require(in.Q_v == 0 || (in.Q_v >= 3 && in.Q_v <= 16), "Q_v", [&] { return fmt::format("expected an AGMA quality number 3..16, found {}", in.Q_v); });
  require(in.reliability > 0.5 && in.reliability < 1.0, "reliability", [&] { return fmt::format("expected a reliability in (0.5, 1), found {}", in.reliability); });
  for (int i = 0; i < 2; ++i) {
    const char* field = i == 0 ? "material1" : "material2";
    try {
      validate(in.material[i]);
    } catch (const std::invalid_argument& e) {
      throw RatingError(field, e.what());
    }
    require(in.R_z_flank[i] > 0.0 && std::isfinite(in.R_z_flank[i]), "R_z_flank", [&] { return fmt::format("expected a flank roughness > 0 um, found {}", in.R_z_flank[i]); });
    require(in.R_z_root[i] >= 0.0 && std::isfinite(in.R_z_root[i]), "R_z_root", [&] { return fmt::format("expected a root roughness >= 0 um, found {}", in.R_z_root[i]); });
    require(in.s_R[i] >= 0.0 && std::isfinite(in.s_R[i]), "s_R", [&] { return fmt::format("expected a rim thickness >= 0 mm, found {}", in.s_R[i]); });
    require(!in.s_pr_gear[i] || (std::isfinite(*in.s_pr_gear[i]) && *in.s_pr_gear[i] >= 0.0), "s_pr", [&] { return fmt::format("expected a residual protuberance >= 0, found {}", *in.s_pr_gear[i]); });
    require(in.cycles_per_rev[i] > 0.0 && std::isfinite(in.cycles_per_rev[i]), "cycles_per_rev", [&] { return fmt::format("expected load cycles per turn > 0, found {}", in.cycles_per_rev[i]); });
  }
  for (int f = 0; f < kFactorCount; ++f) {
    const double v = in.factors.value[f];
    require(std::isnan(v) || (std::isfinite(v) && v > 0.0), "factor", [&] { return fmt::format("expected an imposed {} > 0, found {}", factor_name(static_cast<Factor>(f)), v); });
  }
  for (std::size_t k = 0; k < in.spectrum.size(); ++k) {
    const auto& bin = in.spectrum[k];
    require(std::isfinite(bin.T_1) && bin.T_1 > 0.0 && std::isfinite(bin.n_1) && bin.n_1 > 0.0 && std::isfinite(bin.hours) &&
                bin.hours > 0.0,
            "spectrum", [&] { return fmt::format("row {}: expected torque > 0, speed > 0 and hours > 0, found {} N m, {} 1/min, {} h", k + 1,
                                    bin.T_1, bin.n_1, bin.hours); });
  }
}

namespace detail {

// The ISO 6336 rating at one operating point, without life evaluation.
PairRating operating_point(RatingMethod method, const Mesh& m, const RatingInput& in, double T_1, double n_1) {
  PairRating r;
  r.method = method;
  r.T_1 = T_1;
  r.n_1 = n_1;
  r.K_A = in.K_A;
  r.K_gamma = in.K_gamma;
  r.eps_alpha = m.eps_alpha;
  r.eps_beta = m.eps_beta;
  r.eps_gamma = m.eps_gamma;
  r.F_t = iso::nominal_tangential_load(T_1, m.d[0]);
  r.v = iso::pitch_line_speed(m.d[0], n_1);
  return r;
}

PairRating iso_operating_point(const Mesh& m, const RatingInput& in, double T_1, double n_1) {
  PairRating r = operating_point(RatingMethod::iso6336, m, in, T_1, n_1);
  pair_contact_factors(m, in, r);
  dynamic_factor(m, in, r);
  face_load_factors(m, in, r);
  transverse_load_factors(m, in, r);
  r.sigma_H0 = iso::nominal_contact_stress(r.Z_H, r.Z_E, r.Z_epsilon, r.Z_beta, r.F_t, m.d[0], m.b, m.u, m.internal);
  contact_of_gears(m, in, r);
  root_of_gears(m, in, r);
  return r;
}

}  // namespace detail

namespace {

// T_2 -> T_1 and N_L1 -> life_h, the alternative ways of giving the load and the life.
RatingInput with_load_of_gear1(const GearPairResult& geometry, RatingInput in) {
  if (in.T_2 != 0.0) {
    require(in.T_1 == 0.0, "T_2", [&] { return fmt::format("give the torque on gear 1 or on gear 2, not both (found {} and {} N m)", in.T_1, in.T_2); });
    require(std::isfinite(in.T_2) && in.T_2 > 0.0, "T_2", [&] { return fmt::format("expected a torque > 0 N m, found {}", in.T_2); });
    in.T_1 = in.T_2 * geometry.gear[0].z / geometry.gear[1].z;
  }
  if (!std::isnan(in.N_L1)) {
    require(std::isfinite(in.N_L1) && in.N_L1 > 0.0, "N_L1", [&] { return fmt::format("expected load cycles > 0, found {}", in.N_L1); });
    require(in.spectrum.empty(), "N_L1", [&] { return std::string("a load spectrum gives its life in hours: give the life in hours"); });
    if (std::isfinite(in.n_1) && in.n_1 > 0.0 && in.cycles_per_rev[0] > 0.0) in.life_h = detail::hours_for_cycles(in.N_L1, in.n_1, in.cycles_per_rev[0]);
  }
  return in;
}

// The usable tip diameters d_Na (given, or d_a less a chamfer) replace d_a in the rating, and
// the transverse contact ratio follows them (ISO 6336-1: eps_alpha from d_Na).
void usable_tips(const GearPairResult& geometry, const RatingInput& in, Mesh& m) {
  bool changed = false;
  for (int i = 0; i < 2; ++i) {
    const char* field = i == 0 ? "d_Na1" : "d_Na2";
    require(!(in.d_Na[i] && in.h_K[i]), field, [&] { return fmt::format("gear {}: give the usable tip diameter or the tip chamfer, not both", i + 1); });
    const bool ring = i == 1 && m.internal;
    double d_Na = m.d_a[i];
    if (in.h_K[i]) {
      require(std::isfinite(*in.h_K[i]) && *in.h_K[i] >= 0.0, i == 0 ? "h_K1" : "h_K2", [&] { return fmt::format("expected a tip chamfer >= 0 mm, found {}", *in.h_K[i]); });
      d_Na = m.d_a[i] + (ring ? 2.0 : -2.0) * *in.h_K[i];
    } else if (in.d_Na[i]) {
      d_Na = *in.d_Na[i];
    } else {
      continue;
    }
    const bool inside = ring ? d_Na >= m.d_a[i] - 1e-9 : d_Na <= m.d_a[i] + 1e-9;
    require(std::isfinite(d_Na) && d_Na > m.d_b[i] && inside, in.h_K[i] ? (i == 0 ? "h_K1" : "h_K2") : field, [&] {
      return fmt::format("gear {}: expected a usable tip diameter between the base circle {:.4f} mm and the tip circle {:.4f} mm, found {:.4f} mm",
                         i + 1, m.d_b[i], m.d_a[i], d_Na);
    });
    m.d_Na[i] = d_Na;
    changed = true;
  }
  if (!changed) return;
  const double s = m.internal ? -1.0 : 1.0;
  auto roll = [](double d_a, double d_b) { return 0.5 * std::sqrt(d_a * d_a - d_b * d_b); };
  m.eps_alpha = transverse_contact_ratio_from_lengths(roll(m.d_Na[0], m.d_b[0]), s * roll(m.d_Na[1], m.d_b[1]), s * geometry.pair.a,
                                                      m.alpha_wt, geometry.gear[0].p_bt);
  m.eps_gamma = m.eps_alpha + m.eps_beta;
}

}  // namespace

PairRating rate_gear_pair(const GearPairInput& geometry_input, const GearPairResult& geometry, const RatingInput& given) {
  const RatingInput in = with_load_of_gear1(geometry, given);
  validate(in);
  require(common_face_width(geometry_input) > 0.0, "face_width", [&] { return "the rating needs a common face width b > 0 mm"; });
  Mesh m = detail::mesh_of(geometry_input, geometry);
  for (int i = 0; i < 2; ++i) {
    if (in.A_sne[i]) {
      require(std::isfinite(*in.A_sne[i]), "A_sne", [&] { return fmt::format("expected a finite allowance, found {}", *in.A_sne[i]); });
      m.A_sn[i] = *in.A_sne[i];
    }
  }
  usable_tips(geometry, in, m);
  PairRating r;
  if (in.method == RatingMethod::iso6336 && in.quality) {
    RatingInput with_tolerances = in;
    deviations_of_quality(m, with_tolerances);
    r = detail::rate_iso6336(m, with_tolerances);
  } else {
    switch (in.method) {
      case RatingMethod::iso6336: r = detail::rate_iso6336(m, in); break;
      case RatingMethod::agma: r = detail::rate_agma(m, in); break;
      case RatingMethod::lewis_hertz: r = detail::rate_lewis_hertz(m, in); break;
    }
  }
  detail::scuffing_of_mesh(m, in, r);
  r.imposed = in.factors;
  const FaceLoadInput& f = in.face_load;
  if (in.method == RatingMethod::iso6336 && f.model == FaceLoadModel::pinion_shaft && f.has_shaft() && std::isnan(f.K_prime) &&
      f.s / f.l > iso::shaft_offset_limit(f.arrangement)) {
    r.warnings.push_back(fmt::format("pinion offset s/l = {:.3f} beyond {} of ISO 6336-1 Figure 13 (arrangement {}): K' there is an extrapolation",
                                     f.s / f.l, iso::shaft_offset_limit(f.arrangement), iso::to_string(f.arrangement)));
  }
  detail::safety_warnings(in, r);
  return r;
}

}  // namespace gearkit::gear
