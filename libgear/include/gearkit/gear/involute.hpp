#pragma once
// The involute function and its inverse (ISO 21771 notation: inv alpha = tan alpha - alpha).
// Angles are in radians. Both functions are pure, allocation-free and safe to call from many
// threads; inverse_involute is the hot spot of every gear table (working pressure angle, pin
// measurement, tooth thickness at a diameter), so it is built for speed as well as accuracy.

namespace gearkit::gear {

/// inv(alpha) = tan(alpha) - alpha.
/// @param alpha pressure angle in rad, 0 <= alpha < pi/2 (negative angles give -inv(|alpha|)).
/// Below 0.05 rad a Taylor series is used so that tiny angles keep full relative precision
/// (tan(alpha) - alpha loses digits there by cancellation).
double involute(double alpha);

/// The angle alpha in [0, pi/2) with tan(alpha) - alpha = inv.
/// Accurate to a few 1e-15 rad (absolute; 3.4e-15 measured) over 0 <= alpha <= 1.5 rad, the
/// whole useful range of gear work: one Halley step from a rational initial approximation in
/// u = cbrt(3 inv) (relative error < 3e-7 for alpha <= 1.45 rad), two steps from atan(inv + alpha)
/// above that.
/// @param inv involute function value, inv >= 0.
/// @throws std::domain_error if inv is negative, NaN or infinite.
double inverse_involute(double inv);

/// Pressure angle of the involute of base diameter d_b at the diameter d_y: acos(d_b / d_y).
/// Diameters may both be negative (internal gears, ISO 21771 sign convention).
/// @throws std::domain_error if |d_y| < |d_b| (no involute inside the base circle) or the
///         signs differ.
double pressure_angle_at(double d_b, double d_y);

}  // namespace gearkit::gear
