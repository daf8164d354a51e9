#pragma once
// Workshop measurements of tooth thickness (ISO 21771 clause 6, DIN 3960): span (base tangent
// length) W_k over k teeth, dimension over (or, for internal gears, between) two pins or balls
// M_d, and the chordal tooth thickness at the reference circle with its chordal height.
// Lengths in mm, angles in rad, signed diameters/teeth for internal gears as in
// cylindrical_gear.hpp. All take the actual transverse tooth thickness s_t at the reference
// circle, so allowances are included by passing s_t + A_st.

namespace gearkit::gear {

/// Geometry every measurement needs, taken from the gear table. Build it with make_tooth_data,
/// which also fills the derived members once (they are read by every measurement).
struct ToothData {
  int z = 0;            ///< number of teeth (negative: internal gear)
  double m_n = 0;       ///< normal module, mm
  double alpha_n = 0;   ///< normal pressure angle, rad
  double beta = 0;      ///< helix angle at the reference circle, rad
  double s_t = 0;       ///< transverse tooth thickness (arc) at the reference circle, mm
  // Derived by make_tooth_data:
  double m_t = 0, alpha_t = 0, inv_alpha_t = 0, d = 0, d_b = 0, beta_b = 0;
  double cos_beta = 1, cos_beta_b = 1, tan_alpha_n = 0;
  double x = 0;         ///< profile shift coefficient equivalent to s_t
};

/// @throws std::domain_error if z == 0 or m_n <= 0.
ToothData make_tooth_data(int z, double m_n, double alpha_n, double beta, double s_t);

/// Transverse tooth thickness (arc) at the diameter d_y, as cylindrical_gear.hpp's
/// tooth_thickness_at, from the precomputed data. @throws std::domain_error if |d_y| < |d_b|.
double tooth_thickness_at(const ToothData& g, double d_y);

/// Number of teeth spanned k: the span whose anvils touch the flanks at the diameter
/// d + 2 x m_n (mid working depth), k = round(z/pi (tan alpha_x / cos^2 beta_b - 2 x tan alpha_n / z
/// - inv alpha_t) + 1/2), cos alpha_x = d_b / (d + 2 x m_n), at least 1 (KHK/Niemann rule;
/// for x = 0 and spur gears k = round(z alpha / pi + 1/2)). x is taken from s_t.
/// @throws std::domain_error for internal gears (no span measurement) or z < 2.
int span_teeth(const ToothData& g);

/// Base tangent length over k teeth (normal section):
/// W_k = m_n cos(alpha_n) ((k - 1/2) pi + z inv alpha_t) + 2 x m_n sin(alpha_n), evaluated in
/// the equivalent form W_k = ((k - 1) p_bt + s_bt) cos(beta_b), s_bt = d_b (s_t / d + inv alpha_t)
/// the transverse base thickness, so that thickness allowances in s_t enter directly.
/// @throws std::domain_error for internal gears or k < 1.
double span_measurement(const ToothData& g, int k);

/// Diameter of the circle through the points where the span anvils touch the flanks,
/// d_W = sqrt(d_b^2 + (W_k cos beta_b)^2) (must lie between the form and tip circles).
double span_contact_diameter(const ToothData& g, double W_k);

/// Pin (ball) diameter D_M whose contact with the flanks lies on the diameter d_y (usual
/// choice d_y = d + 2 x m_n): D_M = d_b cos(beta_b) (tan alpha_Mt - tan alpha_yt) with
/// alpha_Mt = alpha_yt + eta_y, eta_y the half space angle at d_y. Works for internal gears
/// (pins between the teeth) with signed values; returns a positive diameter.
/// @throws std::domain_error if |d_y| < |d_b| or the space is closed at d_y.
double pin_diameter_for_contact_at(const ToothData& g, double d_y);

/// Pressure angle of the circle through the pin centres:
/// inv alpha_Mt = inv alpha_t + s_t / d - pi / z + D_M / (d_b cos beta_b) (signed form valid for
/// external and internal gears).
double pin_centre_pressure_angle(const ToothData& g, double D_M);

/// Dimension over two pins (external) or between two pins (internal), balls for helical gears,
/// in the transverse plane: even z: M_d = d_M +- D_M; odd z: M_d = d_M cos(pi / (2 z)) +- D_M,
/// d_M = d_b / cos alpha_Mt. Returns a positive length.
double dimension_over_pins(const ToothData& g, double D_M);

/// How far the pins (balls) of diameter D_M stand out of the tip circle d_a, mm, measured radially
/// at the pin: (d_M + D_M - d_a) / 2 for external gears, (|d_a| - (|d_M| - D_M)) / 2 for internal
/// gears (pins between the teeth), d_M = d_b / cos alpha_Mt the pin-centre circle. A micrometer
/// needs it > 0. Grows with D_M.
double pin_protrusion(const ToothData& g, double D_M, double d_a);

/// Smallest pin (ball) diameter that stands out of the tip circle (pin_protrusion = 0), found by
/// bisection between the pins touching the flanks at the base circle and at the tip circle
/// (external gears).
/// @throws std::domain_error for internal gears, or if even the pin touching at the tip circle
///         does not stand out.
double pin_diameter_flush_with_tip(const ToothData& g, double d_a);

/// Chordal tooth thickness at the reference circle, normal section: s_c = d_n sin(s_n / d_n),
/// d_n = d / cos^2(beta), the diameter of curvature of the reference cylinder's normal section
/// (z / cos^3(beta) teeth of module m_n, as in KHK/SDP "Elements of Metric Gear Technology"
/// Table 10-4; ISO's z_n = z/(cos^2 beta_b cos beta) belongs to the involute, not to this chord).
double chordal_thickness(const ToothData& g);

/// Chordal height over that chord measured from the tip circle:
/// h_c = h_a + d_n / 2 (1 - cos(s_n / d_n)), h_a = (d_a - d) / 2 (signed, |h_c| returned).
double chordal_height(const ToothData& g, double d_a);

}  // namespace gearkit::gear
