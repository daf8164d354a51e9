#pragma once
// The basic rack profile (ISO 53) that defines the tooth proportions of a cylindrical involute
// gear, in the normal section, as coefficients of the normal module m_n.

namespace gearkit::gear {

/// Basic rack tooth profile, ISO 53. Defaults are ISO 53 profile A (and the common
/// "normalised" proportions of course notes): alpha_P = 20 deg, h_aP* = 1, h_fP* = 1.25,
/// rho_fP* = 0.38. All coefficients are multiples of the normal module m_n.
struct Rack {
  double alpha_P = 0.3490658503988659;  ///< profile (pressure) angle, rad (20 deg)
  double h_aP = 1.0;    ///< addendum coefficient h_aP* (gear addendum = tool dedendum part)
  double h_fP = 1.25;   ///< dedendum coefficient h_fP* (depth cut below the reference line)
  double rho_fP = 0.38; ///< root fillet radius coefficient rho_fP* (tool tip radius)
};

/// Bottom clearance coefficient c_P* = h_fP* - h_aP* (0.25 for ISO 53 A).
double clearance_coefficient(const Rack& rack);

/// Largest tool tip radius coefficient that still fits between the tool flank and its tip
/// line at the given rack: rho_max* = (pi/4 - h_fP* tan alpha_P) / ((1 - sin alpha_P)/cos alpha_P)
/// (full-radius tool tip). Returns the value for the normal section.
double max_fillet_radius_coefficient(const Rack& rack);

/// Checks that the rack describes a real tool: 0 < alpha_P < 45 deg, h_aP* > 0,
/// h_fP* >= h_aP*, 0 <= rho_fP* <= max_fillet_radius_coefficient.
/// @throws std::invalid_argument naming the offending coefficient.
void validate(const Rack& rack);

}  // namespace gearkit::gear
