#include <gearkit/gear/measurement.hpp>
#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/involute.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace gearkit::gear {

ToothData make_tooth_data(int z, double m_n, double alpha_n, double beta, double s_t) {
  if (z == 0 || !(m_n > 0.0)) throw std::domain_error("measurement: expected z != 0 and m_n > 0");
  ToothData g{z, m_n, alpha_n, beta, s_t};
  g.m_t = transverse_module(m_n, beta);
  g.alpha_t = transverse_pressure_angle(alpha_n, beta);
  g.inv_alpha_t = involute(g.alpha_t);
  g.d = reference_diameter(z, m_n, beta);
  g.d_b = base_diameter(g.d, g.alpha_t);
  g.beta_b = base_helix_angle(beta, alpha_n);
  g.cos_beta = std::cos(beta);
  g.cos_beta_b = std::cos(g.beta_b);
  g.tan_alpha_n = std::tan(alpha_n);
  g.x = (s_t / g.m_t - std::numbers::pi / 2.0) / (2.0 * g.tan_alpha_n);
  return g;
}

double tooth_thickness_at(const ToothData& g, double d_y) {
  const double alpha_y = pressure_angle_at(g.d_b, d_y);
  const double c_y = g.d_b / d_y;
  const double inv_y = alpha_y < 0.05 ? involute(alpha_y) : std::sqrt(1.0 - c_y * c_y) / c_y - alpha_y;
  return d_y * (g.s_t / g.d + g.inv_alpha_t - inv_y);
}

int span_teeth(const ToothData& g) {
  if (g.z < 2) throw std::domain_error("span measurement needs an external gear with at least 2 teeth");
  const double d_x = g.d + 2.0 * g.x * g.m_n;
  const double cos_ax = std::min(1.0, g.d_b / d_x);
  const double tan_ax = std::sqrt(1.0 - cos_ax * cos_ax) / cos_ax;
  const double cb = g.cos_beta_b;
  const double k_real = g.z / std::numbers::pi *
                            (tan_ax / (cb * cb) - 2.0 * g.x * g.tan_alpha_n / g.z - g.inv_alpha_t) +
                        0.5;
  const int k = static_cast<int>(std::lround(k_real));
  return std::clamp(k, 1, g.z - 1);
}

double span_measurement(const ToothData& g, int k) {
  if (g.z < 2) throw std::domain_error("span measurement needs an external gear with at least 2 teeth");
  if (k < 1) throw std::domain_error("span measurement: k must be >= 1, found " + std::to_string(k));
  const double p_bt = std::numbers::pi * g.d_b / g.z;
  const double s_bt = g.d_b * (g.s_t / g.d + g.inv_alpha_t);
  return ((k - 1) * p_bt + s_bt) * g.cos_beta_b;
}

double span_contact_diameter(const ToothData& g, double W_k) {
  const double l = W_k * g.cos_beta_b;
  return std::sqrt(g.d_b * g.d_b + l * l);
}

double pin_diameter_for_contact_at(const ToothData& g, double d_y) {
  const double alpha_y = pressure_angle_at(g.d_b, d_y);
  const double c_y = g.d_b / d_y;
  const double tan_y = std::sqrt(1.0 - c_y * c_y) / c_y;  // tan(acos c) without a second libm call
  const double p_t = std::numbers::pi * g.m_t;
  const double e_t = p_t - g.s_t;
  const double inv_y = alpha_y < 0.05 ? involute(alpha_y) : tan_y - alpha_y;
  const double eta_y = e_t / g.d - g.inv_alpha_t + inv_y;
  const double alpha_M = alpha_y + eta_y;
  if (!(alpha_M > 0.0 && alpha_M < std::numbers::pi / 2.0)) {
    throw std::domain_error("pin diameter: no pin fits the tooth space at the requested diameter");
  }
  const double D = g.d_b * g.cos_beta_b * (std::tan(alpha_M) - tan_y);
  if (!(D > 0.0)) throw std::domain_error("pin diameter: the tooth space is closed at the requested diameter");
  return D;
}

double pin_centre_pressure_angle(const ToothData& g, double D_M) {
  const double inv_M = g.inv_alpha_t + g.s_t / g.d - std::numbers::pi / g.z + D_M / (g.d_b * g.cos_beta_b);
  return inverse_involute(inv_M);
}

double dimension_over_pins(const ToothData& g, double D_M) {
  const double alpha_M = pin_centre_pressure_angle(g, D_M);
  const double d_M = g.d_b / std::cos(alpha_M);
  const double across = (g.z % 2 == 0) ? d_M : d_M * std::cos(std::numbers::pi / (2.0 * g.z));
  return std::fabs(across + D_M);
}

double pin_protrusion(const ToothData& g, double D_M, double d_a) {
  const double d_M = std::fabs(g.d_b / std::cos(pin_centre_pressure_angle(g, D_M)));
  return g.z > 0 ? 0.5 * (d_M + D_M - std::fabs(d_a)) : 0.5 * (std::fabs(d_a) - (d_M - D_M));
}

double pin_diameter_flush_with_tip(const ToothData& g, double d_a) {
  if (g.z < 0) throw std::domain_error("pin diameter range: external gears only (a ring's usable flank depends on its cutter)");
  // Contact just above the base circle (the smallest pin that still touches the involute) and at
  // the tip circle bracket the answer; the protrusion is monotonic in D_M.
  double lo = pin_diameter_for_contact_at(g, g.d_b * 1.000001);
  double hi = pin_diameter_for_contact_at(g, d_a);
  if (pin_protrusion(g, hi, d_a) < 0.0) {
    throw std::domain_error("pin diameter: no pin touching the flanks stands out of the tip circle");
  }
  if (pin_protrusion(g, lo, d_a) >= 0.0) return lo;
  for (int i = 0; i < 100 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (pin_protrusion(g, mid, d_a) < 0.0 ? lo : hi) = mid;
  }
  return hi;
}

namespace {

// Diameter of the osculating circle of the reference cylinder's normal section at the tooth:
// d / cos^2(beta) (equivalently z / cos^3(beta) teeth of module m_n), the curvature a tooth
// caliper sees when it measures in the normal plane.
double normal_section_diameter(const ToothData& g) {
  const double cb = g.cos_beta;
  return g.d / (cb * cb);
}

}  // namespace

double chordal_thickness(const ToothData& g) {
  const double d_n = normal_section_diameter(g);
  const double s_n = g.s_t * g.cos_beta;
  return d_n * std::sin(s_n / d_n);
}

double chordal_height(const ToothData& g, double d_a) {
  const double d_n = normal_section_diameter(g);
  const double s_n = g.s_t * g.cos_beta;
  const double sag = 0.5 * std::fabs(d_n) * (1.0 - std::cos(s_n / d_n));
  const double h_a = 0.5 * std::fabs(d_a - g.d);
  // External: the chord lies inside the reference arc, away from the tip; internal: towards it.
  return g.z > 0 ? h_a + sag : h_a - sag;
}

}  // namespace gearkit::gear
