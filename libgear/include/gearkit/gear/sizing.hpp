#pragma once
// Rough sizing of a cylindrical gear pair (the design step KISSsoft calls rough sizing): over
// standard modules, pinion tooth counts that give a ratio within a tolerance and V-0 shift splits,
// the smallest face width that meets the required safety factors for the load, ranked by the
// volume of both gears. Lengths in mm.
#include <gearkit/gear/rating.hpp>

#include <optional>
#include <vector>

namespace gearkit::gear {

struct SizingInput {
  RatingInput load;                ///< torque, speed, materials, accuracy, life, S_Hmin, S_Fmin, method
  double ratio = 0;                ///< required u = z2/z1 (> 1 for a reducer; >= 1)
  double ratio_tolerance = 0.02;   ///< relative tolerance on u
  std::vector<double> modules;     ///< candidate normal modules (empty: ISO 54 series I, 1..25 mm)
  int z1_min = 14, z1_max = 40;    ///< pinion tooth counts
  std::vector<double> shifts{0.0, 0.2, 0.4};  ///< x1 of the V-0 split (x2 = -x1)
  double pressure_angle = 0.3490658503988659;  ///< rad
  double helix_angle = 0;          ///< rad
  double h_aP = 1.0, h_fP = 1.25, rho_fP = 0.38;
  double width_ratio_max = 1.0;    ///< largest b / d_1
  double width_module_min = 8.0;   ///< smallest b / m_n (narrower faces carry badly: misalignment, K_Hbeta)
  int count = 5;                   ///< candidates returned
  /// Required working centre distance, mm (empty: free, V-0 pairs with x1 from `shifts`). Given, a
  /// candidate's shift sum follows from it (ISO 21771 inv alpha_wt; compute_gear_pair with the
  /// balanced-sliding split) and must lie in [x_sum_min, x_sum_max]; `shifts` is then unused.
  std::optional<double> centre_distance;
  double x_sum_min = -0.5, x_sum_max = 2.0;  ///< shift sum limits with a centre distance (ISO 6336-1 Table 9 range)
  /// Hunting-tooth pairs only: gcd(z1, z2) = 1 (every pinion tooth meets every wheel tooth). Then
  /// every z2 within the ratio tolerance is tried, not only the nearest to u z1.
  bool hunting_tooth = false;
};

struct SizingCandidate {
  double m_n = 0;
  int z1 = 0, z2 = 0;
  double x1 = 0, x2 = 0;
  double b = 0;                    ///< face width, whole mm
  double a = 0, u = 0, d1 = 0, d2 = 0;
  double S_H = 0, S_F = 0;         ///< smallest of both gears
  double volume = 0;               ///< b pi/4 (d1^2 + d2^2), mm^3
};

struct SizingResult {
  std::vector<SizingCandidate> best;  ///< at most `count`, smallest volume first
  long long evaluated = 0;            ///< ratings computed
  long long combinations = 0;         ///< module x tooth count x shift combinations tried
};

/// Largest number of module x tooth count x shift combinations (keeps a run under a second).
constexpr long long kMaxSizingCombinations = 20000;

/// ISO 54 series I modules 1 .. 25 mm.
std::vector<double> iso54_series1();

/// Sizes the pair. @throws RatingError naming "ratio", "modules", "z1", "shifts", "centre_distance"
/// or a load field for invalid input or too many combinations.
SizingResult size_gear_pair(const SizingInput& input);

}  // namespace gearkit::gear
