#include <gearkit/gear/iso6336_pitting.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gearkit::gear::iso6336 {

namespace {
constexpr double kPi = std::numbers::pi;
}

double zone_factor(double beta_b, double alpha_t, double alpha_wt) {
  const double c = std::cos(alpha_t);
  return std::sqrt(2.0 * std::cos(beta_b) * std::cos(alpha_wt) / (c * c * std::sin(alpha_wt)));
}

double elasticity_factor(double E_1, double nu_1, double E_2, double nu_2) {
  return std::sqrt(1.0 / (kPi * ((1.0 - nu_1 * nu_1) / E_1 + (1.0 - nu_2 * nu_2) / E_2)));
}

double contact_ratio_factor(double eps_alpha, double eps_beta) {
  if (eps_beta >= 1.0) return std::sqrt(1.0 / eps_alpha);
  return std::sqrt((4.0 - eps_alpha) * (1.0 - eps_beta) / 3.0 + eps_beta / eps_alpha);
}

double helix_angle_factor_H(double beta) { return 1.0 / std::sqrt(std::cos(beta)); }

double single_pair_parameter(double alpha_wt, double d_a1, double d_b1, int z_1, double d_a2, double d_b2, int z_2,
                             double eps_alpha) {
  const double t1 = std::sqrt(d_a1 * d_a1 / (d_b1 * d_b1) - 1.0) - 2.0 * kPi / z_1;
  const double t2 = std::sqrt(d_a2 * d_a2 / (d_b2 * d_b2) - 1.0) - (eps_alpha - 1.0) * 2.0 * kPi / z_2;
  return std::tan(alpha_wt) / std::sqrt(t1 * t2);
}

double single_pair_contact_factor(double M, double eps_beta) {
  if (eps_beta >= 1.0) return 1.0;
  return std::max(1.0, M - eps_beta * (M - 1.0));
}

double nominal_contact_stress(double Z_H, double Z_E, double Z_eps, double Z_beta, double F_t, double d_1, double b,
                              double u, bool internal) {
  const double ratio = internal ? (u - 1.0) / u : (u + 1.0) / u;
  return Z_H * Z_E * Z_eps * Z_beta * std::sqrt(F_t / (d_1 * b) * ratio);
}

double contact_stress(double Z_BD, double sigma_H0, double K_gamma, double K_A, double K_v, double K_Hbeta, double K_Halpha) {
  return Z_BD * sigma_H0 * std::sqrt(K_gamma * K_A * K_v * K_Hbeta * K_Halpha);
}

double lubricant_constant(double sigma_Hlim) {
  if (sigma_Hlim < 850.0) return 0.83;
  if (sigma_Hlim > 1200.0) return 0.91;
  return sigma_Hlim / 4375.0 + 0.6357;
}

double lubricant_factor(double C_ZL, double nu_40) {
  const double t = 1.2 + 134.0 / nu_40;
  return C_ZL + 4.0 * (1.0 - C_ZL) / (t * t);
}

double velocity_factor(double C_ZL, double v) {
  const double C_Zv = C_ZL + 0.02;
  return C_Zv + 2.0 * (1.0 - C_Zv) / std::sqrt(0.8 + 32.0 / v);
}

double relative_radius_of_curvature(double d_b1, double d_b2, double alpha_wt, bool internal) {
  const double rho_1 = 0.5 * d_b1 * std::tan(alpha_wt);
  const double rho_2 = (internal ? -0.5 : 0.5) * d_b2 * std::tan(alpha_wt);
  return rho_1 * rho_2 / (rho_1 + rho_2);
}

double roughness_Rz_from_Ra(double R_a) { return 6.0 * R_a; }

double roughness_Rz10(double R_z, double rho_red) { return R_z * std::cbrt(10.0 / rho_red); }

double roughness_factor(double R_z10, double sigma_Hlim) {
  double C_ZR = 0.08;
  if (sigma_Hlim < 850.0) C_ZR = 0.15;
  else if (sigma_Hlim <= 1200.0) C_ZR = 0.32 - 0.0002 * sigma_Hlim;
  return std::pow(3.0 / R_z10, C_ZR);
}

double work_hardening_factor(double HB) {
  if (HB < 130.0) return 1.2;
  if (HB > 470.0) return 1.0;
  return 1.2 - (HB - 130.0) / 1700.0;
}

double pitting_safety_factor(double sigma_HG, double sigma_H) { return sigma_HG / sigma_H; }

}  // namespace gearkit::gear::iso6336
