#pragma once
// DIN 3967:1978 system of gear fits: upper tooth thickness allowances A_sne by deviation series
// (Table 1: a, ab, b, bc, c, cd, d, e, f, g, h) and tooth thickness tolerances T_sn by tolerance
// series (Table 2: 21..30), both by reference diameter range (up to 10, over 10 up to 50, ... up to
// 10000 mm). A drawing's designation "27cd" is tolerance series 27 with deviation series cd:
// A_sni = A_sne - T_sn. Values in mm (the tables print um), normal section.

#include <gearkit/gear/thickness_tolerance.hpp>

#include <string>
#include <string_view>

namespace gearkit::gear {

/// A parsed designation such as "27cd".
struct Din3967Designation {
  int tolerance_series = 0;      ///< 21..30
  std::string deviation_series;  ///< "a" .. "h"
};

/// True for the deviation series of Table 1 (a, ab, b, bc, c, cd, d, e, f, g, h).
bool is_din3967_deviation_series(std::string_view series);

/// Parses "<tolerance series><deviation series>", e.g. "27cd" or "25e".
/// @throws std::invalid_argument naming what is wrong (no such series, malformed).
Din3967Designation parse_din3967(std::string_view designation);

/// Upper allowance A_sne of Table 1, mm (<= 0), for the reference diameter |d| in mm.
/// @throws std::invalid_argument for an unknown series; std::domain_error for |d| > 10000 mm.
double din3967_upper_allowance(std::string_view deviation_series, double d);

/// Tooth thickness tolerance T_sn of Table 2, mm (> 0).
/// @throws std::invalid_argument outside 21..30; std::domain_error for |d| > 10000 mm.
double din3967_thickness_tolerance(int tolerance_series, double d);

/// A_sne and A_sni = A_sne - T_sn of a designation at the reference diameter d (mm).
ThicknessAllowances din3967_allowances(const Din3967Designation& designation, double d);

}  // namespace gearkit::gear
