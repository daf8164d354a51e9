#include <gearkit/gear/iso6336_root.hpp>

#include <gearkit/gear/involute.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gearkit::gear::iso6336 {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

struct Virtual {
  double beta_b, cos2_beta_b, z_n, d_n, d_bn, d_an, eps_alpha_n, p_bn;
};

// The virtual spur gear of a helical gear (ISO 6336-3 6.2, Eq. 31-35), magnitudes.
Virtual virtual_gear(const ToothRootInput& in, bool internal) {
  Virtual v{};
  v.beta_b = std::asin(std::sin(in.beta) * std::cos(in.alpha_n));
  v.cos2_beta_b = std::cos(v.beta_b) * std::cos(v.beta_b);
  v.z_n = in.z / (v.cos2_beta_b * std::cos(in.beta));
  v.d_n = in.d / v.cos2_beta_b;
  v.d_bn = v.d_n * std::cos(in.alpha_n);
  v.d_an = internal ? v.d_n - (in.d - in.d_a) : v.d_n + in.d_a - in.d;
  v.eps_alpha_n = in.eps_alpha / v.cos2_beta_b;
  v.p_bn = kPi * in.m_n * std::cos(in.alpha_n);
  return v;
}

double roll_length(double d_y, double d_b) { return std::sqrt(std::max(0.0, 0.25 * (d_y * d_y - d_b * d_b))); }

}  // namespace

double root_parameter_E(double m_n, double alpha_n, double h_fP, double rho_fP, double s_pr) {
  const double c = std::cos(alpha_n);
  return kPi / 4.0 * m_n - h_fP * std::tan(alpha_n) + s_pr / c - (1.0 - std::sin(alpha_n)) * rho_fP / c;
}

double root_parameter_G(double rho_fP_star, double h_fP_star, double x_E) { return rho_fP_star - h_fP_star + x_E; }

double root_parameter_H(double z_n, double E_over_m_n) { return 2.0 / z_n * (kPi / 2.0 - E_over_m_n) - kPi / 3.0; }

double root_angle_theta(double z_n, double G, double H) {
  double theta = kPi / 6.0;
  for (int i = 0; i < 50; ++i) {
    const double c = std::cos(theta);
    const double f = 2.0 * G / z_n * std::tan(theta) - H - theta;
    const double df = 2.0 * G / (z_n * c * c) - 1.0;
    const double step = f / df;
    theta -= step;
    if (std::fabs(step) < 1e-14) break;
  }
  return theta;
}

double root_chord(double z_n, double theta, double G, double rho_fP_star) {
  return z_n * std::sin(kPi / 3.0 - theta) + std::sqrt(3.0) * (G / std::cos(theta) - rho_fP_star);
}

double root_fillet_radius(double z_n, double theta, double G, double rho_fP_star) {
  const double c = std::cos(theta);
  return rho_fP_star + 2.0 * G * G / (c * (z_n * c * c - 2.0 * G));
}

double form_factor(double h_Fe_star, double alpha_Fen, double s_Fn_star, double alpha_n) {
  return 6.0 * h_Fe_star * std::cos(alpha_Fen) / (s_Fn_star * s_Fn_star * std::cos(alpha_n));
}

double stress_correction_factor(double s_Fn, double h_Fe, double rho_F) {
  const double L = s_Fn / h_Fe;
  const double q_s = s_Fn / (2.0 * rho_F);
  return (1.2 + 0.13 * L) * std::pow(q_s, 1.0 / (1.21 + 2.3 / L));
}

ToothRoot external_tooth_root(const ToothRootInput& in) {
  const Virtual v = virtual_gear(in, false);
  const double m = in.m_n;
  const double E = root_parameter_E(m, in.alpha_n, in.h_fP * m, in.rho_fP * m, in.s_pr * m);
  const double G = root_parameter_G(in.rho_fP, in.h_fP, in.x_E);
  const double H = root_parameter_H(v.z_n, E / m);
  ToothRoot r;
  r.theta = root_angle_theta(v.z_n, G, H);
  if (!(std::isfinite(r.theta) && r.theta > -kPi / 2.0 && r.theta < kPi / 2.0)) {
    throw std::domain_error("no 30-degree tangent on the root fillet (ISO 6336-3 Eq. 22 has no solution)");
  }
  const double s_Fn_star = root_chord(v.z_n, r.theta, G, in.rho_fP);
  const double rho_F_star = root_fillet_radius(v.z_n, r.theta, G, in.rho_fP);
  // Outer point of single tooth contact on the virtual spur gear (Eq. 25-30).
  const double rho_en = roll_length(v.d_an, v.d_bn) - v.p_bn * (v.eps_alpha_n - 1.0);
  if (!(rho_en > 0.0) || !(s_Fn_star > 0.0)) {
    throw std::domain_error(fmt::format("the tooth-root construction fails (s_Fn = {:.4g} m_n, roll length to the load "
                                        "point {:.4g} mm)", s_Fn_star, rho_en));
  }
  r.d_en = 2.0 * std::hypot(rho_en, 0.5 * v.d_bn);
  const double alpha_en = std::acos(v.d_bn / r.d_en);
  const double gamma_e = (0.5 * kPi + 2.0 * in.x_E * std::tan(in.alpha_n)) / v.z_n + involute(in.alpha_n) - involute(alpha_en);
  r.alpha_Fen = alpha_en - gamma_e;
  const double h_Fe_star = 0.5 * ((std::cos(gamma_e) - std::sin(gamma_e) * std::tan(r.alpha_Fen)) * r.d_en / m -
                                  v.z_n * std::cos(kPi / 3.0 - r.theta) - G / std::cos(r.theta) + in.rho_fP);
  r.s_Fn = s_Fn_star * m;
  r.rho_F = rho_F_star * m;
  r.h_Fe = h_Fe_star * m;
  r.Y_F = form_factor(h_Fe_star, r.alpha_Fen, s_Fn_star, in.alpha_n);
  r.Y_S = stress_correction_factor(r.s_Fn, r.h_Fe, r.rho_F);
  return r;
}

ToothRoot internal_tooth_root(const ToothRootInput& in) {
  const Virtual v = virtual_gear(in, true);
  const double m = in.m_n, a = in.alpha_n, t = std::tan(a), c = std::cos(a);
  const double rho = in.rho_fP * m;
  const double h_f = (in.h_fP - in.x_E) * m;          // dedendum of the ring tooth
  const double s_half = m * (kPi / 4.0 + in.x_E * t);  // half thickness at the reference line
  ToothRoot r;
  r.theta = kPi / 6.0;
  // 30-degree tangent on the rack fillet: the fillet circle touches the flank and the root line.
  r.s_Fn = 2.0 * (s_half + (h_f - rho) * t + rho / c - rho * std::cos(kPi / 6.0)) - 2.0 * in.s_pr * m / c;
  r.rho_F = rho;
  const double rho_en = roll_length(v.d_an, v.d_bn) + v.p_bn * (v.eps_alpha_n - 1.0);
  r.d_en = 2.0 * std::hypot(rho_en, 0.5 * v.d_bn);
  const double h_Q = 0.5 * (v.d_n - r.d_en);  // load point above the reference line, towards the ring tip
  const double x_Q = s_half - h_Q * t;        // half thickness there
  if (!(roll_length(v.d_an, v.d_bn) > 0.0) || !(x_Q > 0.0) || !(r.s_Fn > 0.0)) {
    throw std::domain_error("the tooth-root construction of the internal gear fails (tip inside the base circle or "
                            "load point outside the tooth)");
  }
  r.alpha_Fen = a;
  r.h_Fe = (h_f - 0.5 * rho) + h_Q - x_Q * t;
  r.Y_F = form_factor(r.h_Fe / m, r.alpha_Fen, r.s_Fn / m, a);
  r.Y_S = stress_correction_factor(r.s_Fn, r.h_Fe, r.rho_F);
  return r;
}

double helix_angle_factor_F(double eps_beta, double beta) {
  const double e = std::min(1.0, eps_beta);
  const double b = std::min(30.0, std::fabs(beta) / kDeg);
  return 1.0 - e * b / 120.0;
}

double rim_thickness_factor(double s_R, double h_t, double m_n, bool internal) {
  if (!(s_R > 0.0)) return 1.0;
  if (internal) {
    const double r = s_R / m_n;
    if (r >= 3.5) return 1.0;
    return 1.15 * std::log(8.324 * m_n / std::max(s_R, 1.75 * m_n));
  }
  const double r = s_R / h_t;
  if (r >= 1.2) return 1.0;
  return 1.6 * std::log(2.242 * h_t / std::max(s_R, 0.5 * h_t));
}

double deep_tooth_factor(double eps_alpha_n, std::optional<int> iso_grade) {
  if (!iso_grade || *iso_grade > 4 || eps_alpha_n <= 2.05) return 1.0;
  if (eps_alpha_n <= 2.5) return -0.666 * eps_alpha_n + 2.366;
  return 0.7;
}

double virtual_contact_ratio(double eps_alpha, double beta_b) {
  const double c = std::cos(beta_b);
  return eps_alpha / (c * c);
}

double slip_layer_thickness(const Material& material) {
  // ISO 6336-3:2019 Table 4; through-hardened and normalized steels interpolated in the proof stress.
  switch (material.kind) {
    case MaterialClass::case_carburized:
    case MaterialClass::induction_hardened: return 0.0030;
    case MaterialClass::nitrided:
    case MaterialClass::nitrided_through_hardened:
    case MaterialClass::nitrocarburized: return 0.1005;
    case MaterialClass::grey_cast_iron: return 0.3124;
    case MaterialClass::normalized_steel:
    case MaterialClass::cast_steel: {
      const double s = material.yield > 0 ? material.yield : 300.0;
      return s <= 300.0 ? 0.0833 : s >= 400.0 ? 0.0445 : 0.0833 + (s - 300.0) / 100.0 * (0.0445 - 0.0833);
    }
    default: {
      struct P {
        double s, rho;
      };
      constexpr P table[] = {{500, 0.0281}, {600, 0.0194}, {800, 0.0064}, {1000, 0.0014}};
      const double s = material.yield > 0 ? material.yield : 500.0;
      if (s <= table[0].s) return table[0].rho;
      for (int i = 1; i < 4; ++i) {
        if (s <= table[i].s) {
          return table[i - 1].rho + (s - table[i - 1].s) / (table[i].s - table[i - 1].s) * (table[i].rho - table[i - 1].rho);
        }
      }
      return table[3].rho;
    }
  }
}

double relative_notch_sensitivity_factor(double rho_prime, double q_s) {
  const double chi = (1.0 + 2.0 * q_s) / 5.0;
  return (1.0 + std::sqrt(rho_prime * chi)) / (1.0 + std::sqrt(rho_prime * 1.2));
}

double relative_surface_factor(MaterialClass kind, double R_z) {
  const bool hard = kind == MaterialClass::through_hardened_carbon || kind == MaterialClass::through_hardened_alloy ||
                    kind == MaterialClass::nodular_cast_iron || kind == MaterialClass::case_carburized ||
                    kind == MaterialClass::induction_hardened;
  const bool soft = kind == MaterialClass::normalized_steel || kind == MaterialClass::cast_steel;
  if (R_z < 1.0) return hard ? 1.120 : soft ? 1.070 : 1.025;
  const double r = std::min(R_z, 40.0) + 1.0;
  if (hard) return 1.674 - 0.529 * std::pow(r, 0.1);
  if (soft) return 5.306 - 4.203 * std::pow(r, 0.01);
  return 4.299 - 3.259 * std::pow(r, 0.005);
}

double size_factor_F(MaterialClass kind, double m_n) {
  if (m_n <= 5.0) return 1.0;
  switch (kind) {
    case MaterialClass::case_carburized:
    case MaterialClass::induction_hardened:
    case MaterialClass::nitrided:
    case MaterialClass::nitrided_through_hardened:
    case MaterialClass::nitrocarburized: return std::max(0.8, 1.05 - 0.01 * m_n);
    case MaterialClass::grey_cast_iron: return std::max(0.7, 1.075 - 0.015 * m_n);
    default: return std::max(0.85, 1.03 - 0.006 * m_n);
  }
}

double nominal_root_stress(double F_t, double b, double m_n, double Y_F, double Y_S, double Y_beta, double Y_B, double Y_DT) {
  return F_t / (b * m_n) * Y_F * Y_S * Y_beta * Y_B * Y_DT;
}

double root_stress(double sigma_F0, double K_gamma, double K_A, double K_v, double K_Fbeta, double K_Falpha) {
  return sigma_F0 * K_gamma * K_A * K_v * K_Fbeta * K_Falpha;
}

double root_stress_limit(double sigma_Flim, double Y_NT, double Y_deltarelT, double Y_RrelT, double Y_X) {
  return sigma_Flim * 2.0 * Y_NT * Y_deltarelT * Y_RrelT * Y_X;
}

}  // namespace gearkit::gear::iso6336
