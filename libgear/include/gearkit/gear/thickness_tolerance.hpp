#pragma once
// Tooth thickness allowances and tolerances (normal section, reference cylinder) following the
// guidance of ISO/TR 10064-2 (the minimum backlash of industrial drives and the tooth thickness
// tolerance from runout and the radial infeed tolerance), and the conversion of thickness
// allowances into inspection allowances for span and pins (DIN 3967 Appendix B, runout term).
// Lengths in mm unless a name says um (micrometres, as the standards print tolerances), angles
// in rad. Allowances follow DIN 3967 / ISO 21771 signs: negative = thinner teeth.

namespace gearkit::gear {

/// Upper and lower normal tooth thickness allowances of one gear (A_sne >= A_sni), mm.
struct ThicknessAllowances {
  double A_sne = 0;  ///< upper allowance (thickest tooth accepted)
  double A_sni = 0;  ///< lower allowance (thinnest tooth accepted)
};

/// Minimum normal backlash recommended by ISO/TR 10064-2 for industrial drives with ferrous gears
/// in ferrous housings (pitch-line speed below 15 m/s, usual manufacturing tolerances):
/// j_bn,min = (2/3) (0.06 + 0.0005 |a| + 0.03 m_n), mm (a centre distance, m_n normal module, mm).
double recommended_min_backlash(double a, double m_n);

/// Radial infeed tolerance b_r of the tooth cutting, um, by accuracy grade and reference diameter d
/// (mm), in ISO 286 IT values of d: grade 4: 1.26 IT7, 5: IT8, 6: 1.26 IT8, 7: IT9, 8: 1.26 IT9,
/// 9: IT10 (the table used with ISO/TR 10064-2, e.g. in GB/Z 18620.2), continued by its own rule
/// (one IT grade every two accuracy grades, 1.26 = sqrt 1.6 between): 0: IT6/1.26 (the 1995
/// edition's grade 0), 1: IT6, 2: 1.26 IT6, 3: IT7, 10: 1.26 IT10, 11: IT11, 12: 1.26 IT11.
/// @throws std::domain_error for grades outside 0..12 or d outside what iso286.hpp tabulates.
double radial_infeed_tolerance(int grade, double d);

/// Tooth thickness tolerance T_sn = 2 tan(alpha_n) sqrt(F_r^2 + b_r^2), um (F_r runout tolerance and
/// b_r radial infeed tolerance, um; alpha_n normal pressure angle, rad).
double tooth_thickness_tolerance(double F_r, double b_r, double alpha_n);

/// Thickness allowances that a span or pin measurement (local, on the teeth) must meet so that
/// the thickness referred to the axis (as the fit system defines it, runout included) stays within
/// `allowances`: A_sne - 0.72 F_r tan(alpha_n) and A_sni + 0.72 F_r tan(alpha_n). In the normal
/// span these are DIN 3967's A_Wne = A_sne cos alpha_n - 0.72 F_r sin alpha_n and A_Wni = A_sni
/// cos alpha_n + 0.72 F_r sin alpha_n. F_r in mm. The result may have A_sne < A_sni when the
/// tolerance is narrower than the runout allows (no acceptance band left).
ThicknessAllowances measurement_allowances(const ThicknessAllowances& allowances, double F_r, double alpha_n);

/// Normal span allowance for a normal thickness allowance: A_W = A_sn cos(alpha_n) (DIN 3967).
double span_allowance(double A_sn, double alpha_n);

}  // namespace gearkit::gear
