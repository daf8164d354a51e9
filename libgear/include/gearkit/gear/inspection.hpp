#pragma once
// Inspection data of a gear pair: the accuracy grade's flank tolerances (accuracy.hpp), the tooth
// thickness allowances and tolerance (given, or by the ISO/TR 10064-2 guidance of
// thickness_tolerance.hpp), the span W_k and the dimension over pins M_d at their upper and lower
// limits with their measuring conditions, the centre distance allowances (ISO 286 js field or
// given) and the backlash range, at 20 deg C and optionally at operating temperatures.
// An analysis on top of compute_gear_pair: it takes the finished gear table. Lengths in mm,
// tolerances of accuracy.hpp in um, angles in rad, temperatures in deg C.

#include <gearkit/gear/accuracy.hpp>
#include <gearkit/gear/backlash.hpp>
#include <gearkit/gear/din3967.hpp>
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/thickness_tolerance.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::gear {

/// Linear expansion coefficient of steel, 1/K (the default for gears and housing).
inline constexpr double kSteelExpansion = 11.5e-6;

/// What the inspection is asked for. A gear needs its grade or its allowances (or both).
struct InspectionInput {
  std::array<std::optional<int>, 2> grade;  ///< accuracy grade of each gear (ISO 1328-1 class or grade)
  Iso1328Edition edition = Iso1328Edition::iso2013;
  std::array<std::optional<ThicknessAllowances>, 2> allowances;  ///< given directly
  std::array<std::optional<Din3967Designation>, 2> din3967;      ///< else from DIN 3967 ("27cd"); else ISO/TR 10064-2
  std::optional<double> j_bn_min;  ///< minimum normal backlash the allowances must give, mm (default ISO/TR 10064-2)
  std::optional<ThicknessAllowances> centre_distance_allowances;  ///< A_ae, A_ai of |a|, mm (given)
  std::optional<int> centre_distance_it;  ///< IT grade of the js field (default from the accuracy grade)
  std::optional<double> T_gears, T_housing;  ///< operating temperatures, deg C (reference 20)
  double alpha_gear1 = kSteelExpansion, alpha_gear2 = kSteelExpansion, alpha_housing = kSteelExpansion;  ///< 1/K
};

enum class AllowanceSource { given, din3967, iso_tr_10064_2 };
const char* to_string(AllowanceSource source);  ///< "given", "DIN 3967", "ISO/TR 10064-2"

/// Inspection data of one gear. NaN where a value does not exist (no span for a ring, no pin range
/// for a ring, no b_r for given allowances).
struct GearInspection {
  std::optional<FlankTolerances> tolerances;  ///< when the gear has a grade
  AllowanceSource source = AllowanceSource::given;
  std::string din3967;              ///< the DIN 3967 designation ("27cd") when the source is DIN 3967
  ThicknessAllowances allowances;   ///< A_sne, A_sni, mm
  double T_sn = 0;                  ///< A_sne - A_sni, mm
  double b_r = 0;                   ///< radial infeed tolerance, um (ISO/TR 10064-2 system)
  double F_r = 0;                   ///< runout tolerance used for the measurement allowances, um (0: none)
  ThicknessAllowances measured;     ///< allowances the span and pins must meet (runout term removed)
  /// False when the runout term leaves no acceptance band (measured.A_sne < measured.A_sni): no
  /// tooth can be accepted, and W_k_max/min, d_W_max/min and M_d_max/min are all NaN (a warning).
  bool acceptance_band = true;
  int k = 0;                        ///< teeth spanned
  double W_k_max = 0, W_k_min = 0;  ///< span limits: thickest and thinnest accepted tooth
  double d_W_max = 0, d_W_min = 0;  ///< diameters where the anvils touch at W_k_max, W_k_min
  double b_min_span = 0;            ///< face width the spans need: the largest of W_k, W_k_max, W_k_min times sin(beta_b)
  double D_M = 0;                   ///< pin (ball) diameter of the table
  /// Dimension over (external) or between (ring) pins: the larger and smaller limit. External:
  /// max at the thickest tooth; ring: max at the thinnest (its pins move outwards as the teeth thin).
  double M_d_max = 0, M_d_min = 0;
  double D_M_min = 0, D_M_max = 0;  ///< usable pin diameters: touching within the usable flank and standing out of the tip
};

struct PairInspection {
  std::string centre_distance_field;  ///< "js7", ... or "given"
  double A_ae = 0, A_ai = 0;          ///< centre distance allowances, mm
  double j_bn_min_target = 0;         ///< minimum backlash aimed at by the ISO/TR 10064-2 system (NaN if all given)
  BacklashRange range;                ///< at 20 deg C
  std::optional<BacklashRange> operating;  ///< at the operating temperatures
};

struct InspectionResult {
  std::array<GearInspection, 2> gear;
  PairInspection pair;
  std::vector<std::string> warnings;  ///< engineering problems (no backlash, measuring conditions, scope)
};

/// Default IT grade of the centre-distance js field for an accuracy grade: <= 4: js6, 5-6: js7,
/// 7-8: js8, 9-10: js9, >= 11: js10 (+-IT/2 rule of gear practice, one IT grade per two grades).
int default_centre_distance_it(int grade);

/// The inspection data of the pair `input` -> `table`.
/// @throws GeometryError naming the InspectionInput field at fault ("grade1", "allowances2",
///         "centre_distance_it", ...) when a gear has neither grade nor allowances, a grade is outside
///         the edition, allowances have A_sne < A_sni, or the data fall outside the tables used.
InspectionResult compute_inspection(const GearPairInput& input, const GearPairResult& table,
                                    const InspectionInput& inspection);

}  // namespace gearkit::gear
