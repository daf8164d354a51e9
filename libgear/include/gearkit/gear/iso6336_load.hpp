#pragma once
// ISO 6336-1:2019 (basic principles and general influence factors), one function per formula.
// Units as in the standard: forces N, lengths mm, deviations and stiffness in um and
// N/(mm um), speeds m/s and 1/min, masses kg/mm. The clause of each formula is cited; where
// the 2006 edition is followed instead it says so.
#include <string>

namespace gearkit::gear::iso6336 {

// ---- Nominal load (clause 5.2) ----

/// Nominal tangential load at the reference circle F_t = 2000 T_1 / d_1 (N; T_1 in N m, d_1 in mm).
double nominal_tangential_load(double T_1, double d_1);

/// Pitch-line speed v = pi d_1 n_1 / 60000 (m/s; d_1 in mm, n_1 in 1/min).
double pitch_line_speed(double d_1, double n_1);

// ---- Mesh stiffness (clause 9, method B) ----

/// Flank deformation of a solid steel pair q' = C_1 + C_2/z_n1 + ... + C_9 x_2^2 (clause 9.3.2,
/// Table 9), in mm um/N. For an internal pair pass z_n2 = infinity (9.3.2: "z_n2 = inf").
double minimum_flank_deformation(double z_n1, double z_n2, double x_1, double x_2);

/// Theoretical single stiffness c'_th = 1 / q' (9.3.2), N/(mm um).
double theoretical_single_stiffness(double q_prime);

/// Basic rack factor C_B = (1 + 0.5 (1.2 - h_fP/m_n)) (1 - 0.02 (20 deg - alpha_Pn)) (9.3.5),
/// h_fP_star = h_fP/m_n, alpha_Pn in rad. For two different racks use the mean of both.
double basic_rack_factor(double h_fP_star, double alpha_Pn);

/// Gear blank factor C_R = 1 + ln(b_s/b) / (5 exp(s_R / (5 m_n))) for 0.2 <= b_s/b < 1
/// (web-type blanks, 9.3.4); 1 for solid blanks (b_s/b >= 1).
double gear_blank_factor(double b_s_over_b, double s_R, double m_n);

/// Single stiffness c' = c'_th C_M C_R C_B cos(beta) for F_t K_A / b >= 100 N/mm, else
/// multiplied by (F_t K_A / b / 100)^0.25 (9.3.1, Eq. 54-55). C_M = 0.8 (9.3.3).
double single_stiffness(double c_th, double C_M, double C_R, double C_B, double beta, double F_t_K_A_per_b);

/// Mesh stiffness c_gamma_alpha = c' (0.75 eps_alpha + 0.25) (9.4, Eq. 61) for K_v and K_Halpha.
double mesh_stiffness_alpha(double c_prime, double eps_alpha);

/// c_gamma_beta = 0.85 c_gamma_alpha (9.4, Eq. 62) for K_Hbeta.
double mesh_stiffness_beta(double c_gamma_alpha);

// ---- Dynamic factor K_v, method B (clause 6.5) ----

/// Reduced mass of an external pair per unit face width (6.5.9, Eq. 30), kg/mm:
/// m_red = (pi/8) (d_m1/d_b1)^2 d_m1^2 / (1/(rho_1 (1 - q_1^4)) + 1/(rho_2 (1 - q_2^4) u^2)),
/// d_m the mean of tip and root diameters, q = bore diameter / d_m, rho in kg/mm^3.
double reduced_mass(double d_m1, double d_b1, double q_1, double q_2, double rho_1, double rho_2, double u);

/// Resonance speed of the pinion n_E1 = 30000/(pi z_1) sqrt(c_gamma_alpha / m_red) (Eq. 6), 1/min.
double resonance_speed(int z_1, double c_gamma_alpha, double m_red);

/// Lower limit of the main resonance range N_S = 0.85 when F_t K_A / b >= 100 N/mm, else
/// 0.5 + 0.35 sqrt(F_t K_A / (100 b)) (6.5.4, Eq. 12).
double resonance_lower_limit(double F_t_K_A_per_b);

enum class ResonanceRange { subcritical, main_resonance, intermediate, supercritical };
const char* to_string(ResonanceRange range);

/// Range of the resonance ratio N = n_1 / n_E1 (6.5.4): N <= N_S sub-critical, N_S < N <= 1.15
/// main resonance, 1.15 < N < 1.5 intermediate, N >= 1.5 super-critical.
ResonanceRange resonance_range(double N, double N_S);

/// Running-in allowance y of a pitch or profile deviation f, um, for one gear's material (8.3.7,
/// used by 6.5.9 for y_p and y_f): St, V, GGG (perlitic, bainitic), GTS: y = 160 f / sigma_Hlim,
/// at most 12800/sigma_Hlim for 5 < v <= 10 m/s and 6400/sigma_Hlim above 10 m/s (no limit up to
/// 5 m/s); Eh, IF, NT, NV (`surface_hardened`): y = 0.075 f, at most 3 um; GG, GGG ferritic
/// (`cast_iron`): y = 0.275 f, at most 22 um for 5 < v <= 10 m/s and 11 um above. f and y in um,
/// sigma_Hlim in MPa, v in m/s. For a pair of different materials the mean of both gears' y is used.
double running_in_allowance_alpha(double f, double sigma_Hlim, bool surface_hardened, bool cast_iron, double v);

/// Tip relief by running-in of one gear's material C_ay = (1/18)(sigma_Hlim/97 - 18.45)^2 + 1.5
/// (6.5.9, used in B_k when no tip relief is given), um; sigma_Hlim in MPa.
double tip_relief_by_running_in(double sigma_Hlim);

/// C_ay of a pair: the mean 0.5 (C_ay1 + C_ay2) of both gears' values when the materials differ
/// (6.5.9, as for the running-in allowances y_alpha and y_beta; DIN 3990-1 states the same), um.
double mesh_tip_relief_by_running_in(double sigma_Hlim1, double sigma_Hlim2);

/// The coefficients C_v1..C_v7 of 6.5.9 Table 6 for the total contact ratio eps_gamma.
struct DynamicCoefficients {
  double C_v1, C_v2, C_v3, C_v4, C_v5, C_v6, C_v7;
};
DynamicCoefficients dynamic_coefficients(double eps_gamma);

/// B_p = c' f_pb,eff / (K_A F_t/b), B_f = c' f_falpha,eff / (K_A F_t/b),
/// B_k = |1 - c' C_a / (K_A F_t/b)| (6.5.9, Eq. 19-21).
struct DeviationTerms {
  double B_p, B_f, B_k;
};
DeviationTerms deviation_terms(double c_prime, double f_pb_eff, double f_falpha_eff, double C_a, double K_A_F_t_per_b);

/// K_v by method B (6.5.9, Eq. 13-18) in the range of N.
double dynamic_factor(double N, double N_S, const DynamicCoefficients& C, const DeviationTerms& B);

// ---- Face load factor K_Hbeta, method C (clause 7.6) ----

/// Component of the mesh misalignment from shaft and pinion deflection (7.6.4, Eq. 43 with
/// Eq. 44 for spur and single helical gears):
/// f_sh = F_m/b * 0.023 * (|B* + K' l s / d_1^2 (d_1/d_sh)^4 - 0.3| + 0.3) (b/d_1)^2, um.
/// F_m/b in N/mm; b, d_1, l (bearing span), s (offset of the pinion from the middle of the span)
/// and d_sh (outer diameter of the pinion shaft) in mm. Pass K_prime = 0 (or d_sh = 0) for no
/// pinion offset data (the pinion centred on its own shaft); B_star = 1 when the mesh transmits
/// all of the pinion's torque (power_split_factor).
double shaft_deflection_misalignment(double F_m_per_b, double b, double d_1, double K_prime, double l, double s, double d_sh,
                                     double B_star = 1.0);

/// B* = 1 + 2 (100 - k)/k (7.6.4): k is the percentage of the pinion's input torque that this
/// mesh transmits; the rest passes through the pinion body to another mesh (power split). k in
/// (0, 100]; 100 gives B* = 1.
double power_split_factor(double k_percent);

/// The five pinion and bearing arrangements of ISO 6336-1:2019 Figure 13 (the 2006 edition's
/// Figure 13 too), named by their letter there.
enum class ShaftArrangement { a, b, c, d, e };
const char* to_string(ShaftArrangement arrangement);  ///< "a" .. "e"

/// Constant K' of Figure 13 for an arrangement, with stiffening (the pinion body stiffens its
/// shaft: pinion integral with the shaft, d_1/d_sh >= 1.15) or without (d_1/d_sh < 1.15, or a
/// pinion shrunk or keyed on the shaft): a 0.48 / 0.8, b -0.48 / -0.8, c 1.33 / 1.33,
/// d -0.36 / -0.6, e -0.6 / -1.0.
double shaft_constant_K_prime(ShaftArrangement arrangement, bool stiffening);

/// Largest s/l for which Figure 13 gives K': 0.3 for arrangements a and b, 0.5 for c, d and e.
double shaft_offset_limit(ShaftArrangement arrangement);

/// Flank line modifications of 7.6.2 Table 10 (Table 8 in the 2006 edition) and their constants
/// B_1 (on f_sh) and B_2 (on f_ma) of Eq. 38: none 1/1, helix correction 0.1/1, helix correction
/// plus crowning 0.1/0.5, crowning 0.5/0.5, end relief 0.7/0.7.
enum class HelixModification { none, helix_correction, helix_correction_and_crowning, crowning, end_relief };
const char* to_string(HelixModification modification);  ///< "none", "helix-correction", ...

struct MisalignmentConstants {
  double B_1 = 1, B_2 = 1;
};
MisalignmentConstants misalignment_constants(HelixModification modification);

/// Initial equivalent misalignment F_betax = 1.33 B_1 f_sh + B_2 f_ma (7.6.2, Eq. 38; B_1 = B_2 = 1
/// for no helix modification), at least F_betax,min = max(0.005 F_m/b, 0.5 f_Hbeta).
double initial_equivalent_misalignment(double f_sh, double f_ma, double F_m_per_b, double f_Hbeta,
                                       MisalignmentConstants B = {});

/// Running-in allowance y_beta (7.6.3, Table 11): St/V/GGG: 320/sigma_Hlim F_betax (limited for
/// v > 5 m/s), Eh/IF/NT/NV: 0.15 F_betax (<= 6 um), GG: 0.55 F_betax (<= 45 um). um.
double running_in_allowance_beta(double F_betax, double sigma_Hlim, bool surface_hardened, bool cast_iron, double v);

/// K_Hbeta = 1 + c_gamma_beta F_betay / (2 F_m/b) when that is <= 2, else
/// sqrt(2 c_gamma_beta F_betay / (F_m/b)) (7.6.1, Eq. 35-36).
double face_load_factor_H(double c_gamma_beta, double F_betay, double F_m_per_b);

/// Exponent N_F = (b/h)^2 / (1 + b/h + (b/h)^2), b/h the smaller of both gears, at least 3 (7.7, Eq. 49).
double face_load_exponent(double b_over_h);

/// K_Fbeta = K_Hbeta^N_F (7.7, Eq. 48).
double face_load_factor_F(double K_Hbeta, double N_F);

// ---- Transverse load factors, method B (clause 8.3) ----

/// K_Halpha = K_Falpha before limits (8.3.2, Eq. 73-74): for eps_gamma <= 2,
/// (eps_gamma/2)(0.9 + 0.4 c_gamma_alpha (f_pb - y_alpha)/(F_tH/b)), else
/// 0.9 + 0.4 sqrt(2 (eps_gamma - 1)/eps_gamma) c_gamma_alpha (f_pb - y_alpha)/(F_tH/b).
double transverse_load_factor(double eps_gamma, double c_gamma_alpha, double f_pb_minus_y_alpha, double F_tH_per_b);

/// K_Halpha limited to [1, eps_gamma / (eps_alpha Z_eps^2)] (8.3.4, Eq. 75).
double limit_K_Halpha(double K, double eps_gamma, double eps_alpha, double Z_epsilon);

/// K_Falpha limited to [1, eps_gamma / (0.25 eps_alpha + 0.75)] (8.3.5, Eq. 76).
double limit_K_Falpha(double K, double eps_gamma, double eps_alpha);

}  // namespace gearkit::gear::iso6336
