#pragma once
// AGMA 2101-D (metric edition of AGMA 2001-D) for spur and helical gears, in the form Shigley's
// "Mechanical Engineering Design" chapter 14 teaches it (equation numbers of the 9th edition).
// Metric units: N, mm, MPa, m/s. US customary callers convert (1 in = 25.4 mm, 1 lbf = 4.448 N,
// 1 psi = 6.895e-3 MPa); the dimensionless factors are the same in both systems.
#include <gearkit/gear/rating.hpp>

namespace gearkit::gear::agma {

/// Dynamic factor K_v = ((A + sqrt(V_ft_min))/A)^B, B = 0.25 (12 - Q_v)^(2/3), A = 50 + 56 (1 - B)
/// (Eq. 14-27) with V in m/s converted exactly (1 m/s = 196.85 ft/min); AGMA 2101's metric
/// form rounds that to 200 V, 0.8 % more speed under the root. Q_v <= 12 (K_v = 1 at 12).
double dynamic_factor(int Q_v, double V);

/// The exact US form with the speed in ft/min: K_v = ((A + sqrt(V_ft_min))/A)^B (Eq. 14-27).
double dynamic_factor_ft_min(int Q_v, double V_ft_min);

/// Size factor K_s = 0.8433 (m b sqrt(Y))^0.0535 (Eq. 14-46 metric; US 1.192 (F sqrt(Y)/P)^0.0535),
/// at least 1. m module and b face width in mm, Y the Lewis form factor.
double size_factor(double m, double b, double Y);

/// Load-distribution factor K_m = K_H = 1 + C_mc (C_pf C_pm + C_ma C_e) (Eq. 14-30 to 14-35),
/// b and d_1 in mm (converted to inches inside: the coefficients are in inches).
double load_distribution_factor(double b, double d_1, AgmaMounting mounting, bool crowned, bool straddle_centred = true,
                                bool adjusted = false);

/// Surface strength geometry factor I = cos(phi_t) sin(phi_t) / (2 m_N) * m_G / (m_G +- 1)
/// (Eq. 14-23), m_N = p_N / (0.95 Z) for helical gears (Eq. 14-21), 1 for spur gears.
double surface_geometry_factor(double phi_t, double m_G, double m_N, bool internal);

/// Load sharing ratio m_N = p_N / (0.95 Z) with Z the length of the line of action in the
/// transverse plane and p_N the normal base pitch (Eq. 14-21, 14-22), mm.
double load_sharing_ratio(double p_N, double Z);

/// Bending stress sigma = W_t K_o K_v K_s K_m K_B / (b m_t J) (Eq. 14-15 metric), MPa.
double bending_stress(double W_t, double K_o, double K_v, double K_s, double K_m, double K_B, double b, double m_t, double J);

/// Contact stress sigma_c = Z_E sqrt(W_t K_o K_v K_s K_m Z_R / (d_w1 b I)) (Eq. 14-16 metric), MPa.
double contact_stress(double Z_E, double W_t, double K_o, double K_v, double K_s, double K_m, double C_f, double d_w1, double b,
                      double I);

/// Allowable bending stress number of through-hardened steel S_t = 0.533 HB + 88.3 (grade 1),
/// 0.703 HB + 113 (grade 2) MPa (Fig. 14-2).
double bending_strength_through_hardened(double HB, int grade);

/// Allowable contact stress number of through-hardened steel S_c = 2.22 HB + 200 (grade 1),
/// 2.41 HB + 237 (grade 2) MPa (Fig. 14-5).
double contact_strength_through_hardened(double HB, int grade);

/// Stress cycle factors: Y_N = 1.3558 N^-0.0178 for N >= 3e6, 2.3194 N^-0.0538 below (Fig. 14-14);
/// Z_N = 1.4488 N^-0.023 for N >= 1e7, 2.466 N^-0.056 below (Fig. 14-15).
double bending_cycle_factor(double N);
double contact_cycle_factor(double N);

/// Reliability factor K_R: Table 14-10 at its reliabilities (0.5: 0.70, 0.9: 0.85, 0.99: 1.00,
/// 0.999: 1.25, 0.9999: 1.50) and Eq. 14-38 between them (0.658 - 0.0759 ln(1 - R) below 0.99,
/// 0.50 - 0.109 ln(1 - R) from 0.99).
double reliability_factor(double R);

/// Hardness-ratio factor of the gear C_H = 1 + A' (m_G - 1), A' = 8.98e-3 (HB_P/HB_G) - 8.29e-3
/// for 1.2 <= HB_P/HB_G <= 1.7, 0 below, 0.00698 above (Eq. 14-36).
double hardness_ratio_factor(double HB_P, double HB_G, double m_G);

}  // namespace gearkit::gear::agma
