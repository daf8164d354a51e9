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

/// Backlash of one state of the pair: circumferential on the working circle and normal, mm.
struct Backlash {
  double j_t = 0;  ///< circumferential (transverse) backlash j_wt
  double j_n = 0;  ///< normal backlash j_bn = j_wt cos(alpha_wt) cos(beta_b)
};

/// j_t and j_n of `in` (circumferential_backlash and normal_backlash together).
/// @throws std::domain_error if the base circles do not fit the centre distance.
Backlash backlash_at(const BacklashInput& in);

/// The pair with both gears and the housing at other temperatures than the reference 20 deg C of
/// ISO 1: every length of gear i (diameters, thicknesses) grows by the factor (1 + growth_i), the
/// centre distance by (1 + growth_housing), growth = alpha (T - 20 deg C) with alpha the linear
/// expansion coefficient of the material (1/K).
BacklashInput at_temperature(const BacklashInput& in, double growth1, double growth2, double growth_housing);

/// The pair with the magnitude of its centre distance changed by A_a (mm, positive = shafts
/// further apart), whatever the sign convention of `in.a` (negative for internal pairs).
BacklashInput with_centre_distance_deviation(BacklashInput in, double A_a);

/// Tooth thickness and centre distance limits of a pair, mm (normal thickness allowances with the
/// DIN 3967 signs, negative = thinner; centre distance allowances of |a|, positive = shafts further apart).
struct PairLimits {
  double A_sne1 = 0, A_sni1 = 0;  ///< gear 1 upper, lower
  double A_sne2 = 0, A_sni2 = 0;  ///< gear 2 upper, lower
  double A_ae = 0, A_ai = 0;      ///< centre distance upper, lower
};

/// Smallest and largest backlash over the limits: the thickest teeth (upper allowances) at the
/// least favourable centre distance give the minimum, the thinnest teeth at the most favourable
/// the maximum (for an external pair the smallest and largest distance; for an internal pair the
/// other way round: both ends are evaluated). Exact (each state through circumferential_backlash),
/// no pitch, profile or helix deviations included (the theoretical backlash of ISO 21771-2).
/// `nominal` holds the thicknesses without allowance (s_t) and the nominal working centre
/// distance; beta is the reference helix angle (to turn normal allowances into transverse ones).
struct BacklashRange {
  Backlash min, max;
};
BacklashRange backlash_range(const BacklashInput& nominal, double beta, const PairLimits& limits);

}  // namespace gearkit::gear
