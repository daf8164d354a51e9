#pragma once
// ISO 286-1 standard tolerance grades (IT values) and the symmetric js field, used for the
// centre-distance allowances of a gear pair (the housing bores are toleranced as a js field, the
// classic gear-practice choice: +-IT/2, e.g. js7 for accuracy grades 5-6). Sizes in mm,
// tolerances in micrometres as ISO 286-1 Table 1 prints them.

namespace gearkit::gear {

/// Smallest and largest IT grade tabulated here: IT5..IT11 up to 500 mm, IT6..IT11 from 500 to
/// 3150 mm (ISO 286-1:2010 Table 1).
inline constexpr int kMinItGrade = 5;
inline constexpr int kMaxItGrade = 11;
inline constexpr double kMaxIso286Size = 3150.0;

/// Standard tolerance IT<grade> for a nominal size in (0, 3150] mm, um. The size ranges are those of
/// ISO 286-1 Table 1 (up to and including 3, over 3 up to 6, ...).
/// @throws std::domain_error if size <= 0 or > 3150 mm, or the grade is outside 5..11 (6..11 above
///         500 mm).
double standard_tolerance(int it_grade, double size);

/// Limit deviations of the js field: +-IT/2 (ISO 286-1 5.4), mm (upper, lower = -upper).
/// @throws std::domain_error as standard_tolerance.
double js_limit_deviation(int it_grade, double size);

}  // namespace gearkit::gear
