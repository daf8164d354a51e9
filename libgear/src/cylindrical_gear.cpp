#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/involute.hpp>

#include <cmath>
#include <numbers>

namespace gearkit::gear {

double transverse_module(double m_n, double beta) { return m_n / std::cos(beta); }

double transverse_pressure_angle(double alpha_n, double beta) {
  return std::atan(std::tan(alpha_n) / std::cos(beta));
}

double normal_pressure_angle(double alpha_t, double beta) { return std::atan(std::tan(alpha_t) * std::cos(beta)); }

double base_helix_angle(double beta, double alpha_n) { return std::asin(std::sin(beta) * std::cos(alpha_n)); }

double helix_angle_at(double beta, double d, double d_y) { return std::atan(std::tan(beta) * d_y / d); }

double reference_diameter(int z, double m_n, double beta) { return z * m_n / std::cos(beta); }

double base_diameter(double d, double alpha_t) { return d * std::cos(alpha_t); }

double tip_diameter(double d, double m_n, double h_aP, double x, double k) { return d + 2.0 * m_n * (h_aP + x - k); }

double root_diameter(double d, double m_n, double h_fP, double x) { return d - 2.0 * m_n * (h_fP - x); }

double reference_tooth_thickness(double m_t, double x, double alpha_n) {
  return m_t * (std::numbers::pi / 2.0 + 2.0 * x * std::tan(alpha_n));
}

double tooth_thickness_at(double s_t, double d, double d_b, double alpha_t, double d_y) {
  const double alpha_y = pressure_angle_at(d_b, d_y);
  return d_y * (s_t / d + involute(alpha_t) - involute(alpha_y));
}

double virtual_number_of_teeth(int z, double beta, double alpha_n) {
  const double cb = std::cos(base_helix_angle(beta, alpha_n));
  return z / (cb * cb * std::cos(beta));
}

double min_shift_no_undercut(int z, double beta, const Rack& rack) {
  return min_shift_no_undercut(reference_diameter(z, 1.0, beta), 1.0, transverse_pressure_angle(rack.alpha_P, beta), rack);
}

double min_shift_no_undercut(double d, double m_n, double alpha_t, const Rack& rack) {
  const double s = std::sin(alpha_t);
  return rack.h_fP - rack.rho_fP * (1.0 - std::sin(rack.alpha_P)) - 0.5 * (d / m_n) * s * s;
}

double practical_min_shift(double z_n, const Rack& rack) {
  const double s = std::sin(rack.alpha_P);
  const double z_g = std::round(2.0 * rack.h_aP / (s * s));
  const double z_g_practical = std::round(5.0 * z_g / 6.0);
  return rack.h_aP * (z_g_practical - z_n) / z_g;
}

double form_roll_length(int z, double m_n, double beta, double x, const Rack& rack) {
  const double alpha_t = transverse_pressure_angle(rack.alpha_P, beta);
  return form_roll_length(base_diameter(reference_diameter(z, m_n, beta), alpha_t), alpha_t, m_n, x, rack);
}

double form_roll_length(double d_b, double alpha_t, double m_n, double x, const Rack& rack) {
  const double h = (rack.h_fP - rack.rho_fP * (1.0 - std::sin(rack.alpha_P)) - x) * m_n;
  return 0.5 * d_b * std::tan(alpha_t) - h / std::sin(alpha_t);
}

}  // namespace gearkit::gear
