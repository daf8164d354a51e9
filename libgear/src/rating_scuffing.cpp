// Scuffing of the mesh by the integral temperature method (ISO/TS 6336-21, formerly ISO/TR
// 13989-2): the formulas of iso6336_scuffing.hpp put in order with the load factors of the
// ISO 6336 rating (K_Bbeta = K_Hbeta, K_Balpha = K_Halpha) and the oil of RatingInput::scuffing.
#include "rating_detail.hpp"

#include <gearkit/gear/iso6336_load.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace gearkit::gear::detail {

namespace iso = iso6336;

namespace {

// The standard's pinion (index 1): the smaller external gear; the pinion of an internal pair
// (the ring is gear 2). Internal pairs carry the standard's signs: u < 0, a < 0.
struct PinionFrame {
  int p = 0, w = 1;
  double sign = 1, u = 1, a = 0;
};

PinionFrame frame_of(const Mesh& m) {
  PinionFrame f;
  f.p = (!m.internal && m.z[0] > m.z[1]) ? 1 : 0;
  f.w = 1 - f.p;
  f.sign = m.internal ? -1.0 : 1.0;
  f.u = f.sign * static_cast<double>(m.z[f.w]) / m.z[f.p];
  f.a = f.sign * 0.5 * (m.d_w[f.w] + f.sign * m.d_w[f.p]);
  return f;
}

// Friction and the flash temperature at the pinion tip (Eq. 1-13, 19, 22-38).
void flash_temperature(const Mesh& m, const RatingInput& in, const PairRating& r, const PinionFrame& f, ScuffingRating& s) {
  const ScuffingInput& oil = in.scuffing;
  s.K_Bgamma = iso::helical_load_factor_B(m.eps_gamma);
  s.w_Bt = iso::transverse_unit_load_B(r.F_t, r.K_A, r.K_gamma, r.K_v, r.K_Hbeta, r.K_Halpha, m.b);
  s.v_SigmaC = iso::pitch_point_velocity_sum(r.v, m.alpha_wt, m.alpha_t);
  s.rho_redC = iso::pitch_relative_radius(f.u, f.a, m.alpha_wt, m.beta_b);
  const double R_a = (in.R_z_flank[0] + in.R_z_flank[1]) / 12.0;  // R_z = 6 R_a (docs/rating.md)
  s.X_R = iso::roughness_factor_X_R(R_a, s.rho_redC);
  s.X_L = iso::lubricant_factor_X_L(oil.oil);
  s.nu_oil = iso::kinematic_viscosity_at(in.nu_40, oil.nu_100, oil.theta_oil);
  s.eta_oil = iso::dynamic_viscosity(s.nu_oil, iso::oil_density_at(oil.rho_15, oil.theta_oil));
  s.mu_mC = iso::mean_friction_coefficient(s.w_Bt, s.K_Bgamma, s.v_SigmaC, s.rho_redC, s.eta_oil, s.X_R, s.X_L);
  s.X_E = iso::running_in_factor_X_E(1.0, R_a, s.rho_redC);  // well run in
  const double B_M = iso::thermal_contact_coefficient(iso::kSteelLambda_M, iso::kSteelC_v);
  const Material& m1 = in.material[0];
  const Material& m2 = in.material[1];
  s.X_M = iso::thermo_elastic_factor_X_M(iso::reduced_modulus(m1.E, m1.nu, m2.E, m2.nu), B_M);
  s.X_alphabeta = iso::pressure_angle_factor_X_alphabeta(m.alpha_wt, m.alpha_n, m.alpha_t, m.beta);
  const double rho_E1 = iso::pinion_tip_radius_rho_E1(m.d_Na[f.p], m.d_b[f.p]);
  s.X_BE = iso::geometry_factor_X_BE(f.u, rho_E1, iso::wheel_radius_at_pinion_tip_rho_E2(f.a, m.alpha_wt, rho_E1));
  const bool pinion_drives = (f.p == 0) == oil.gear1_driving;
  s.X_Q = pinion_drives ? iso::approach_factor_X_Q(s.eps_2, s.eps_1) : iso::approach_factor_X_Q(s.eps_1, s.eps_2);
  s.C_a = std::isnan(in.C_a) ? iso::mesh_tip_relief_by_running_in(m1.sigma_Hlim, m2.sigma_Hlim) : in.C_a;
  s.C_eff = iso::effective_tip_relief(r.K_A, r.F_t, m.b, m.beta == 0.0 ? r.c_prime : r.c_gamma_alpha);
  s.X_Ca = iso::tip_relief_factor_X_Ca(s.C_a, s.C_eff, std::max(s.eps_1, s.eps_2));
  s.theta_flaE = iso::flash_temperature_at_pinion_tip(s.mu_mC, s.X_M, s.X_BE, s.X_alphabeta, s.K_Bgamma, s.w_Bt, r.v, f.a, s.X_E,
                                                      s.X_Q, s.X_Ca);
}

// The scuffing integral temperature of the oil from its FZG load stage (Eq. 94-97, 102).
void scuffing_temperature(const RatingInput& in, ScuffingRating& s) {
  const double X_W = std::min(iso::welding_factor_X_W(in.material[0].kind), iso::welding_factor_X_W(in.material[1].kind));
  s.X_WrelT = imposed_or(in.factors, Factor::X_WrelT, X_W);
  s.T_1T = iso::fzg_test_torque(*in.scuffing.fzg_stage);
  s.theta_MT = iso::test_bulk_temperature(s.T_1T, s.X_L);
  s.theta_flaintT = iso::test_mean_flash_temperature(s.T_1T, in.nu_40, s.X_L);
  s.theta_intS = iso::scuffing_integral_temperature(s.theta_MT, s.theta_flaintT, s.X_WrelT);
}

}  // namespace

void scuffing_of_mesh(const Mesh& m, const RatingInput& in, PairRating& r) {
  const ScuffingInput& oil = in.scuffing;
  if (!oil.fzg_stage) return;
  if (in.method != RatingMethod::iso6336) {
    r.warnings.push_back("scuffing is rated by ISO/TS 6336-21 with the ISO 6336 method only (--method iso6336)");
    return;
  }
  const PinionFrame f = frame_of(m);
  ScuffingRating s;
  s.pinion = f.p;
  s.eps_1 = iso::addendum_contact_ratio(m.z[f.p], m.d_Na[f.p], m.d_b[f.p], m.alpha_wt);
  s.eps_2 = iso::addendum_contact_ratio(static_cast<int>(f.sign) * m.z[f.w], m.d_Na[f.w], m.d_b[f.w], m.alpha_wt);
  if (!(s.eps_1 > 0.0 && s.eps_2 >= 0.0 && s.eps_1 + s.eps_2 < 3.0)) {
    r.warnings.push_back(fmt::format("scuffing not rated: ISO/TS 6336-21 covers addendum contact ratios eps_1 > 0, eps_2 >= 0 with "
                                     "eps_alpha < 3, found eps_1 = {:.3f}, eps_2 = {:.3f}", s.eps_1, s.eps_2));
    return;
  }
  flash_temperature(m, in, r, f, s);
  s.X_eps = iso::contact_ratio_factor_X_eps(s.eps_1, s.eps_2);
  s.theta_flaint = iso::mean_flash_temperature(s.theta_flaE, s.X_eps);
  s.X_S = iso::lubrication_factor_X_S(oil.lubrication);
  s.theta_M = iso::bulk_temperature_int(oil.theta_oil, s.theta_flaint, s.X_S);
  s.theta_int = iso::integral_temperature(s.theta_M, s.theta_flaint);
  scuffing_temperature(in, s);
  s.S_intS = iso::scuffing_safety_integral(s.theta_intS, s.theta_int);
  s.S_SL = iso::scuffing_load_safety(s.theta_intS, s.theta_int, oil.theta_oil);
  if (s.S_intS < oil.S_Smin) {
    r.warnings.push_back(fmt::format("scuffing safety S_intS = {:.3f} below S_Smin = {:.2f} (integral temperature {:.1f} C, "
                                     "scuffing integral temperature {:.1f} C)", s.S_intS, oil.S_Smin, s.theta_int, s.theta_intS));
  }
  if (r.v > 50.0) {
    r.warnings.push_back(fmt::format("scuffing: v = {:.1f} m/s above 50 m/s; the friction coefficient is evaluated at 50 m/s (ISO/TS 6336-21 5.1)", r.v));
  }
  r.scuffing = s;
}

}  // namespace gearkit::gear::detail
