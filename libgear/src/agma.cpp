#include <gearkit/gear/agma.hpp>

#include "rating_detail.hpp"

#include <gearkit/gear/iso6336_pitting.hpp>
#include <gearkit/gear/iso6336_root.hpp>
#include <gearkit/gear/lewis_hertz.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gearkit::gear::agma {

namespace {
constexpr double kInch = 25.4;
}

double dynamic_factor(int Q_v, double V) { return dynamic_factor_ft_min(Q_v, V / 0.00508); }

double dynamic_factor_ft_min(int Q_v, double V_ft_min) {
  const double B = 0.25 * std::pow(12.0 - Q_v, 2.0 / 3.0);
  const double A = 50.0 + 56.0 * (1.0 - B);
  return std::pow((A + std::sqrt(V_ft_min)) / A, B);
}

double size_factor(double m, double b, double Y) { return std::max(1.0, 0.8433 * std::pow(m * b * std::sqrt(Y), 0.0535)); }

double load_distribution_factor(double b, double d_1, AgmaMounting mounting, bool crowned, bool straddle_centred,
                                bool adjusted) {
  const double F = b / kInch, d = d_1 / kInch;
  const double ratio = std::max(0.05, F / (10.0 * d));
  const double C_pf = F <= 1.0 ? ratio - 0.025 : ratio - 0.0375 + 0.0125 * F;  // Eq. 14-32
  const double C_pm = straddle_centred ? 1.0 : 1.1;                             // Eq. 14-33
  struct Abc {
    double A, B, C;
  };
  constexpr Abc table[] = {{0.247, 0.0167, -0.765e-4}, {0.127, 0.0158, -0.930e-4}, {0.0675, 0.0128, -0.926e-4},
                           {0.00360, 0.0102, -0.822e-4}};  // Table 14-9
  const Abc& k = table[static_cast<int>(mounting)];
  const double C_ma = k.A + k.B * F + k.C * F * F;  // Eq. 14-34
  const double C_mc = crowned ? 0.8 : 1.0;          // Eq. 14-31
  const double C_e = adjusted ? 0.8 : 1.0;          // Eq. 14-35
  return 1.0 + C_mc * (C_pf * C_pm + C_ma * C_e);
}

double surface_geometry_factor(double phi_t, double m_G, double m_N, bool internal) {
  return std::cos(phi_t) * std::sin(phi_t) / (2.0 * m_N) * m_G / (internal ? m_G - 1.0 : m_G + 1.0);
}

double load_sharing_ratio(double p_N, double Z) { return p_N / (0.95 * Z); }

double bending_stress(double W_t, double K_o, double K_v, double K_s, double K_m, double K_B, double b, double m_t, double J) {
  return W_t * K_o * K_v * K_s * K_m * K_B / (b * m_t * J);
}

double contact_stress(double Z_E, double W_t, double K_o, double K_v, double K_s, double K_m, double C_f, double d_w1, double b,
                      double I) {
  return Z_E * std::sqrt(W_t * K_o * K_v * K_s * K_m * C_f / (d_w1 * b * I));
}

double bending_strength_through_hardened(double HB, int grade) { return grade >= 2 ? 0.703 * HB + 113.0 : 0.533 * HB + 88.3; }

double contact_strength_through_hardened(double HB, int grade) { return grade >= 2 ? 2.41 * HB + 237.0 : 2.22 * HB + 200.0; }

double bending_cycle_factor(double N) { return N >= 3e6 ? 1.3558 * std::pow(N, -0.0178) : 2.3194 * std::pow(N, -0.0538); }

double contact_cycle_factor(double N) { return N >= 1e7 ? 1.4488 * std::pow(N, -0.023) : 2.466 * std::pow(N, -0.056); }

double reliability_factor(double R) {
  struct P {
    double R, K;
  };
  constexpr P table[] = {{0.5, 0.70}, {0.9, 0.85}, {0.99, 1.00}, {0.999, 1.25}, {0.9999, 1.50}};
  for (const auto& p : table) {
    if (std::fabs(R - p.R) < 1e-12) return p.K;
  }
  return R < 0.99 ? 0.658 - 0.0759 * std::log(1.0 - R) : 0.50 - 0.109 * std::log(1.0 - R);
}

double hardness_ratio_factor(double HB_P, double HB_G, double m_G) {
  const double ratio = HB_P / HB_G;
  const double A = ratio < 1.2 ? 0.0 : ratio > 1.7 ? 0.00698 : 8.98e-3 * ratio - 8.29e-3;
  return 1.0 + A * (m_G - 1.0);
}

}  // namespace gearkit::gear::agma

namespace gearkit::gear::detail {

namespace {

bool brinell_class(MaterialClass k) {
  return k == MaterialClass::normalized_steel || k == MaterialClass::cast_steel || k == MaterialClass::through_hardened_carbon ||
         k == MaterialClass::through_hardened_alloy;
}

// S_t, S_c of the material: Shigley Fig. 14-2/14-5 for through-hardened steel (grade 2 for ME),
// Tables 14-3/14-6 for carburized steel (grade 1: 380 / 1240 MPa, grade 2: 450 / 1550 MPa); the
// ISO 6336-5 limits otherwise (sigma_Flim, sigma_Hlim: same load cycles and reliability basis).
std::pair<double, double> agma_strengths(const Material& mat) {
  const int grade = mat.grade == QualityGrade::ME ? 2 : 1;
  if (brinell_class(mat.kind) && mat.HB > 0) {
    return {agma::bending_strength_through_hardened(mat.HB, grade), agma::contact_strength_through_hardened(mat.HB, grade)};
  }
  if (mat.kind == MaterialClass::case_carburized) return grade == 2 ? std::pair{450.0, 1550.0} : std::pair{380.0, 1240.0};
  return {mat.sigma_Flim, mat.sigma_Hlim};
}

double agma_J_from_iso(const Mesh& m, const RatingInput& in, int i) {
  PairRating p;
  p.F_t = 1.0;
  RatingInput probe = in;
  probe.factors = ImposedFactors();
  probe.factors.set(Factor::K_v, 1.0);
  // The ISO 6336-3 tooth form at the outer point of single contact, as an AGMA J: sigma equal
  // for the same load gives J = m_n / (m_t Y_F Y_S Y_beta).
  root_of_gears(m, probe, p);
  const GearRating& g = p.gear[i];
  return m.m_n / (m.m_n / std::cos(m.beta) * g.Y_F * g.Y_S * g.Y_beta);
}

}  // namespace

PairRating rate_agma(const Mesh& m, const RatingInput& in) {
  PairRating r = operating_point(RatingMethod::agma, m, in, in.T_1, in.n_1);
  const auto& f = in.factors;
  const int Q_v = in.Q_v > 0 ? in.Q_v : in.quality ? 17 - *in.quality : 0;
  if (Q_v == 0 && !f.has(Factor::K_v)) {
    throw RatingError("Q_v", "the AGMA dynamic factor needs the quality number Q_v (or the ISO grade, or an imposed K_v)");
  }
  r.K_v = imposed_or(f, Factor::K_v, agma::dynamic_factor(std::min(12, Q_v), r.v));
  r.K_Hbeta = r.K_Fbeta = imposed_or(f, Factor::K_m, agma::load_distribution_factor(m.b, m.d[0], in.agma_mounting, in.agma_crowned));
  const double m_t = m.m_n / std::cos(m.beta);
  const double m_N = m.beta == 0.0 ? 1.0
                                   : agma::load_sharing_ratio(std::numbers::pi * m.m_n * std::cos(m.alpha_n),
                                                              m.eps_alpha * std::numbers::pi * m_t * std::cos(m.alpha_t));
  const double I = imposed_or(f, Factor::I, agma::surface_geometry_factor(m.alpha_wt, m.u, m_N, m.internal));
  r.Z_E = imposed_or(f, Factor::Z_E, iso6336::elasticity_factor(in.material[0].E, in.material[0].nu, in.material[1].E, in.material[1].nu));
  const double K_R = imposed_or(f, Factor::K_R, agma::reliability_factor(in.reliability));
  const double C_f = imposed_or(f, Factor::C_f, 1.0);
  r.extra = {{"Q_v", Q_v}, {"K_m", r.K_Hbeta}, {"I", I}, {"K_R", K_R}, {"C_f", C_f}, {"m_N", m_N}};
  for (int i = 0; i < 2; ++i) {
    GearRating& g = r.gear[i];
    const Material& mat = in.material[i];
    g.n = i == 0 ? in.n_1 : in.n_1 / m.u;
    g.N_L = g.n * 60.0 * in.life_h * in.cycles_per_rev[i];
    const double Y = imposed_or(f, per_gear(Factor::Y1, i), lewis::form_factor(m.z_n[i]));
    const double K_s = imposed_or(f, per_gear(Factor::K_s1, i), agma::size_factor(m_t, m.b, Y));
    const double K_B = imposed_or(f, per_gear(Factor::K_B1, i), 1.0);
    const double J = imposed_or(f, per_gear(Factor::J1, i), agma_J_from_iso(m, in, i));
    const double Y_N = imposed_or(f, per_gear(Factor::Y_N1, i), agma::bending_cycle_factor(g.N_L));
    const double Z_N = imposed_or(f, per_gear(Factor::Z_N1, i), agma::contact_cycle_factor(g.N_L));
    const double C_H = i == 0 ? 1.0 : imposed_or(f, Factor::C_H, agma::hardness_ratio_factor(in.material[0].HB, mat.HB, m.u));
    const auto [S_t, S_c] = agma_strengths(mat);
    g.sigma_F = agma::bending_stress(r.F_t * r.K_gamma, in.K_A, r.K_v, K_s, r.K_Fbeta, K_B, m.b, m_t, J);
    g.sigma_H = agma::contact_stress(r.Z_E, r.F_t * r.K_gamma, in.K_A, r.K_v, K_s, r.K_Hbeta, C_f, m.d_w[0], m.b, I);
    g.sigma_FG = S_t * Y_N / K_R;
    g.sigma_HG = S_c * Z_N * C_H / K_R;
    g.sigma_FP = g.sigma_FG / in.S_Fmin;
    g.sigma_HP = g.sigma_HG / in.S_Hmin;
    g.S_F = g.sigma_FG / g.sigma_F;
    g.S_H = g.sigma_HG / g.sigma_H;
    g.Z_NT = Z_N;
    g.Y_NT = Y_N;
    g.extra = {{"Y", Y}, {"K_s", K_s}, {"K_B", K_B}, {"J", J}, {"Y_N", Y_N}, {"Z_N", Z_N}, {"C_H", C_H}, {"S_t_MPa", S_t}, {"S_c_MPa", S_c}};
  }
  return r;
}

}  // namespace gearkit::gear::detail
