#pragma once
// A cylindrical involute gear pair with profile shift: the complete gear table (ISO 21771
// notation, basic rack ISO 53). Lengths in mm, angles in rad.
//
// Conventions (decisions where the standards leave a choice):
// - Input tooth counts are positive; `internal = true` makes gear 2 a ring. Internally the
//   ISO 21771 signed convention is used (z2 < 0, d2 < 0, a < 0), so one set of formulas serves
//   both kinds of pair. Results report positive magnitudes (for a ring d_a < d < d_f).
// - Profile shift coefficients keep the ISO 21771 sign for ring gears: x2 > 0 thickens the ring
//   teeth (and moves their tips towards the axis). KHK/JIS tables use the opposite sign.
// - Tip shortening k = x1 + x2 - y is applied (d_a = d + 2 m_n (h_aP* + x - k)) when k > 0 and
//   `apply_tip_shortening` is set (default), so that the bottom clearance stays c_P* m_n.
// - Given a centre distance, the default split of the shift sum is the one that balances the
//   maximum specific sliding of both gears (ShiftSplit::balanced_sliding).
#include <gearkit/gear/rack.hpp>

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gearkit::gear {

/// Bad pair data. `field` names the GearPairInput member at fault ("z1", "module",
/// "centre_distance", ...) so that front ends can name their own option or key.
class GeometryError : public std::invalid_argument {
 public:
  GeometryError(std::string field, const std::string& message);
  const std::string& field() const noexcept { return field_; }

 private:
  std::string field_;
};

enum class Mounting { zero, v_zero, v };           ///< x1 = x2 = 0; x1 + x2 = 0; x1 + x2 != 0
/// How the shift sum of a given centre distance is split: x1 given; balanced maximum specific
/// sliding; proportional to the teeth; min_shift: the smallest shifts (x1 and x2 as equal as
/// the sum allows, i.e. the least max |x_i|) that keep both gears above the undercut limit
/// GearPairInput::undercut_limit.
enum class ShiftSplit { user_x1, balanced_sliding, proportional, min_shift };
/// Which undercut limit the min_shift split keeps: ISO x_min (no undercut by the rack with its
/// tip radius) or the practical limit x'_min (slight undercut accepted, DIN 3960; course notes).
enum class UndercutLimit { iso, practical };
enum class ModuleSystem { normal, transverse };    ///< how `module` and `pressure_angle` are given

/// "zero", "V-0", "V".
const char* to_string(Mounting mounting);
const char* to_string(ShiftSplit split);
const char* to_string(UndercutLimit limit);  ///< "ISO", "practical"

struct GearPairInput {
  int z1 = 0;                 ///< teeth of gear 1 (pinion), > 0
  int z2 = 0;                 ///< teeth of gear 2 (wheel or ring), > 0
  bool internal = false;      ///< gear 2 is an internal gear (ring), needs z2 > z1
  double module = 0;          ///< mm: m_n (normal system) or m_t (transverse system), > 0
  double pressure_angle = 0.3490658503988659;  ///< rad: alpha_n or alpha_t, in (0, 45 deg)
  double helix_angle = 0;     ///< rad: beta at the reference circle, |beta| < 45 deg
  ModuleSystem system = ModuleSystem::normal;
  double h_aP = 1.0, h_fP = 1.25, rho_fP = 0.38;  ///< basic rack coefficients (ISO 53 A)
  /// The tool of each gear when the two are cut by different tools: its basic rack coefficients
  /// h_aP*, h_fP*, rho_fP* (its alpha_P is ignored: the pair's pressure angle serves both);
  /// empty: h_aP, h_fP, rho_fP above. Validated like the shared rack (field "tool1", "tool2").
  std::array<std::optional<Rack>, 2> tool;

  double x1 = 0, x2 = 0;                 ///< profile shift coefficients, used if no centre distance
  std::optional<double> centre_distance; ///< mm, > 0; if set the shift sum follows from it
  ShiftSplit split = ShiftSplit::balanced_sliding;  ///< with centre_distance; user_x1 keeps x1
  UndercutLimit undercut_limit = UndercutLimit::iso;  ///< the limit ShiftSplit::min_shift keeps
  bool apply_tip_shortening = true;

  double face_width = 0;       ///< mm, b >= 0 (overlap ratio; 0 gives eps_beta = 0)
  /// Face width of each gear, mm, when they differ (empty: face_width), and the axial offset of
  /// the middle of gear 2's face from gear 1's, mm. The mesh then has the common width of both
  /// faces (common_face_width). Fields "face_width1", "face_width2", "face_offset".
  std::array<std::optional<double>, 2> face_widths;
  double face_offset = 0;
  double A_sn1 = 0, A_sn2 = 0; ///< normal tooth thickness allowances, mm (<= 0: thinner teeth)
  double A_a = 0;              ///< centre distance deviation, mm (> 0: shafts further apart)
  std::optional<double> backlash_target;  ///< normal backlash j_bn, mm; sets A_sn1 = A_sn2
  std::optional<double> pin_diameter1, pin_diameter2;  ///< mm; default: contact at d + 2 x m_n
  /// Tip diameter of each gear as made, mm (magnitude; empty: from the rack, with tip shortening).
  /// Contact ratio, clearances, sliding and tip thickness use it. Field "d_a1", "d_a2".
  std::array<std::optional<double>, 2> d_a;
  /// Root diameter of each gear as made, mm (magnitude; empty: what the tool cuts,
  /// d + 2 m_n (x - h_fP*)). A value that differs from what the tool cuts by more than 1 um is a
  /// warning: the tool data then do not describe the gear. Field "d_f1", "d_f2".
  std::array<std::optional<double>, 2> d_f;
};

/// Face width of gear i (0 or 1), mm: face_widths[i] or face_width.
double face_width_of(const GearPairInput& in, int i);

/// The common face width of the pair, mm: the overlap of both faces (>= 0); face_width when the
/// gears have one width and no offset. Overlap ratio and load capacity use it (ISO 6336: b).
double common_face_width(const GearPairInput& in);

/// Face width of gear i for its tooth root stress, mm (ISO 6336-3, DIN 3990-3: a
/// wider face carries at most one module m_n beyond the mate's on each side): the common width
/// plus, on each side, what the gear's face extends beyond the mate's, at most m_n.
double root_face_width(const GearPairInput& in, int i, double m_n);

/// The basic rack of the tool that cuts gear i (0 or 1): GearPairInput::tool[i] or the pair's
/// h_aP, h_fP, rho_fP, with alpha_P = alpha_n.
Rack tool_rack(const GearPairInput& in, int i, double alpha_n);

/// Hand of the helix of gear i (0 or 1). Sign convention of GearPairInput::helix_angle: it is
/// gear 1's, positive for a right-hand helix; gear 2 of an external pair has the opposite hand,
/// a ring the same hand as its pinion.
enum class HelixHand { spur, right, left };
HelixHand helix_hand(const GearPairInput& in, int i);
const char* to_string(HelixHand hand);  ///< "spur", "right", "left"

/// One gear of the table. Diameters are positive magnitudes.
struct GearResult {
  int z = 0;              ///< positive count
  bool internal = false;
  double x = 0;           ///< profile shift coefficient (ISO sign)
  double shift_mm = 0;    ///< x m_n
  double m_n = 0, m_t = 0;
  double alpha_n = 0, alpha_t = 0, beta = 0, beta_b = 0;
  double d = 0, d_b = 0, d_w = 0, d_a = 0, d_f = 0;
  double p_t = 0, p_n = 0, p_bt = 0, p_en = 0;  ///< pitches: transverse, normal, base transverse, base normal
  double s_t = 0, s_n = 0, e_t = 0, e_n = 0;    ///< reference-circle thickness and space width (nominal)
  double s_an = 0;        ///< normal tooth thickness at the tip circle (nominal)
  double z_n = 0;         ///< virtual number of teeth
  double x_min = 0;       ///< undercut limit (external gears; NaN for a ring)
  double x_min_practical = 0;  ///< practical undercut limit (DIN 3960, (14 - z)/17 at 20 deg; NaN for a ring)
  double d_Ff = 0;        ///< generated form (start of involute) diameter; NaN for a ring
  double A_sn = 0;        ///< normal thickness allowance used for measurements and backlash
  int k_span = 0;         ///< teeth spanned (0 for a ring: no span measurement)
  double W_k = 0;         ///< span over k_span teeth, nominal (NaN for a ring)
  double W_k_actual = 0;  ///< span with the allowance A_sn
  double pin_diameter = 0;
  double M_d = 0;         ///< over (external) or between (ring) pins/balls, nominal
  double M_d_actual = 0;  ///< with the allowance A_sn
  double chordal_s = 0, chordal_h = 0;  ///< chordal thickness and height at the reference circle (normal section)
};

struct PairResult {
  double a = 0;           ///< working centre distance (positive)
  double a_d = 0;         ///< reference centre distance (positive)
  double alpha_wt = 0;    ///< working transverse pressure angle
  double sum_x = 0;       ///< x1 + x2
  double y = 0;           ///< centre distance modification coefficient (a - a_d)/m_n (signed ISO)
  double k = 0;           ///< tip shortening coefficient x1 + x2 - y
  bool tip_shortened = false;
  Mounting mounting = Mounting::zero;
  ShiftSplit split = ShiftSplit::user_x1;  ///< how x1, x2 were obtained (user_x1 when given)
  double u = 0;           ///< gear ratio z2/z1
  double eps_alpha = 0, eps_beta = 0, eps_gamma = 0;
  double c1 = 0;          ///< clearance tip of gear 1 - root of gear 2
  double c2 = 0;          ///< clearance tip of gear 2 - root of gear 1
  double zeta1 = 0, zeta2 = 0;  ///< maximum specific sliding at the root of gear 1 / gear 2
  double j_wt = 0;        ///< circumferential backlash on the working circle (allowances + A_a)
  double j_bn = 0;        ///< normal backlash
  double A_a = 0;
};

struct GearPairResult {
  std::array<GearResult, 2> gear;
  PairResult pair;
  std::vector<std::string> warnings;  ///< engineering problems (undercut, interference, ...)
};

/// The complete table. @throws GeometryError on invalid input (naming the field).
GearPairResult compute_gear_pair(const GearPairInput& input);

// ---- pair formulas (signed ISO 21771 convention: z2 < 0 for internal pairs) ----

/// Reference centre distance a_d = m_t (z1 + z2) / 2.
double reference_centre_distance(int z1, int z2, double m_t);

/// Working transverse pressure angle from the shift sum:
/// inv alpha_wt = inv alpha_t + 2 tan(alpha_n) (x1 + x2) / (z1 + z2).
/// @throws std::domain_error if the right-hand side is negative (shift sum too negative).
double working_pressure_angle(double alpha_t, double alpha_n, int z1, int z2, double sum_x);

/// Working transverse pressure angle from the centre distance: cos alpha_wt = a_d cos(alpha_t) / a.
/// @throws std::domain_error if |a| < |a_d| cos alpha_t (the base circles would overlap).
double working_pressure_angle_for_centre_distance(double a_d, double alpha_t, double a);

/// Centre distance a = a_d cos(alpha_t) / cos(alpha_wt).
double centre_distance(double a_d, double alpha_t, double alpha_wt);

/// Shift sum for a working pressure angle: x1 + x2 = (z1 + z2)(inv alpha_wt - inv alpha_t) / (2 tan alpha_n).
double sum_of_shifts(int z1, int z2, double alpha_t, double alpha_n, double alpha_wt);

/// Centre distance modification coefficient y = (a - a_d) / m_n.
double centre_distance_modification(double a, double a_d, double m_n);

/// Tip shortening coefficient k = x1 + x2 - y.
double tip_shortening(double sum_x, double y);

/// Mounting type from the shifts (tolerance 1e-9).
Mounting mounting_type(double x1, double x2);

/// Transverse contact ratio eps_alpha = (z1 (tan a_a1 - tan a_wt) + z2 (tan a_a2 - tan a_wt)) / (2 pi),
/// alpha_ai the pressure angles at the tip circles.
double transverse_contact_ratio(int z1, int z2, double alpha_a1, double alpha_a2, double alpha_wt);

/// The same ratio as length of the path of contact over the transverse base pitch:
/// eps_alpha = (rho_a1 + rho_a2 - a sin alpha_wt) / p_bt, rho_ai = sqrt(r_ai^2 - r_bi^2) (signed
/// like r_bi for a ring, a negative for internal pairs).
double transverse_contact_ratio_from_lengths(double rho_a1, double rho_a2, double a, double alpha_wt, double p_bt);

/// Overlap ratio eps_beta = b sin|beta| / (pi m_n).
double overlap_ratio(double b, double beta, double m_n);

/// Bottom clearance between the tip of gear i and the root of gear j: c = a - r_ai - r_fj (signed values).
double tip_clearance(double a, double d_ai, double d_fj);

/// Maximum specific sliding at the root of gear i (contact with the tip of gear j):
/// zeta_i = 1 - (rho_j,tip / rho_i,root)(z_i / z_j), rho_j,tip = r_bj tan alpha_aj,
/// rho_i,root = a sin(alpha_wt) - rho_j,tip (signed values). -infinity when the contact reaches
/// the base circle of gear i.
double max_specific_sliding(int z_i, int z_j, double d_bj, double d_aj, double a, double alpha_wt);

/// Sum of tooth numbers that fits centre distance a at module m_n without shift:
/// z1 + z2 = 2 a cos(beta) / m_n (not rounded; the caller checks it is an integer).
double teeth_sum_for_centre_distance(double a, double m_n, double beta);

}  // namespace gearkit::gear
