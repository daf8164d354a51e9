#pragma once
// ISO 6336-2:2019 (surface durability, pitting), method B, one function per formula.
// Stresses in MPa, lengths in mm, angles in rad, speeds in m/s, viscosity in mm^2/s,
// roughness in um.

namespace gearkit::gear::iso6336 {

/// Zone factor Z_H = sqrt(2 cos(beta_b) cos(alpha_wt) / (cos^2(alpha_t) sin(alpha_wt))) (6.1, Eq. 9).
double zone_factor(double beta_b, double alpha_t, double alpha_wt);

/// Elasticity factor Z_E = sqrt(1 / (pi ((1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2))) (7, Eq. 21), sqrt(MPa).
double elasticity_factor(double E_1, double nu_1, double E_2, double nu_2);

/// Contact ratio factor Z_eps (8, Eq. 22-24): spur sqrt((4 - eps_alpha)/3); helical with
/// eps_beta < 1 sqrt((4 - eps_alpha)(1 - eps_beta)/3 + eps_beta/eps_alpha); eps_beta >= 1 sqrt(1/eps_alpha).
double contact_ratio_factor(double eps_alpha, double eps_beta);

/// Helix angle factor Z_beta = 1 / sqrt(cos beta) (9, Eq. 25).
double helix_angle_factor_H(double beta);

/// M_1 of 6.2 (Eq. 11), with the signed ISO 21771 convention for the second gear kept as
/// magnitudes: tan(alpha_wt) / sqrt((sqrt(d_a1^2/d_b1^2 - 1) - 2 pi/z_1)(sqrt(d_a2^2/d_b2^2 - 1)
/// - (eps_alpha - 1) 2 pi / z_2)). M_2 swaps the gears (Eq. 12).
double single_pair_parameter(double alpha_wt, double d_a1, double d_b1, int z_1, double d_a2, double d_b2, int z_2,
                             double eps_alpha);

/// Single pair tooth contact factor Z_B or Z_D from M (6.2, Eq. 13-16): spur max(1, M);
/// eps_beta >= 1: 1; 0 < eps_beta < 1: M - eps_beta (M - 1), at least 1.
double single_pair_contact_factor(double M, double eps_beta);

/// Nominal contact stress at the pitch point sigma_H0 = Z_H Z_E Z_eps Z_beta sqrt(F_t/(d_1 b) (u + 1)/u)
/// (5, Eq. 2). u = z_2/z_1 > 0; `internal` uses (u - 1)/u (u negative in the standard's signs).
double nominal_contact_stress(double Z_H, double Z_E, double Z_eps, double Z_beta, double F_t, double d_1, double b,
                              double u, bool internal);

/// Contact stress sigma_H = Z_BD sigma_H0 sqrt(K_gamma K_A K_v K_Hbeta K_Halpha) (5, Eq. 1).
double contact_stress(double Z_BD, double sigma_H0, double K_gamma, double K_A, double K_v, double K_Hbeta, double K_Halpha);

/// C_ZL of the lubricant factor (11.2, Eq. 28-30): 0.83 below sigma_Hlim = 850 MPa, 0.91 above
/// 1200 MPa, sigma_Hlim/4375 + 0.6357 between.
double lubricant_constant(double sigma_Hlim);

/// Lubricant factor Z_L = C_ZL + 4 (1 - C_ZL) / (1.2 + 134/nu_40)^2 (11.2, Eq. 27).
double lubricant_factor(double C_ZL, double nu_40);

/// Velocity factor Z_v = C_Zv + 2 (1 - C_Zv) / sqrt(0.8 + 32/v), C_Zv = C_ZL + 0.02 (11.3, Eq. 31-32).
double velocity_factor(double C_ZL, double v);

/// Relative radius of curvature at the pitch point rho_red = rho_1 rho_2 / (rho_1 + rho_2),
/// rho_i = 0.5 d_bi tan(alpha_wt) (11.4, Eq. 35-37); `internal` uses rho_2 negative.
double relative_radius_of_curvature(double d_b1, double d_b2, double alpha_wt, bool internal);

/// Mean peak-to-valley roughness of the pair from R_a: R_z = 6 R_a (11.4 note), um.
double roughness_Rz_from_Ra(double R_a);

/// R_z10 = R_z (10 / rho_red)^(1/3), R_z the mean of both flanks (11.4, Eq. 34).
double roughness_Rz10(double R_z, double rho_red);

/// Roughness factor Z_R = (3 / R_z10)^C_ZR, C_ZR = 0.15 (< 850 MPa), 0.08 (> 1200 MPa),
/// 0.32 - 0.0002 sigma_Hlim between (11.4, Eq. 33-34).
double roughness_factor(double R_z10, double sigma_Hlim);

/// Work hardening factor of a through-hardened gear meshing with a surface-hardened one
/// (12, ISO 6336-2:2006 Eq. 40): Z_W = 1.2 - (HB - 130)/1700 for 130 <= HB <= 470, 1.2 below, 1.0 above.
double work_hardening_factor(double HB);

/// Safety factor for pitting S_H = sigma_Hlim Z_NT Z_L Z_v Z_R Z_W Z_X / sigma_H (Eq. 4-5).
double pitting_safety_factor(double sigma_HG, double sigma_H);

}  // namespace gearkit::gear::iso6336
