#pragma once
// Straight, Zerol and spiral bevel gear pairs (no offset, i.e. not hypoid): the cone geometry of
// ISO 23509 for any shaft angle, the tooth proportions of the Gleason system (unequal addendum,
// KHK gear technical reference, "Gleason straight bevel gears") or of ISO 23509 (profile shift at
// the mean point), the virtual cylindrical gears of ISO 10300-1 with their contact ratio and an
// undercut check, and the forces at the mean point of the face width.
// Lengths in mm, angles in rad, torques in N m, forces in N.
//
// Conventions (docs/bevel.md):
// - Gear 1 is the pinion of the table (any tooth count; usually z1 <= z2); gear 2 the wheel.
// - The pitch apex is the crossing point of the axes (no hypoid offset). Each gear's axial
//   direction points from the apex into its body, towards its back (large end).
// - Hand (AGMA 1012): a gear is right-hand when the outer half of a tooth is inclined clockwise
//   from the axial plane through the tooth's mid-point, seen by an observer looking at the face
//   of the gear (from the apex side). Gear 2 has the opposite hand of gear 1.
// - Sense of rotation: clockwise or counter-clockwise seen from the gear's back (large end),
//   looking towards the apex. Mating bevel gears seen so always turn opposite ways.
// - Forces on each gear at its mean point: F_t along or against its rotation (magnitude), F_r
//   positive towards its own axis, F_a positive along its axis away from the apex (out of mesh).
#include <gearkit/gear/gear_pair.hpp>  // GeometryError

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::gear {

enum class BevelType { straight, zerol, spiral };
/// Gleason: outer-end proportions in m_et (working depth 2.000 m_et, whole depth 2.188 m_et for
/// straight and Zerol; 1.700 and 1.888 for spiral), addendum split x_he by the Gleason formula.
/// iso23509: mean-point proportions in m_mn (h_aP* = 1, h_fP* = 1.25), profile shift x_hm.
enum class BevelSystem { gleason, iso23509 };
/// standard: tip and root cones both through the pitch apex (depth tapers with the cone distance).
/// constant_clearance: root cones through the apex, each tip cone parallel to the mate's root cone
/// (theta_a1 = theta_f2; Gleason/KHK standard-depth teeth). uniform: constant depth (theta = 0).
enum class DepthTaper { standard, constant_clearance, uniform };
enum class SpiralHand { right, left };
enum class Rotation { ccw, cw };  ///< seen from the gear's back (large end) towards the apex

const char* to_string(BevelType type);     ///< "straight", "Zerol", "spiral"
const char* to_string(BevelSystem system);  ///< "Gleason", "ISO 23509"
const char* to_string(DepthTaper taper);    ///< "standard", "constant clearance", "uniform"
const char* to_string(SpiralHand hand);     ///< "right", "left"
const char* to_string(Rotation rotation);   ///< "ccw", "cw"

// --- formula functions (one per equation) --------------------------------------------------------

/// Pitch cone angle of gear 1: tan delta_1 = sin Sigma / (cos Sigma + z2/z1) (ISO 23509, pitch
/// cone angles; KHK Table "Gleason straight bevel gears" No. 6). delta_2 = Sigma - delta_1.
double pitch_cone_angle1(int z1, int z2, double Sigma);

/// Outer cone distance R_e = d_e / (2 sin delta) (the same for both gears; ISO 23509).
double outer_cone_distance(double d_e, double delta);

/// Mean cone distance R_m = R_e - b/2 (ISO 23509).
double mean_cone_distance(double R_e, double b);

/// Mean transverse module m_mt = m_et R_m / R_e (ISO 23509, ISO 10300-1).
double mean_transverse_module(double m_et, double R_m, double R_e);

/// Mean normal module m_mn = m_mt cos beta_m (ISO 23509, ISO 10300-1).
double mean_normal_module(double m_mt, double beta_m);

/// Virtual (equivalent) gear ratio u_v = z2 cos delta_1 / (z1 cos delta_2): the ratio of the
/// virtual cylindrical gears, which the Gleason addendum formula uses (= u^2 at Sigma = 90 deg).
double virtual_gear_ratio(int z1, int z2, double delta1, double delta2);

/// Gleason addendum modification coefficient of gear 1 at the outer end (x_he2 = -x_he1), from
/// the Gleason wheel addendum: straight and Zerol h_ae2 = m_et (0.54 + 0.46 / u_v) with
/// h_a* = 1, i.e. x_he1 = 0.46 (1 - 1/u_v) (KHK Table "Gleason straight bevel gears" No. 11);
/// spiral h_ae2 = m_et (0.46 + 0.39 / u_v) with h_a* = 0.85, i.e. x_he1 = 0.39 (1 - 1/u_v)
/// (Gleason spiral bevel system, working depth 1.700 m_et).
double gleason_addendum_shift(BevelType type, double u_v);

/// Dedendum (or addendum) angle of a cone through the pitch apex: theta = atan(h / R), h and R
/// taken at the same section (outer end: h_fe and R_e, KHK No. 14; mean point: h_fm and R_m).
double cone_angle_of_depth(double h, double R);

/// Outer tip diameter d_ae = d_e + 2 h_ae cos delta (ISO 23509; KHK No. 18).
double outer_tip_diameter(double d_e, double h_ae, double delta);

/// Outer crown to crossing point t_xo = R_e cos delta - h_ae sin delta, the axial distance from
/// the crossing point of the axes (= pitch apex) to the crown (KHK No. 19, "X").
double crown_to_crossing_point(double R_e, double h_ae, double delta);

/// Virtual number of teeth in the transverse section z_v = z / cos delta (ISO 10300-1).
double virtual_teeth(int z, double delta);

/// Virtual number of teeth in the normal section z_vn = z_v / (cos^2 beta_vb cos beta_m),
/// sin beta_vb = sin beta_m cos alpha_n (ISO 10300-1).
double virtual_teeth_normal(double z_v, double beta_m, double alpha_n);

/// Transverse contact ratio of the virtual cylindrical gears at the mean point (ISO 10300-1):
/// eps_va = (sqrt(r_va1^2 - r_vb1^2) + sqrt(r_va2^2 - r_vb2^2) - a_v sin alpha_vt) / (pi m_mt cos alpha_vt),
/// d_va = d_v + 2 h_am, d_vb = d_v cos alpha_vt, a_v = (d_v1 + d_v2)/2 (through
/// transverse_contact_ratio_from_lengths of the cylindrical code).
double virtual_contact_ratio(double d_v1, double d_v2, double h_am1, double h_am2, double alpha_vt, double m_mt);

/// Overlap ratio of the virtual gears eps_vb = b sin beta_m / (pi m_mn) (ISO 10300-1).
double virtual_overlap_ratio(double b, double beta_m, double m_mn);

/// Tangential force at the mean point F_mt = 2000 T / d_m (N, T in N m, d_m in mm; ISO 10300-1).
double bevel_tangential_force(double T, double d_m);

/// Axial force on a gear (positive away from the apex), Gleason/Shigley form:
/// F_a = F_t / cos beta (tan alpha_n sin delta +- sin beta_s cos delta), + for the driving gear,
/// - for the driven one. beta_s is the signed mean spiral angle: > 0 when the outer end of a
/// tooth leads in the direction of motion (see spiral_sign). beta_s = 0 gives the straight-bevel
/// F_a = F_t tan alpha sin delta (Budynas and Nisbett, Shigley's MED, ch. 13, bevel force analysis).
double bevel_axial_force(double F_t, double alpha_n, double beta_s, double delta, bool driving);

/// Radial force on a gear (positive towards its axis):
/// F_r = F_t / cos beta (tan alpha_n cos delta -+ sin beta_s sin delta), - for the driving gear,
/// + for the driven one; beta_s = 0 gives F_r = F_t tan alpha cos delta (same source).
double bevel_radial_force(double F_t, double alpha_n, double beta_s, double delta, bool driving);

/// +1 when the outer end of gear 1's teeth leads in the direction of motion, -1 when it trails:
/// right hand turning counter-clockwise (seen from the back), or left hand turning clockwise,
/// leads. The same sign holds for gear 2 (opposite hand, opposite sense).
int spiral_sign(SpiralHand hand1, Rotation rotation1);

// --- the pair --------------------------------------------------------------------------------------

struct BevelPairInput {
  int z1 = 0, z2 = 0;          ///< teeth, > 0
  double m_et = 0;             ///< mm: outer transverse module, > 0
  double Sigma = 1.5707963267948966;  ///< rad: shaft angle, 0 < Sigma < 180 deg (both delta < 90 deg)
  double alpha_n = 0.3490658503988659; ///< rad: normal pressure angle, (0, 45 deg)
  double b = 0;                ///< mm: face width, 0 < b < R_e
  BevelType type = BevelType::straight;
  double beta_m = 0;           ///< rad: mean spiral angle (0 for straight and Zerol), 0 < beta_m < 60 deg for spiral
  SpiralHand hand1 = SpiralHand::left;  ///< hand of gear 1 (spiral bevels)
  BevelSystem system = BevelSystem::gleason;
  std::optional<double> x1;    ///< Gleason: x_he1 at the outer end; ISO 23509: x_hm1 at the mean point. Default: Gleason formula / 0
  DepthTaper taper = DepthTaper::constant_clearance;
};

struct BevelGearResult {
  int z = 0;
  double delta = 0;            ///< rad: pitch cone angle
  double d_e = 0, d_m = 0, d_i = 0;  ///< mm: outer, mean and inner pitch diameters
  double x_he = 0;             ///< addendum modification coefficient at the outer end (in m_et)
  double x_hm = 0;             ///< profile shift coefficient at the mean point (in m_mn, about the mean working depth)
  double h_ae = 0, h_fe = 0;   ///< mm: outer addendum and dedendum
  double h_am = 0, h_fm = 0;   ///< mm: mean addendum and dedendum
  double h_ai = 0, h_fi = 0;   ///< mm: inner addendum and dedendum
  double theta_a = 0, theta_f = 0;   ///< rad: addendum and dedendum angles
  double delta_a = 0, delta_f = 0;   ///< rad: face (tip) and root cone angles
  double d_ae = 0, d_fe = 0;   ///< mm: outer tip and root diameters
  double d_ai = 0;             ///< mm: inner tip diameter
  double t_xo = 0, t_xi = 0;   ///< mm: outer / inner crown to crossing point (axial)
  double b_x = 0;              ///< mm: axial length of the tip cone over the face width (KHK X_b)
  double t_zm = 0;             ///< mm: mean pitch point to crossing point, R_m cos delta (axial)
  double z_v = 0, z_vn = 0;    ///< virtual teeth, transverse and normal section
  double d_v = 0, d_va = 0, d_vb = 0;  ///< mm: virtual reference, tip and base diameters
  double x_min = 0;            ///< undercut limit of x_hm on the virtual gear (generating flank only)
  SpiralHand hand = SpiralHand::left;
};

struct BevelPairResult {
  double u = 0, u_v = 0;       ///< ratio z2/z1 and virtual ratio
  double R_e = 0, R_m = 0, R_i = 0;  ///< mm: outer, mean and inner cone distances
  double m_mt = 0, m_mn = 0, m_it = 0;  ///< mm: mean transverse, mean normal, inner transverse module
  double p_et = 0;             ///< mm: outer transverse pitch pi m_et
  double alpha_vt = 0;         ///< rad: transverse pressure angle of the virtual gears
  double beta_vb = 0;          ///< rad: base spiral angle of the virtual gears
  double h_mw = 0;             ///< mm: mean working depth h_am1 + h_am2
  double c = 0;                ///< mm: clearance at the outer end
  double a_v = 0;              ///< mm: centre distance of the virtual gears
  double eps_va = 0, eps_vb = 0, eps_vg = 0;  ///< virtual contact, overlap and total contact ratio
  std::array<BevelGearResult, 2> gear;
  std::vector<std::string> warnings;  ///< engineering problems (undercut, face width, contact ratio)
};

/// The geometry table of the pair.
/// @throws GeometryError naming the input field ("z1", "z2", "module", "shaft_angle",
///         "pressure_angle", "face_width", "spiral_angle", "x1") for input outside the stated
///         ranges, and "x1" when an addendum or dedendum comes out <= 0.
BevelPairResult compute_bevel_pair(const BevelPairInput& input);

struct BevelLoad {
  double T = 0;                ///< N m: torque on the driving gear, > 0
  int driver = 1;              ///< 1 or 2: the gear the torque drives
  Rotation rotation1 = Rotation::ccw;  ///< sense of gear 1 (seen from its back)
};

struct BevelGearForces {
  bool driving = false;
  Rotation rotation = Rotation::ccw;
  double T = 0;                ///< N m: torque on the gear (driver's input, driven's output)
  double F_t = 0, F_r = 0, F_a = 0, F_n = 0;  ///< N: see the conventions above; F_n the normal tooth force
};

struct BevelForces {
  double beta_s = 0;           ///< rad: signed spiral angle (spiral_sign * beta_m)
  std::array<BevelGearForces, 2> gear;
};

/// Forces of the pair at the mean point (no friction).
/// @throws GeometryError ("torque") when T <= 0 or not finite, ("driver") unless 1 or 2.
BevelForces bevel_forces(const BevelPairInput& input, const BevelPairResult& table, const BevelLoad& load);

}  // namespace gearkit::gear
