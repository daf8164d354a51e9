#pragma once
// Scuffing load capacity of cylindrical gears by the integral temperature method, ISO/TS 6336-21
// (formerly ISO/TR 13989-2:2000, the method of DIN 3990-4), one function per formula, and the
// oil properties it needs. Equation numbers are those of ISO/TR 13989-2:2000 (the edition whose
// published worked values, a KISSsoft 03/2017 report, the tests reproduce; docs/rating.md).
// Temperatures in deg C (differences in K), lengths in mm, loads per width in N/mm, speeds in
// m/s, viscosity in mm^2/s (kinematic) or mPa s (dynamic), roughness in um, angles in rad.
//
// Index 1 is the pinion (the smaller external gear; the pinion of an internal pair), 2 the wheel.
// Internal pairs use signed values as the standard does: u = z_2/z_1 < 0, a < 0, rho_E2 < 0.
#include <gearkit/gear/materials.hpp>

#include <array>

namespace gearkit::gear::iso6336 {

/// The base oil (ISO/TR 13989-2 5.1, the lubricant factor X_L).
enum class OilBase {
  mineral,                       ///< X_L = 1.0
  polyalphaolefin,               ///< PAO, X_L = 0.8
  polyglycol_water_soluble,      ///< PAG, water soluble, X_L = 0.6
  polyglycol_not_water_soluble,  ///< PAG, not water soluble, X_L = 0.7
  phosphate_ester,               ///< X_L = 1.3
  traction_fluid,                ///< X_L = 1.5
};
const char* to_string(OilBase base);  ///< "mineral", "pao", "pag-water-soluble", "pag", "phosphate-ester", "traction"
constexpr std::array<OilBase, 6> kOilBases = {OilBase::mineral, OilBase::polyalphaolefin, OilBase::polyglycol_water_soluble,
                                              OilBase::polyglycol_not_water_soluble, OilBase::phosphate_ester, OilBase::traction_fluid};

/// How the mesh is lubricated (the lubrication factor X_S of the bulk temperature, Eq. 20).
enum class Lubrication {
  dip,       ///< dip (splash) lubrication, X_S = 1.0
  spray,     ///< injection (spray) lubrication, X_S = 1.2
  immersed,  ///< gears immersed in oil with ample cooling, X_S = 0.2
};
const char* to_string(Lubrication method);  ///< "dip", "spray", "immersed"
constexpr std::array<Lubrication, 3> kLubrications = {Lubrication::dip, Lubrication::spray, Lubrication::immersed};

/// Lubricant factor X_L of the base oil (5.1).
double lubricant_factor_X_L(OilBase base);

/// Lubrication factor X_S (Eq. 20): 1.0 dip, 1.2 spray, 0.2 immersed.
double lubrication_factor_X_S(Lubrication method);

/// Welding factor X_W of a material class (Table 3): 1.5 for the nitrided and nitrocarburized
/// classes, 1.0 for the others (through-hardened steel; case-carburized steel of average retained
/// austenite, 10 % to 20 %); the test gears' X_WT = 1, so X_WrelT = X_W.
double welding_factor_X_W(MaterialClass kind);

/// Helical load factor K_Bgamma (Eq. 5): 1 for eps_gamma <= 2, 1 + 0.2 sqrt((eps_gamma - 2)(5 -
/// eps_gamma)) up to 3.5, 1.3 above.
double helical_load_factor_B(double eps_gamma);

/// Transverse unit load w_Bt = F_t K_A K_gamma K_v K_Bbeta K_Balpha / b (Eq. 4, with K_Bbeta =
/// K_Hbeta and K_Balpha = K_Halpha of ISO 6336-1, and gearkit's mesh load factor K_gamma), N/mm.
double transverse_unit_load_B(double F_t, double K_A, double K_gamma, double K_v, double K_Bbeta, double K_Balpha, double b);

/// Sum of the tangential velocities at the pitch point v_SigmaC = 2 v tan(alpha_wt) cos(alpha_t)
/// (Eq. 2), m/s; v is the pitch-line speed at the reference circle, capped at 50 m/s (5.1).
double pitch_point_velocity_sum(double v, double alpha_wt, double alpha_t);

/// Normal relative radius of curvature at the pitch point rho_redC = u/(1 + u)^2 a sin(alpha_wt) /
/// cos(beta_b) (Eq. 3), mm; u and a signed (internal: both negative, the result positive).
double pitch_relative_radius(double u, double a, double alpha_wt, double beta_b);

/// Roughness factor X_R = 2.2 (R_a/rho_redC)^0.25 (Eq. 7), R_a = (R_a1 + R_a2)/2 in um (Eq. 6).
double roughness_factor_X_R(double R_a, double rho_redC);

/// Mean coefficient of friction mu_mC = 0.045 (w_Bt K_Bgamma / (v_SigmaC rho_redC))^0.2
/// eta_oil^-0.05 X_R X_L (Eq. 1); w_Bt below 150 N/mm is taken as 150 (5.1). eta_oil in mPa s at
/// the oil temperature.
double mean_friction_coefficient(double w_Bt, double K_Bgamma, double v_SigmaC, double rho_redC, double eta_oil, double X_R,
                                 double X_L);

/// Running-in factor X_E = 1 + (1 - phi_E) 30 R_a / rho_redC (Eq. 8): phi_E = 1 well run in
/// (X_E = 1), 0 new flanks.
double running_in_factor_X_E(double phi_E, double R_a, double rho_redC);

/// Contact coefficient of a material B_M = sqrt(lambda_M c_v) (Eq. 12), N/(mm s^0.5 K), from its
/// heat conductivity lambda_M in N/(s K) and its specific heat per volume c_v in N/(mm^2 K).
double thermal_contact_coefficient(double lambda_M, double c_v);
constexpr double kSteelLambda_M = 50.0;  ///< N/(s K), steel (5.3)
constexpr double kSteelC_v = 3.8;        ///< N/(mm^2 K), steel (5.3)

/// Reduced modulus E_r = 2 / ((1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2), MPa.
double reduced_modulus(double E_1, double nu_1, double E_2, double nu_2);

/// Thermo-elastic factor X_M = sqrt(1000) E_r^0.25 / B_M (Eq. 11), K N^-3/4 s^1/2 m^-1/2 mm (the
/// sqrt(1000) adapts the mixed m/mm units: steel gives X_M = 50). E_r in MPa, B_M as above.
double thermo_elastic_factor_X_M(double E_r, double B_M);

/// Pressure angle factor X_alphabeta = 1.22 sin^0.25(alpha_wt) cos^0.25(alpha_n) cos^0.25(beta) /
/// (cos^0.5(alpha_wt) cos^0.5(alpha_t)) (Eq. 13; 0.978 at 20 deg spur).
double pressure_angle_factor_X_alphabeta(double alpha_wt, double alpha_n, double alpha_t, double beta);

/// Radii of curvature at the pinion tip E: rho_E1 = 0.5 sqrt(d_a1^2 - d_b1^2) (Eq. 23) and
/// rho_E2 = a sin(alpha_wt) - rho_E1 (Eq. 24, negative for a ring with a < 0), mm.
double pinion_tip_radius_rho_E1(double d_a1, double d_b1);
double wheel_radius_at_pinion_tip_rho_E2(double a, double alpha_wt, double rho_E1);

/// Geometry factor at the pinion tip X_BE = 0.51 sqrt(z_2/|z_2| (u + 1)) (sqrt(rho_E1) -
/// sqrt(rho_E2/u)) / (rho_E1 |rho_E2|)^0.25 (Eq. 22), u and rho_E2 signed.
double geometry_factor_X_BE(double u, double rho_E1, double rho_E2);

/// Addendum contact ratio of a gear eps_i = z_i/(2 pi) (sqrt(d_ai^2/d_bi^2 - 1) - tan(alpha_wt))
/// (Eq. 30, 31), z_i signed (a ring's negative, which keeps eps positive).
double addendum_contact_ratio(int z, double d_a, double d_b, double alpha_wt);

/// Approach factor X_Q (Eq. 25-29) of the approach and recess addendum contact ratios eps_f,
/// eps_a (pinion driving: eps_f = eps_2, eps_a = eps_1; wheel driving: the other way round):
/// 1 for eps_f/eps_a <= 1.5, 1.40 - 4/15 eps_f/eps_a up to 3, 0.6 above.
double approach_factor_X_Q(double eps_f, double eps_a);

/// Effective tip relief C_eff = K_A F_t / (b c) (Eq. 37, 38), um: c = c_gamma (helical) or c'
/// (spur), N/(mm um).
double effective_tip_relief(double K_A, double F_t, double b, double c);

/// Tip relief factor X_Ca = 1 + (0.06 + 0.18 C_a/C_eff) eps_max + (0.02 + 0.69 C_a/C_eff)
/// eps_max^2 (Eq. 32), C_a taken at most C_eff, eps_max the larger addendum contact ratio.
double tip_relief_factor_X_Ca(double C_a, double C_eff, double eps_max);

/// Contact ratio factor X_eps (Eq. 39-44) from the addendum contact ratios eps_1 (pinion) and
/// eps_2: the mean flash temperature over the path relative to the one at the pinion tip.
/// @throws std::invalid_argument for eps_1 <= 0, eps_2 < 0 or eps_alpha = eps_1 + eps_2 >= 3
///         (outside the standard's cases).
double contact_ratio_factor_X_eps(double eps_1, double eps_2);

/// Flash temperature at the pinion tip theta_flaE = mu_mC X_M X_BE X_alphabeta (K_Bgamma
/// w_Bt)^0.75 v^0.5 / |a|^0.25 X_E / (X_Q X_Ca) (Eq. 19), K; v at the reference circle, m/s.
double flash_temperature_at_pinion_tip(double mu_mC, double X_M, double X_BE, double X_alphabeta, double K_Bgamma,
                                       double w_Bt, double v, double a, double X_E, double X_Q, double X_Ca);

/// Mean flash temperature theta_flaint = theta_flaE X_eps (Eq. 18), K.
double mean_flash_temperature(double theta_flaE, double X_eps);

/// Bulk temperature theta_M = theta_oil + C_1 X_mp X_S theta_flaint, C_1 = 0.7 (Eq. 20, 21;
/// X_mp = 1 for one mating gear), deg C.
double bulk_temperature_int(double theta_oil, double theta_flaint, double X_S, double X_mp = 1.0);

/// Integral temperature theta_int = theta_M + C_2 theta_flaint, C_2 = 1.5 (Eq. 17), deg C.
double integral_temperature(double theta_M, double theta_flaint);

/// Pinion torque of the FZG test A/8.3/90 at load stage S: T_1T = 3.726 S^2 (Eq. 97), N m.
double fzg_test_torque(double load_stage);

/// Bulk temperature of the test gears theta_MT = 80 + 0.23 T_1T X_L (Eq. 95), deg C.
double test_bulk_temperature(double T_1T, double X_L);

/// Mean flash temperature of the test gears theta_flaintT = 0.2 T_1T (100/nu_40)^0.02 X_L
/// (Eq. 96), K.
double test_mean_flash_temperature(double T_1T, double nu_40, double X_L);

/// Scuffing integral temperature theta_intS = theta_MT + X_WrelT C_2 theta_flaintT (Eq. 94), deg C.
double scuffing_integral_temperature(double theta_MT, double theta_flaintT, double X_WrelT);

/// Safety factor of the integral temperature S_intS = theta_intS / theta_int (Eq. 14).
double scuffing_safety_integral(double theta_intS, double theta_int);

/// Safety referred to the transmitted load S_SL = (theta_intS - theta_oil) / (theta_int -
/// theta_oil) (Eq. 15).
double scuffing_load_safety(double theta_intS, double theta_int, double theta_oil);

// --- oil properties ---

/// Kinematic viscosity at theta (deg C) from nu_40 and nu_100 by the Ubbelohde-Walther relation
/// of ASTM D341 / DIN 51563: lg lg(nu + 0.7) = A - B lg(T), T in K; mm^2/s.
/// @throws std::invalid_argument unless 0 < nu_100 < nu_40 (finite).
double kinematic_viscosity_at(double nu_40, double nu_100, double theta);

/// Density at theta: rho_15 - 0.0007 (theta - 15) kg/dm^3 (the linear thermal expansion of gear
/// oils; with it KISSsoft's printed eta_oil is reproduced), rho_15 in kg/dm^3.
double oil_density_at(double rho_15, double theta);

/// Dynamic viscosity eta = nu rho, mPa s (nu in mm^2/s, rho in kg/dm^3).
double dynamic_viscosity(double nu, double rho);

}  // namespace gearkit::gear::iso6336
