#include <gearkit/gear/iso6336_load.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gearkit::gear::iso6336 {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
}  // namespace

double nominal_tangential_load(double T_1, double d_1) { return 2000.0 * T_1 / d_1; }

double pitch_line_speed(double d_1, double n_1) { return kPi * d_1 * n_1 / 60000.0; }

double minimum_flank_deformation(double z_n1, double z_n2, double x_1, double x_2) {
  // ISO 6336-1:2019 Table 9 (valid for x_1 >= x_2 and -0.5 <= x_1 + x_2 <= 2).
  const double inv_z2 = std::isinf(z_n2) ? 0.0 : 1.0 / z_n2;
  return 0.04723 + 0.15551 / z_n1 + 0.25791 * inv_z2 - 0.00635 * x_1 - 0.11654 * x_1 / z_n1 - 0.00193 * x_2 -
         0.24188 * x_2 * inv_z2 + 0.00529 * x_1 * x_1 + 0.00182 * x_2 * x_2;
}

double theoretical_single_stiffness(double q_prime) { return 1.0 / q_prime; }

double basic_rack_factor(double h_fP_star, double alpha_Pn) {
  return (1.0 + 0.5 * (1.2 - h_fP_star)) * (1.0 - 0.02 * (20.0 - alpha_Pn / kDeg));
}

double gear_blank_factor(double b_s_over_b, double s_R, double m_n) {
  if (!(b_s_over_b < 1.0)) return 1.0;
  const double ratio = std::max(0.2, b_s_over_b);
  return 1.0 + std::log(ratio) / (5.0 * std::exp(s_R / (5.0 * m_n)));
}

double single_stiffness(double c_th, double C_M, double C_R, double C_B, double beta, double F_t_K_A_per_b) {
  const double c = c_th * C_M * C_R * C_B * std::cos(beta);
  return F_t_K_A_per_b >= 100.0 ? c : c * std::pow(F_t_K_A_per_b / 100.0, 0.25);
}

double mesh_stiffness_alpha(double c_prime, double eps_alpha) { return c_prime * (0.75 * eps_alpha + 0.25); }

double mesh_stiffness_beta(double c_gamma_alpha) { return 0.85 * c_gamma_alpha; }

double reduced_mass(double d_m1, double d_b1, double q_1, double q_2, double rho_1, double rho_2, double u) {
  const double r = d_m1 / d_b1;
  return kPi / 8.0 * r * r * d_m1 * d_m1 /
         (1.0 / (rho_1 * (1.0 - std::pow(q_1, 4))) + 1.0 / (rho_2 * (1.0 - std::pow(q_2, 4)) * u * u));
}

double resonance_speed(int z_1, double c_gamma_alpha, double m_red) {
  return 30000.0 / (kPi * z_1) * std::sqrt(c_gamma_alpha / m_red);
}

double resonance_lower_limit(double F_t_K_A_per_b) {
  return F_t_K_A_per_b >= 100.0 ? 0.85 : 0.5 + 0.35 * std::sqrt(F_t_K_A_per_b / 100.0);
}

const char* to_string(ResonanceRange range) {
  switch (range) {
    case ResonanceRange::subcritical: return "sub-critical";
    case ResonanceRange::main_resonance: return "main resonance";
    case ResonanceRange::intermediate: return "intermediate";
    case ResonanceRange::supercritical: return "super-critical";
  }
  return "sub-critical";
}

ResonanceRange resonance_range(double N, double N_S) {
  if (N <= N_S) return ResonanceRange::subcritical;
  if (N <= 1.15) return ResonanceRange::main_resonance;
  if (N < 1.5) return ResonanceRange::intermediate;
  return ResonanceRange::supercritical;
}

double running_in_allowance_alpha(double f, double sigma_Hlim, bool surface_hardened, bool cast_iron, double v) {
  if (surface_hardened) return std::min(0.075 * f, 3.0);
  if (cast_iron) {
    const double y = 0.275 * f;
    return v <= 5.0 ? y : std::min(y, v <= 10.0 ? 22.0 : 11.0);
  }
  const double y = 160.0 / sigma_Hlim * f;
  return v <= 5.0 ? y : std::min(y, (v <= 10.0 ? 12800.0 : 6400.0) / sigma_Hlim);
}

double tip_relief_by_running_in(double sigma_Hlim) {
  const double t = sigma_Hlim / 97.0 - 18.45;
  return t * t / 18.0 + 1.5;
}

double mesh_tip_relief_by_running_in(double sigma_Hlim1, double sigma_Hlim2) {
  return 0.5 * (tip_relief_by_running_in(sigma_Hlim1) + tip_relief_by_running_in(sigma_Hlim2));
}

DynamicCoefficients dynamic_coefficients(double eps_gamma) {
  DynamicCoefficients C{};
  C.C_v1 = 0.32;
  C.C_v5 = 0.47;
  if (eps_gamma <= 2.0) {
    C.C_v2 = 0.34;
    C.C_v3 = 0.23;
    C.C_v4 = 0.90;
    C.C_v6 = 0.47;
  } else {
    C.C_v2 = 0.57 / (eps_gamma - 0.3);
    C.C_v3 = 0.096 / (eps_gamma - 1.56);
    C.C_v4 = (0.57 - 0.05 * eps_gamma) / (eps_gamma - 1.44);
    C.C_v6 = 0.12 / (eps_gamma - 1.74);
  }
  if (eps_gamma <= 1.5) C.C_v7 = 0.75;
  else if (eps_gamma <= 2.5) C.C_v7 = 0.125 * std::sin(kPi * (eps_gamma - 2.0)) + 0.875;
  else C.C_v7 = 1.0;
  return C;
}

DeviationTerms deviation_terms(double c_prime, double f_pb_eff, double f_falpha_eff, double C_a, double K_A_F_t_per_b) {
  return {c_prime * f_pb_eff / K_A_F_t_per_b, c_prime * f_falpha_eff / K_A_F_t_per_b,
          std::fabs(1.0 - c_prime * C_a / K_A_F_t_per_b)};
}

namespace {
double K_v_main(const DynamicCoefficients& C, const DeviationTerms& B) {
  return C.C_v1 * B.B_p + C.C_v2 * B.B_f + C.C_v4 * B.B_k + 1.0;
}
double K_v_super(const DynamicCoefficients& C, const DeviationTerms& B) {
  return C.C_v5 * B.B_p + C.C_v6 * B.B_f + C.C_v7;
}
}  // namespace

double dynamic_factor(double N, double N_S, const DynamicCoefficients& C, const DeviationTerms& B) {
  switch (resonance_range(N, N_S)) {
    case ResonanceRange::subcritical:
      return N * (C.C_v1 * B.B_p + C.C_v2 * B.B_f + C.C_v3 * B.B_k) + 1.0;  // Eq. 13-14
    case ResonanceRange::main_resonance: return K_v_main(C, B);               // Eq. 15
    case ResonanceRange::supercritical: return K_v_super(C, B);              // Eq. 16
    case ResonanceRange::intermediate:                                        // Eq. 17
      return K_v_super(C, B) + (K_v_main(C, B) - K_v_super(C, B)) / 0.35 * (1.5 - N);
  }
  return 1.0;
}

double shaft_deflection_misalignment(double F_m_per_b, double b, double d_1, double K_prime, double l, double s, double d_sh,
                                     double B_star) {
  const double offset = d_sh > 0.0 ? K_prime * l * s / (d_1 * d_1) * std::pow(d_1 / d_sh, 4) : 0.0;
  const double gamma = (std::fabs(B_star + offset - 0.3) + 0.3) * (b / d_1) * (b / d_1);
  return F_m_per_b * 0.023 * gamma;
}

double power_split_factor(double k_percent) { return 1.0 + 2.0 * (100.0 - k_percent) / k_percent; }

const char* to_string(ShaftArrangement arrangement) {
  static constexpr const char* kNames[] = {"a", "b", "c", "d", "e"};
  return kNames[static_cast<int>(arrangement)];
}

double shaft_constant_K_prime(ShaftArrangement arrangement, bool stiffening) {
  // Figure 13: {with stiffening, without stiffening}.
  static constexpr double kK[5][2] = {{0.48, 0.8}, {-0.48, -0.8}, {1.33, 1.33}, {-0.36, -0.6}, {-0.6, -1.0}};
  return kK[static_cast<int>(arrangement)][stiffening ? 0 : 1];
}

double shaft_offset_limit(ShaftArrangement arrangement) {
  return arrangement == ShaftArrangement::a || arrangement == ShaftArrangement::b ? 0.3 : 0.5;
}

const char* to_string(HelixModification modification) {
  switch (modification) {
    case HelixModification::none: return "none";
    case HelixModification::helix_correction: return "helix-correction";
    case HelixModification::helix_correction_and_crowning: return "helix-correction-and-crowning";
    case HelixModification::crowning: return "crowning";
    case HelixModification::end_relief: return "end-relief";
  }
  return "none";
}

MisalignmentConstants misalignment_constants(HelixModification modification) {
  switch (modification) {
    case HelixModification::none: return {1.0, 1.0};
    case HelixModification::helix_correction: return {0.1, 1.0};
    case HelixModification::helix_correction_and_crowning: return {0.1, 0.5};
    case HelixModification::crowning: return {0.5, 0.5};
    case HelixModification::end_relief: return {0.7, 0.7};
  }
  return {1.0, 1.0};
}

double initial_equivalent_misalignment(double f_sh, double f_ma, double F_m_per_b, double f_Hbeta, MisalignmentConstants B) {
  return std::max({1.33 * B.B_1 * f_sh + B.B_2 * f_ma, 0.005 * F_m_per_b, 0.5 * f_Hbeta});
}

double running_in_allowance_beta(double F_betax, double sigma_Hlim, bool surface_hardened, bool cast_iron, double v) {
  if (surface_hardened) return std::min(0.15 * F_betax, 6.0);
  if (cast_iron) {
    const double y = 0.55 * F_betax;
    return v <= 5.0 ? y : std::min(y, v <= 10.0 ? 45.0 : 22.0);
  }
  const double y = 320.0 / sigma_Hlim * F_betax;
  return v <= 5.0 ? y : std::min(y, (v <= 10.0 ? 25600.0 : 12800.0) / sigma_Hlim);
}

double face_load_factor_H(double c_gamma_beta, double F_betay, double F_m_per_b) {
  const double K = 1.0 + c_gamma_beta * F_betay / (2.0 * F_m_per_b);
  return K <= 2.0 ? K : std::sqrt(2.0 * c_gamma_beta * F_betay / F_m_per_b);
}

double face_load_exponent(double b_over_h) {
  const double r = std::max(3.0, b_over_h);
  return r * r / (1.0 + r + r * r);
}

double face_load_factor_F(double K_Hbeta, double N_F) { return std::pow(K_Hbeta, N_F); }

double transverse_load_factor(double eps_gamma, double c_gamma_alpha, double f_pb_minus_y_alpha, double F_tH_per_b) {
  const double term = c_gamma_alpha * f_pb_minus_y_alpha / F_tH_per_b;
  if (eps_gamma <= 2.0) return 0.5 * eps_gamma * (0.9 + 0.4 * term);
  return 0.9 + 0.4 * std::sqrt(2.0 * (eps_gamma - 1.0) / eps_gamma) * term;
}

double limit_K_Halpha(double K, double eps_gamma, double eps_alpha, double Z_epsilon) {
  return std::clamp(K, 1.0, std::max(1.0, eps_gamma / (eps_alpha * Z_epsilon * Z_epsilon)));
}

double limit_K_Falpha(double K, double eps_gamma, double eps_alpha) {
  return std::clamp(K, 1.0, std::max(1.0, eps_gamma / (0.25 * eps_alpha + 0.75)));
}

}  // namespace gearkit::gear::iso6336
