#pragma once
// ISO 6336-3:2019 method B form factor Y_F and stress correction factor Y_S of an external gear,
// written out again from the standard's equations (Eq. 17-30, 42-44; the virtual spur gear of
// clause 6.2) for tests that need an independent value of the tooth root (the tool, the tip and
// the thickness allowance of each gear). Lengths in mm, angles in rad. Not libgear's code: its
// theta comes from fixed-point iteration, libgear's from Newton's method.
#include <cmath>
#include <numbers>

namespace gearkit::testing {

struct RootByHand {
  double Y_F = 0, Y_S = 0, s_Fn = 0, h_Fe = 0;
};

/// z, m_n, alpha_n, beta; the tool h_fP*, rho_fP*, s_pr*; the generating shift x_E
/// (= x + A_sne/(2 m_n tan alpha_n)); the tip diameter d_a (or d_Na) and the transverse contact ratio.
inline RootByHand root_by_hand(int z, double m, double alpha_n, double beta, double h_fP, double rho_fP, double s_pr,
                               double x_E, double d_a, double eps_alpha) {
  const double pi = std::numbers::pi;
  auto inv = [](double a) { return std::tan(a) - a; };
  const double beta_b = std::asin(std::sin(beta) * std::cos(alpha_n));
  const double d = z * m / std::cos(beta);
  // Eq. 19-22: E, G, H and theta = 2 G/z_n tan(theta) - H.
  const double E = pi / 4.0 * m - h_fP * m * std::tan(alpha_n) + s_pr * m / std::cos(alpha_n) -
                   (1.0 - std::sin(alpha_n)) * rho_fP * m / std::cos(alpha_n);
  const double z_n = z / (std::cos(beta_b) * std::cos(beta_b) * std::cos(beta));
  const double G = rho_fP - h_fP + x_E;
  const double H = 2.0 / z_n * (pi / 2.0 - E / m) - pi / 3.0;
  double theta = pi / 6.0;
  for (int k = 0; k < 200; ++k) theta = 2.0 * G / z_n * std::tan(theta) - H;
  // Eq. 23-24: root chord and fillet radius at the 30-degree tangent.
  const double s_Fn = m * (z_n * std::sin(pi / 3.0 - theta) + std::sqrt(3.0) * (G / std::cos(theta) - rho_fP));
  const double rho_F = m * (rho_fP + 2.0 * G * G / (std::cos(theta) * (z_n * std::cos(theta) * std::cos(theta) - 2.0 * G)));
  // Eq. 25-30: the load at the outer point of single tooth contact of the virtual spur gear.
  const double eps_an = eps_alpha / (std::cos(beta_b) * std::cos(beta_b));
  const double d_n = m * z_n, d_bn = d_n * std::cos(alpha_n), d_an = d_n + d_a - d;
  const double roll = std::sqrt(d_an * d_an / 4.0 - d_bn * d_bn / 4.0) - pi * d * std::cos(beta) * std::cos(alpha_n) / z * (eps_an - 1.0);
  const double d_en = 2.0 * std::sqrt(roll * roll + d_bn * d_bn / 4.0);
  const double alpha_en = std::acos(d_bn / d_en);
  const double gamma_e = (pi / 2.0 + 2.0 * x_E * std::tan(alpha_n)) / z_n + inv(alpha_n) - inv(alpha_en);
  const double alpha_Fen = alpha_en - gamma_e;
  const double h_Fe = 0.5 * m * ((std::cos(gamma_e) - std::sin(gamma_e) * std::tan(alpha_Fen)) * d_en / m -
                                 z_n * std::cos(pi / 3.0 - theta) - G / std::cos(theta) + rho_fP);
  RootByHand r;
  r.s_Fn = s_Fn;
  r.h_Fe = h_Fe;
  r.Y_F = 6.0 * h_Fe / m * std::cos(alpha_Fen) / ((s_Fn / m) * (s_Fn / m) * std::cos(alpha_n));  // Eq. 17
  const double L = s_Fn / h_Fe, q_s = s_Fn / (2.0 * rho_F);  // Eq. 42-44
  r.Y_S = (1.2 + 0.13 * L) * std::pow(q_s, 1.0 / (1.21 + 2.3 / L));
  return r;
}

}  // namespace gearkit::testing
