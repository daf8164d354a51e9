#pragma once
// Backlash of a gear pair from tooth-thickness allowances and centre-distance deviation
// (ISO 21771 clause 7, ISO/TR 10064-2, DIN 3967). Lengths in mm, angles in rad; diameters and
// tooth counts signed as in cylindrical_gear.hpp (gear 2 negative for an internal pair), the
// centre distance signed accordingly (negative for internal pairs).

namespace gearkit::gear {

/// What backlash depends on, for one pair at its actual centre distance.
struct BacklashInput {
  int z1 = 0, z2 = 0;         ///< signed tooth counts
  double d1 = 0, d2 = 0;      ///< reference diameters (signed)
  double d_b1 = 0, d_b2 = 0;  ///< base diameters (signed)
  double alpha_t = 0;         ///< transverse pressure angle
  double beta_b = 0;          ///< base helix angle
  double s_t1 = 0, s_t2 = 0;  ///< actual transverse thicknesses at the reference circle (with allowances)
  double a = 0;               ///< actual centre distance (signed; nominal plus deviation)
};

/// Circumferential (transverse) backlash on the working circle of the actual centre distance:
/// j_wt = p_w - s_w1 - s_w2 with cos alpha_w = (d_b1 + d_b2) / (2 a), d_wi = 2 a z_i / (z1 + z2),
/// s_wi = d_wi (s_ti / d_i + inv alpha_t - inv alpha_w). Exact (not linearised); negative means
/// the teeth would interpenetrate (the pair cannot be assembled at that distance).
/// @throws std::domain_error if the base circles do not fit the centre distance.
double circumferential_backlash(const BacklashInput& in);

/// Working transverse pressure angle of the actual centre distance: cos alpha_w = (d_b1 + d_b2) / (2 a).
double working_pressure_angle_at(const BacklashInput& in);

/// Normal backlash (along the line of action, normal section) j_bn = j_wt cos(alpha_wt) cos(beta_b).
double normal_backlash(double j_wt, double alpha_wt, double beta_b);

/// Equal normal tooth-thickness allowances A_sn1 = A_sn2 (mm, negative = thinner teeth) that give
/// the normal backlash j_bn_target at the actual centre distance of `in` (whose s_t1, s_t2 are the
/// thicknesses without allowance). Exact, because j_bn is linear in the allowances:
/// j_bn = j_bn0 - (A_sn1 + A_sn2) cos(alpha_n).
double allowance_for_backlash(const BacklashInput& in, double alpha_n, double j_bn_target);

}  // namespace gearkit::gear
