#pragma once
// A cylindrical worm and its wheel, shaft angle 90 deg, axial module system (DIN 3975-1,
// ISO/TR 10828, ISO 1122-1 symbols): lead angle, pitches, diameters, the wheel's profile shift for
// a centre distance, face width and worm length, sliding velocity, efficiency in both directions,
// self-locking, and the forces at the mesh with friction. Lengths in mm, angles in rad, speeds in
// 1/min, velocities in m/s, torques in N m, forces in N, power in W.
//
// Conventions (docs/gear-types.md):
// - Gear 1 is the worm (z1 threads), gear 2 the wheel (z2 teeth); u = z2 / z1.
// - The flank form names the section in which the given pressure angle alpha_0 holds: ZA the axial
//   section (alpha_x = alpha_0), ZN, ZI and ZK the normal section (alpha_n = alpha_0; for ZK the
//   tool's angle, approximately the flank's). tan alpha_n = tan alpha_x cos gamma links them.
// - The wheel's pitch circle is its reference circle d2 = z2 m_x; the worm rolls on it with its
//   working cylinder d_w1 = 2 a - d2 = d_m1 + 2 x2 m_x. Efficiency and forces are taken at that
//   pitch point (lead angle gamma_w), so that the power balance holds exactly; without profile
//   shift gamma_w = gamma_m.
// - Frame of the forces: origin at the wheel centre, wheel axis +y, worm axis parallel to +x
//   through (0, 0, a); the pitch point lies at (0, 0, d2/2). n1 > 0 turns the worm about +x (right-
//   hand rule); a right-hand worm then turns the wheel about -y (omega2 = -omega1 z1/z2 about +y),
//   a left-hand worm about +y.
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::gear {

enum class WormFlank { ZA, ZN, ZI, ZK };
const char* to_string(WormFlank flank);  ///< "ZA", "ZN", "ZI", "ZK"

// ---- formulas (DIN 3975-1 / ISO/TR 10828) ----

/// Lead angle at the worm's reference (mean) cylinder: tan gamma_m = z1 m_x / d_m1 = z1 / q.
double worm_lead_angle(int z1, double m_x, double d_m1);

/// Axial pitch p_x = pi m_x.
double worm_axial_pitch(double m_x);

/// Lead p_z = z1 p_x.
double worm_lead(int z1, double p_x);

/// Normal module m_n = m_x cos gamma.
double worm_normal_module(double m_x, double gamma);

/// Axial pressure angle from the normal one: tan alpha_x = tan alpha_n / cos gamma.
double worm_axial_pressure_angle(double alpha_n, double gamma);

/// Normal pressure angle from the axial one: tan alpha_n = tan alpha_x cos gamma.
double worm_normal_pressure_angle(double alpha_x, double gamma);

/// Base lead angle of an involute helicoid (ZI) worm: cos gamma_b = cos gamma cos alpha_n.
double worm_base_lead_angle(double gamma, double alpha_n);

/// Base diameter of a ZI worm, mm: d_b1 = d_m1 tan gamma / tan gamma_b (the lead is the same on
/// every cylinder: pi d tan gamma = p_z).
double worm_base_diameter(double d_m1, double gamma, double gamma_b);

/// Worm tip diameter d_a1 = d_m1 + 2 h_aP* m_x, root diameter d_f1 = d_m1 - 2 h_fP* m_x.
double worm_tip_diameter(double d_m1, double h_aP, double m_x);
double worm_root_diameter(double d_m1, double h_fP, double m_x);

/// Wheel reference diameter d2 = z2 m_x.
double wheel_reference_diameter(int z2, double m_x);

/// Centre distance a = (d_m1 + d2) / 2 + x2 m_x.
double worm_centre_distance(double d_m1, double d2, double x2, double m_x);

/// The wheel's profile shift coefficient for a centre distance: x2 = (a - (d_m1 + d2) / 2) / m_x.
double wheel_shift_for_centre_distance(double a, double d_m1, double d2, double m_x);

/// Wheel tip (throat) diameter in its mid-plane d_a2 = d2 + 2 m_x (h_aP* + x2), root diameter
/// d_f2 = d2 - 2 m_x (h_fP* - x2).
double wheel_tip_diameter(double d2, double h_aP, double x2, double m_x);
double wheel_root_diameter(double d2, double h_fP, double x2, double m_x);

/// Throat radius of the wheel rim (DIN 3975 r_k, KHK "throat surface radius"): r_k = a - d_a2 / 2
/// (= d_m1/2 - h_aP* m_x).
double wheel_throat_radius(double a, double d_a2);

/// Outside diameter of the wheel rim, recommendation d_e2 = d_a2 + m_x (Niemann/Winter,
/// Maschinenelemente III: the rim's corners turned off about one module above the throat).
double wheel_outside_diameter(double d_a2, double m_x);

/// Wheel face width, recommendation b2 = 0.45 (d_a1 + 4 m_x) (Niemann/Winter).
double wheel_face_width(double d_a1, double m_x);

/// Shortest worm thread that meets the wheel everywhere in its mid-plane, mm: the chord of the
/// wheel's outside circle d_e2 along the worm's tip cylinder, b1 = 2 sqrt((d_e2/2)^2 - (a - d_a1/2)^2)
/// (geometric; gearkit recommends one axial pitch more for the thread's run-out).
double worm_length(double d_e2, double a, double d_a1);

/// Worm working (pitch) diameter d_w1 = 2 a - d2, and the lead angle on it tan gamma_w = z1 m_x / d_w1.
double worm_working_diameter(double a, double d2);

/// Peripheral velocity of a diameter d (mm) at n (1/min), m/s: v = pi d n / 60000 (magnitude).
double peripheral_velocity(double d, double n);

/// Sliding velocity at the pitch point v_g = v1 / cos gamma (m/s).
double worm_sliding_velocity(double v1, double gamma);

/// Friction angle of the mesh tan rho' = mu / cos alpha_n (DIN 3975; Shigley/Budynas eq. 13-46).
double friction_angle(double mu, double alpha_n);

/// Friction coefficient of a case-hardened steel worm on a bronze wheel from the sliding velocity
/// v_g (m/s), ANSI/AGMA 6034-B92 as printed in Shigley/Budynas, Mechanical Engineering Design,
/// worm gearing (V_s in ft/min = v_g / 0.00508): f = 0.150 at V_s = 0; 0.124 exp(-0.074 V_s^0.645) for V_s <= 10 ft/min;
/// 0.103 exp(-0.110 V_s^0.450) + 0.012 above.
/// @throws std::domain_error if v_g < 0 or not finite.
double worm_friction_coefficient_agma(double v_g);

/// Efficiency with the worm driving eta_12 = tan gamma / tan(gamma + rho') (DIN 3975; Niemann).
double worm_efficiency_worm_driving(double gamma, double rho);

/// Efficiency with the wheel driving eta_21 = tan(gamma - rho') / tan gamma; <= 0 means the wheel
/// cannot drive the worm (self-locking).
double worm_efficiency_wheel_driving(double gamma, double rho);

// ---- the table ----

struct WormInput {
  int z1 = 0;                    ///< threads of the worm, 1..10
  int z2 = 0;                    ///< teeth of the wheel, >= 1 (>= 17 usual)
  double m_x = 0;                ///< axial module, mm, > 0
  WormFlank flank = WormFlank::ZI;
  double alpha_0 = 0.3490658503988659;  ///< pressure angle of the flank form's section, rad (20 deg)
  std::optional<double> q;       ///< diameter quotient q = d_m1 / m_x (one of q, d_m1)
  std::optional<double> d_m1;    ///< worm reference diameter, mm
  bool right_hand = true;        ///< hand of the worm's thread (the wheel has the same hand)
  double h_aP = 1.0, h_fP = 1.25;  ///< addendum and dedendum coefficients (of m_x), worm and wheel
  double x2 = 0;                 ///< wheel profile shift coefficient (unless a is given)
  std::optional<double> centre_distance;  ///< a, mm: sets x2
  std::optional<double> mu;      ///< friction coefficient (running); default from v_g (AGMA)
  double mu_static = 0.15;       ///< friction coefficient at rest (AGMA 6034 at v_g = 0)
  double n1 = 0;                 ///< worm speed, 1/min, signed about the worm axis (0: at rest)
};

struct WormResult {
  double q = 0, d_m1 = 0, gamma = 0, p_x = 0, p_z = 0, m_n = 0, alpha_x = 0, alpha_n = 0;
  double gamma_b = 0, d_b1 = 0;  ///< ZI only (NaN otherwise)
  double d_a1 = 0, d_f1 = 0, d2 = 0, d_a2 = 0, d_f2 = 0, d_e2 = 0, r_k = 0;
  double a = 0, x2 = 0, d_w1 = 0, gamma_w = 0, u = 0;
  double b2 = 0, b1 = 0;         ///< recommended wheel face width, shortest worm thread
  double wheel_sense = 0;        ///< omega2 / omega1 about +y / +x: -z1/z2 (right hand), +z1/z2 (left)
  double n1 = 0, n2 = 0;         ///< worm speed about +x (as given), wheel speed about +y, 1/min
  double v1 = 0, v2 = 0, v_g = 0;  ///< pitch-point velocities of worm and wheel, sliding velocity (m/s)
  double mu = 0, rho = 0, rho_static = 0;
  bool mu_from_velocity = false; ///< mu from the AGMA relation of v_g (not given)
  double eta_12 = 0, eta_21 = 0; ///< worm driving, wheel driving (<= 0: self-locking)
  bool self_locking_static = false, self_locking_dynamic = false;
  std::vector<std::string> warnings;
};

/// The table. @throws GeometryError (gear_pair.hpp) naming the WormInput member at fault ("z1",
/// "z2", "m_x", "alpha_0", "q", "d_m1", "centre_distance", "mu", "mu_static", "n1", ...).
WormResult compute_worm(const WormInput& in);

/// Forces at the mesh. `torque` (N m, > 0) acts on the worm (on_worm true) or the wheel; the
/// driver is the worm (worm_drives) or the wheel. Magnitudes (Shigley/Budynas eq. 13-43 with
/// tan rho' = f / cos alpha_n), worm driving: F_t1 = 2000 T1 / d_w1 = F_a2,
/// F_t2 = F_t1 / tan(gamma_w + rho') = F_a1, F_r = F_t1 tan alpha_n cos rho' / sin(gamma_w + rho');
/// wheel driving: F_t1 = F_t2 tan(gamma_w - rho'), F_r = F_t2 tan alpha_n cos rho' / cos(gamma_w - rho').
/// Vectors in the frame of the header; on_worm = -on_wheel. With the speed n1 of the table:
/// P_in = P_out + P_loss, P_loss = mu N v_g.
struct WormForces {
  bool worm_drives = true;
  double T1 = 0, T2 = 0;          ///< torques on worm and wheel, N m (magnitudes)
  double F_t1 = 0, F_a1 = 0, F_r = 0, F_t2 = 0, F_a2 = 0, F_n = 0;  ///< N; F_n the normal force
  std::array<double, 3> on_worm{}, on_wheel{};
  double P_in = 0, P_out = 0, P_loss = 0;  ///< W (0 at rest)
};
/// @throws std::domain_error if torque <= 0 or the wheel drives a self-locking mesh (eta_21 <= 0).
WormForces worm_forces(const WormResult& w, double torque, bool on_worm, bool worm_drives);

}  // namespace gearkit::gear
