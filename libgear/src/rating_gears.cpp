// Per-gear steps of the ISO 6336 rating: pitting (part 2) and tooth root (part 3).
#include "rating_detail.hpp"

#include <gearkit/gear/iso6336_pitting.hpp>
#include <gearkit/gear/iso6336_root.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace gearkit::gear::detail {

namespace iso = iso6336;

namespace {

// Z_W of gear i (ISO 6336-2:2006 clause 12): a through-hardened gear meshing with a
// surface-hardened mate gets harder by running; otherwise 1.
double work_hardening(const RatingInput& in, int i) {
  const Material& self = in.material[i];
  const Material& mate = in.material[1 - i];
  if (surface_hardened(self.kind) || !surface_hardened(mate.kind)) return 1.0;
  return iso::work_hardening_factor(self.HB);
}

double cycles(const RatingInput& in, const PairRating& r, int i) { return r.gear[i].n * 60.0 * in.life_h * in.cycles_per_rev[i]; }

iso::ToothRoot tooth_root_of(const Mesh& m, const RatingInput& in, int i) {
  iso::ToothRootInput t;
  t.z = m.z[i];
  t.m_n = m.m_n;
  t.alpha_n = m.alpha_n;
  t.beta = m.beta;
  t.x_E = m.x[i] + (in.root_shift == RootShift::generating ? m.A_sn[i] / (2.0 * m.m_n * std::tan(m.alpha_n)) : 0.0);
  t.h_fP = m.h_fP[i];
  t.rho_fP = m.rho_fP[i];
  t.s_pr = in.s_pr_gear[i].value_or(in.s_pr);
  t.d = m.d[i];
  t.d_a = m.d_Na[i];
  t.eps_alpha = m.eps_alpha;
  try {
    return (i == 1 && m.internal) ? iso::internal_tooth_root(t) : iso::external_tooth_root(t);
  } catch (const std::domain_error& e) {
    throw RatingError("tooth_root", fmt::format("gear {}: {}", i + 1, e.what()));
  }
}

}  // namespace

void contact_of_gears(const Mesh& m, const RatingInput& in, PairRating& r) {
  const auto& f = in.factors;
  const double M_1 = iso::single_pair_parameter(m.alpha_wt, m.d_Na[0], m.d_b[0], m.z[0], m.d_Na[1], m.d_b[1], m.z[1], m.eps_alpha);
  const double M_2 = iso::single_pair_parameter(m.alpha_wt, m.d_Na[1], m.d_b[1], m.z[1], m.d_Na[0], m.d_b[0], m.z[0], m.eps_alpha);
  const double Z_BD[2] = {imposed_or(f, Factor::Z_B, iso::single_pair_contact_factor(M_1, m.eps_beta)),
                          imposed_or(f, Factor::Z_D, m.internal ? 1.0 : iso::single_pair_contact_factor(M_2, m.eps_beta))};
  const double rho_red = iso::relative_radius_of_curvature(m.d_b[0], m.d_b[1], m.alpha_wt, m.internal);
  const double R_z10 = iso::roughness_Rz10(0.5 * (in.R_z_flank[0] + in.R_z_flank[1]), rho_red);
  for (int i = 0; i < 2; ++i) {
    GearRating& g = r.gear[i];
    const Material& mat = in.material[i];
    g.n = i == 0 ? r.n_1 : r.n_1 / m.u;
    g.N_L = cycles(in, r, i);
    const double C_ZL = iso::lubricant_constant(mat.sigma_Hlim);
    g.Z_B_or_D = Z_BD[i];
    g.Z_L = imposed_or(f, Factor::Z_L, iso::lubricant_factor(C_ZL, in.nu_40));
    g.Z_v = imposed_or(f, Factor::Z_v, iso::velocity_factor(C_ZL, r.v));
    g.Z_R = imposed_or(f, Factor::Z_R, iso::roughness_factor(R_z10, mat.sigma_Hlim));
    g.Z_W = imposed_or(f, per_gear(Factor::Z_W1, i), work_hardening(in, i));
    g.Z_X = imposed_or(f, Factor::Z_X, 1.0);
    const auto line = iso::pitting_life_line(mat.kind, in.limited_pitting, in.optimum_long_life);
    g.Z_NT = imposed_or(f, per_gear(Factor::Z_NT1, i), iso::life_factor(line, g.N_L));
    g.sigma_H = iso::contact_stress(g.Z_B_or_D, r.sigma_H0, r.K_gamma, r.K_A, r.K_v, r.K_Hbeta, r.K_Halpha);
    g.sigma_HG = mat.sigma_Hlim * g.Z_NT * g.Z_L * g.Z_v * g.Z_R * g.Z_W * g.Z_X;
    g.sigma_HP = g.sigma_HG / in.S_Hmin;
    g.S_H = iso::pitting_safety_factor(g.sigma_HG, g.sigma_H);
  }
}

void root_of_gears(const Mesh& m, const RatingInput& in, PairRating& r) {
  const auto& f = in.factors;
  const double Y_beta = imposed_or(f, Factor::Y_beta, iso::helix_angle_factor_F(m.eps_beta, m.beta));
  const double Y_DT = imposed_or(f, Factor::Y_DT, iso::deep_tooth_factor(iso::virtual_contact_ratio(m.eps_alpha, m.beta_b), in.quality));
  for (int i = 0; i < 2; ++i) {
    GearRating& g = r.gear[i];
    const Material& mat = in.material[i];
    const iso::ToothRoot root = tooth_root_of(m, in, i);
    g.s_Fn = root.s_Fn;
    g.rho_F = root.rho_F;
    g.h_Fe = root.h_Fe;
    g.alpha_Fen = root.alpha_Fen;
    g.Y_F = imposed_or(f, per_gear(Factor::Y_F1, i), root.Y_F);
    g.Y_S = imposed_or(f, per_gear(Factor::Y_S1, i), root.Y_S);
    g.Y_beta = Y_beta;
    g.Y_DT = Y_DT;
    const double h_t = 0.5 * std::fabs(m.d_a[i] - m.d_f[i]);
    g.Y_B = imposed_or(f, per_gear(Factor::Y_B1, i), iso::rim_thickness_factor(in.s_R[i], h_t, m.m_n, i == 1 && m.internal));
    const double q_s = root.s_Fn / (2.0 * root.rho_F);
    g.Y_deltarelT = imposed_or(f, per_gear(Factor::Y_deltarelT1, i),
                               iso::relative_notch_sensitivity_factor(iso::slip_layer_thickness(mat), q_s));
    g.Y_RrelT = imposed_or(f, per_gear(Factor::Y_RrelT1, i), iso::relative_surface_factor(mat.kind, in.R_z_root[i]));
    g.Y_X = imposed_or(f, per_gear(Factor::Y_X1, i), iso::size_factor_F(mat.kind, m.m_n));
    g.Y_NT = imposed_or(f, per_gear(Factor::Y_NT1, i), iso::life_factor(iso::root_life_line(mat.kind, in.optimum_long_life), g.N_L));
    g.Y_M = imposed_or(f, per_gear(Factor::Y_M1, i), in.reversed_bending[i] ? 0.7 : 1.0);
    g.sigma_F0 = iso::nominal_root_stress(r.F_t, m.b_F[i], m.m_n, g.Y_F, g.Y_S, g.Y_beta, g.Y_B, g.Y_DT);
    g.sigma_F = iso::root_stress(g.sigma_F0, r.K_gamma, r.K_A, r.K_v, r.K_Fbeta, r.K_Falpha);
    g.sigma_FG = iso::root_stress_limit(mat.sigma_Flim, g.Y_NT, g.Y_deltarelT, g.Y_RrelT, g.Y_X) * g.Y_M;
    g.sigma_FP = g.sigma_FG / in.S_Fmin;
    g.S_F = g.sigma_FG / g.sigma_F;
    if (!(q_s >= 1.0 && q_s < 8.0)) {
      r.warnings.push_back(fmt::format("gear {}: notch parameter q_s = {:.2f} outside 1 <= q_s < 8 of ISO 6336-3 Eq. 44", i + 1, q_s));
    }
  }
}

}  // namespace gearkit::gear::detail
