#include <gearkit/gear/iso6336_scuffing.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gearkit::gear::iso6336 {

namespace {
constexpr double kC_1 = 0.7;  // Eq. 20
constexpr double kC_2 = 1.5;  // Eq. 17, 94
}  // namespace

const char* to_string(OilBase base) {
  switch (base) {
    case OilBase::mineral: return "mineral";
    case OilBase::polyalphaolefin: return "pao";
    case OilBase::polyglycol_water_soluble: return "pag-water-soluble";
    case OilBase::polyglycol_not_water_soluble: return "pag";
    case OilBase::phosphate_ester: return "phosphate-ester";
    case OilBase::traction_fluid: return "traction";
  }
  return "mineral";
}

const char* to_string(Lubrication method) {
  switch (method) {
    case Lubrication::dip: return "dip";
    case Lubrication::spray: return "spray";
    case Lubrication::immersed: return "immersed";
  }
  return "dip";
}

double lubricant_factor_X_L(OilBase base) {
  switch (base) {
    case OilBase::mineral: return 1.0;
    case OilBase::polyalphaolefin: return 0.8;
    case OilBase::polyglycol_water_soluble: return 0.6;
    case OilBase::polyglycol_not_water_soluble: return 0.7;
    case OilBase::phosphate_ester: return 1.3;
    case OilBase::traction_fluid: return 1.5;
  }
  return 1.0;
}

double lubrication_factor_X_S(Lubrication method) {
  switch (method) {
    case Lubrication::dip: return 1.0;
    case Lubrication::spray: return 1.2;
    case Lubrication::immersed: return 0.2;
  }
  return 1.0;
}

double welding_factor_X_W(MaterialClass kind) {
  switch (kind) {
    case MaterialClass::nitrided:
    case MaterialClass::nitrided_through_hardened:
    case MaterialClass::nitrocarburized: return 1.5;
    default: return 1.0;
  }
}

double helical_load_factor_B(double eps_gamma) {
  if (eps_gamma <= 2.0) return 1.0;
  if (eps_gamma >= 3.5) return 1.3;
  return 1.0 + 0.2 * std::sqrt((eps_gamma - 2.0) * (5.0 - eps_gamma));
}

double transverse_unit_load_B(double F_t, double K_A, double K_gamma, double K_v, double K_Bbeta, double K_Balpha, double b) {
  return F_t * K_A * K_gamma * K_v * K_Bbeta * K_Balpha / b;
}

double pitch_point_velocity_sum(double v, double alpha_wt, double alpha_t) {
  return 2.0 * std::min(v, 50.0) * std::tan(alpha_wt) * std::cos(alpha_t);
}

double pitch_relative_radius(double u, double a, double alpha_wt, double beta_b) {
  return u / ((1.0 + u) * (1.0 + u)) * a * std::sin(alpha_wt) / std::cos(beta_b);
}

double roughness_factor_X_R(double R_a, double rho_redC) { return 2.2 * std::pow(R_a / rho_redC, 0.25); }

double mean_friction_coefficient(double w_Bt, double K_Bgamma, double v_SigmaC, double rho_redC, double eta_oil, double X_R,
                                 double X_L) {
  const double w = std::max(w_Bt, 150.0);
  return 0.045 * std::pow(w * K_Bgamma / (v_SigmaC * rho_redC), 0.2) * std::pow(eta_oil, -0.05) * X_R * X_L;
}

double running_in_factor_X_E(double phi_E, double R_a, double rho_redC) { return 1.0 + (1.0 - phi_E) * 30.0 * R_a / rho_redC; }

double thermal_contact_coefficient(double lambda_M, double c_v) { return std::sqrt(lambda_M * c_v); }

double reduced_modulus(double E_1, double nu_1, double E_2, double nu_2) {
  return 2.0 / ((1.0 - nu_1 * nu_1) / E_1 + (1.0 - nu_2 * nu_2) / E_2);
}

double thermo_elastic_factor_X_M(double E_r, double B_M) { return std::sqrt(1000.0) * std::pow(E_r, 0.25) / B_M; }

double pressure_angle_factor_X_alphabeta(double alpha_wt, double alpha_n, double alpha_t, double beta) {
  return 1.22 * std::pow(std::sin(alpha_wt) * std::cos(alpha_n) * std::cos(beta), 0.25) /
         std::sqrt(std::cos(alpha_wt) * std::cos(alpha_t));
}

double pinion_tip_radius_rho_E1(double d_a1, double d_b1) { return 0.5 * std::sqrt(d_a1 * d_a1 - d_b1 * d_b1); }

double wheel_radius_at_pinion_tip_rho_E2(double a, double alpha_wt, double rho_E1) { return a * std::sin(alpha_wt) - rho_E1; }

double geometry_factor_X_BE(double u, double rho_E1, double rho_E2) {
  const double sign_z2 = u < 0.0 ? -1.0 : 1.0;
  return 0.51 * std::sqrt(sign_z2 * (u + 1.0)) * (std::sqrt(rho_E1) - std::sqrt(rho_E2 / u)) /
         std::pow(rho_E1 * std::fabs(rho_E2), 0.25);
}

double addendum_contact_ratio(int z, double d_a, double d_b, double alpha_wt) {
  return z / (2.0 * std::numbers::pi) * (std::sqrt(d_a * d_a / (d_b * d_b) - 1.0) - std::tan(alpha_wt));
}

double approach_factor_X_Q(double eps_f, double eps_a) {
  const double r = eps_f / eps_a;
  if (r <= 1.5) return 1.0;
  if (r >= 3.0) return 0.6;
  return 1.40 - 4.0 / 15.0 * r;
}

double effective_tip_relief(double K_A, double F_t, double b, double c) { return K_A * F_t / (b * c); }

double tip_relief_factor_X_Ca(double C_a, double C_eff, double eps_max) {
  const double q = std::min(C_a, C_eff) / C_eff;
  return 1.0 + (0.06 + 0.18 * q) * eps_max + (0.02 + 0.69 * q) * eps_max * eps_max;
}

double contact_ratio_factor_X_eps(double e1, double e2) {
  const double ea = e1 + e2;
  if (!(e1 > 0.0 && e2 >= 0.0 && ea < 3.0)) {
    throw std::invalid_argument(fmt::format("the contact ratio factor X_eps needs eps_1 > 0, eps_2 >= 0 and eps_alpha < 3, "
                                            "found eps_1 = {:.4f}, eps_2 = {:.4f}", e1, e2));
  }
  double s = 0.0;
  if (ea < 1.0) {
    s = e1 * e1 + e2 * e2;  // Eq. 39
  } else if (ea < 2.0 && e1 < 1.0 && e2 < 1.0) {
    s = 0.70 * (e1 * e1 + e2 * e2) - 0.22 * ea + 0.52 - 0.60 * e1 * e2;  // Eq. 40
  } else if (ea < 2.0 && e1 >= 1.0) {
    s = 0.18 * e1 * e1 + 0.70 * e2 * e2 + 0.82 * e1 - 0.52 * e2 - 0.30 * e1 * e2;  // Eq. 41
  } else if (ea < 2.0) {
    s = 0.70 * e1 * e1 + 0.18 * e2 * e2 - 0.52 * e1 + 0.82 * e2 - 0.30 * e1 * e2;  // Eq. 42
  } else if (e1 >= e2) {
    s = 0.44 * e1 * e1 + 0.59 * e2 * e2 + 0.30 * e1 - 0.30 * e2 - 0.15 * e1 * e2;  // Eq. 43
  } else {
    s = 0.59 * e1 * e1 + 0.44 * e2 * e2 - 0.30 * e1 + 0.30 * e2 - 0.15 * e1 * e2;  // Eq. 44
  }
  return s / (2.0 * ea * e1);
}

double flash_temperature_at_pinion_tip(double mu_mC, double X_M, double X_BE, double X_alphabeta, double K_Bgamma,
                                       double w_Bt, double v, double a, double X_E, double X_Q, double X_Ca) {
  return mu_mC * X_M * X_BE * X_alphabeta * std::pow(K_Bgamma * w_Bt, 0.75) * std::sqrt(v) / std::pow(std::fabs(a), 0.25) * X_E /
         (X_Q * X_Ca);
}

double mean_flash_temperature(double theta_flaE, double X_eps) { return theta_flaE * X_eps; }

double bulk_temperature_int(double theta_oil, double theta_flaint, double X_S, double X_mp) {
  return theta_oil + kC_1 * X_mp * X_S * theta_flaint;
}

double integral_temperature(double theta_M, double theta_flaint) { return theta_M + kC_2 * theta_flaint; }

double fzg_test_torque(double load_stage) { return 3.726 * load_stage * load_stage; }

double test_bulk_temperature(double T_1T, double X_L) { return 80.0 + 0.23 * T_1T * X_L; }

double test_mean_flash_temperature(double T_1T, double nu_40, double X_L) {
  return 0.2 * T_1T * std::pow(100.0 / nu_40, 0.02) * X_L;
}

double scuffing_integral_temperature(double theta_MT, double theta_flaintT, double X_WrelT) {
  return theta_MT + X_WrelT * kC_2 * theta_flaintT;
}

double scuffing_safety_integral(double theta_intS, double theta_int) { return theta_intS / theta_int; }

double scuffing_load_safety(double theta_intS, double theta_int, double theta_oil) {
  return (theta_intS - theta_oil) / (theta_int - theta_oil);
}

double kinematic_viscosity_at(double nu_40, double nu_100, double theta) {
  if (!(std::isfinite(nu_40) && std::isfinite(nu_100) && nu_100 > 0.0 && nu_100 < nu_40)) {
    throw std::invalid_argument(fmt::format("expected viscosities 0 < nu_100 < nu_40 mm^2/s, found nu_40 = {}, nu_100 = {}", nu_40, nu_100));
  }
  auto W = [](double nu) { return std::log10(std::log10(nu + 0.7)); };
  const double x40 = std::log10(313.15), x100 = std::log10(373.15);
  const double B = (W(nu_40) - W(nu_100)) / (x100 - x40);
  const double w = W(nu_40) - B * (std::log10(theta + 273.15) - x40);
  return std::pow(10.0, std::pow(10.0, w)) - 0.7;
}

double oil_density_at(double rho_15, double theta) { return rho_15 - 0.0007 * (theta - 15.0); }

double dynamic_viscosity(double nu, double rho) { return nu * rho; }

}  // namespace gearkit::gear::iso6336
