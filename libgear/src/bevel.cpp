// Formula functions of libgear/include/gearkit/gear/bevel.hpp, one per equation.
#include <gearkit/gear/bevel.hpp>

#include <gearkit/gear/gear_pair.hpp>

#include <cmath>
#include <numbers>

namespace gearkit::gear {

const char* to_string(BevelType type) {
  switch (type) {
    case BevelType::straight: return "straight";
    case BevelType::zerol: return "Zerol";
    case BevelType::spiral: return "spiral";
  }
  return "?";
}

const char* to_string(BevelSystem system) { return system == BevelSystem::gleason ? "Gleason" : "ISO 23509"; }

const char* to_string(DepthTaper taper) {
  switch (taper) {
    case DepthTaper::standard: return "standard";
    case DepthTaper::constant_clearance: return "constant clearance";
    case DepthTaper::uniform: return "uniform";
  }
  return "?";
}

const char* to_string(SpiralHand hand) { return hand == SpiralHand::right ? "right" : "left"; }

const char* to_string(Rotation rotation) { return rotation == Rotation::ccw ? "ccw" : "cw"; }

double pitch_cone_angle1(int z1, int z2, double Sigma) {
  // atan2 keeps delta_1 in (0, pi) for every shaft angle, also where cos Sigma + u < 0.
  return std::atan2(std::sin(Sigma), std::cos(Sigma) + static_cast<double>(z2) / z1);
}

double outer_cone_distance(double d_e, double delta) { return d_e / (2.0 * std::sin(delta)); }

double mean_cone_distance(double R_e, double b) { return R_e - 0.5 * b; }

double mean_transverse_module(double m_et, double R_m, double R_e) { return m_et * R_m / R_e; }

double mean_normal_module(double m_mt, double beta_m) { return m_mt * std::cos(beta_m); }

double virtual_gear_ratio(int z1, int z2, double delta1, double delta2) {
  return (z2 * std::cos(delta1)) / (z1 * std::cos(delta2));
}

double gleason_addendum_shift(BevelType type, double u_v) {
  // Both systems give the wheel a short addendum that tends to the basic one as u_v -> 1.
  return type == BevelType::spiral ? 0.39 * (1.0 - 1.0 / u_v) : 0.46 * (1.0 - 1.0 / u_v);
}

double cone_angle_of_depth(double h, double R) { return std::atan(h / R); }

double outer_tip_diameter(double d_e, double h_ae, double delta) { return d_e + 2.0 * h_ae * std::cos(delta); }

double crown_to_crossing_point(double R_e, double h_ae, double delta) {
  return R_e * std::cos(delta) - h_ae * std::sin(delta);
}

double virtual_teeth(int z, double delta) { return z / std::cos(delta); }

double virtual_teeth_normal(double z_v, double beta_m, double alpha_n) {
  const double beta_vb = std::asin(std::sin(beta_m) * std::cos(alpha_n));
  const double c = std::cos(beta_vb);
  return z_v / (c * c * std::cos(beta_m));
}

double virtual_contact_ratio(double d_v1, double d_v2, double h_am1, double h_am2, double alpha_vt, double m_mt) {
  auto roll = [alpha_vt](double d_v, double h_am) {
    const double r_a = 0.5 * d_v + h_am, r_b = 0.5 * d_v * std::cos(alpha_vt);
    return std::sqrt(r_a * r_a - r_b * r_b);
  };
  const double a_v = 0.5 * (d_v1 + d_v2);
  return transverse_contact_ratio_from_lengths(roll(d_v1, h_am1), roll(d_v2, h_am2), a_v, alpha_vt,
                                               std::numbers::pi * m_mt * std::cos(alpha_vt));
}

double virtual_overlap_ratio(double b, double beta_m, double m_mn) {
  return b * std::sin(std::fabs(beta_m)) / (std::numbers::pi * m_mn);
}

double bevel_tangential_force(double T, double d_m) { return 2000.0 * T / d_m; }

double bevel_axial_force(double F_t, double alpha_n, double beta_s, double delta, bool driving) {
  const double s = driving ? 1.0 : -1.0;
  return F_t / std::cos(beta_s) * (std::tan(alpha_n) * std::sin(delta) + s * std::sin(beta_s) * std::cos(delta));
}

double bevel_radial_force(double F_t, double alpha_n, double beta_s, double delta, bool driving) {
  const double s = driving ? -1.0 : 1.0;
  return F_t / std::cos(beta_s) * (std::tan(alpha_n) * std::cos(delta) + s * std::sin(beta_s) * std::sin(delta));
}

int spiral_sign(SpiralHand hand1, Rotation rotation1) {
  return (hand1 == SpiralHand::right) == (rotation1 == Rotation::ccw) ? 1 : -1;
}

}  // namespace gearkit::gear
