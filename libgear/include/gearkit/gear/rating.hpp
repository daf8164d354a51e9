#pragma once
// Load capacity of a cylindrical gear pair: the complete rating of both gears by ISO 6336
// (2019, method B with K_Hbeta by method C), by AGMA 2101-D as Shigley teaches it, or by the
// Lewis and Hertz equations of the course notes. One input, one output shape; the method
// decides which factors are computed. Units: N, mm, MPa, N m, 1/min, um for deviations.
//
// The geometry comes from compute_gear_pair (gear_pair.hpp); the rating is a free function of
// the table and the load, so a sizing loop computes both without building anything else.
#include <gearkit/gear/accuracy.hpp>
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/iso6336_life.hpp>
#include <gearkit/gear/iso6336_load.hpp>
#include <gearkit/gear/iso6336_scuffing.hpp>
#include <gearkit/gear/materials.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace gearkit::gear {

/// Bad rating input; `field` names the RatingInput member ("T_1", "n_1", "material1", "f_pb",
/// "face_width", ...) so that front ends can name their option or key.
class RatingError : public std::invalid_argument {
 public:
  RatingError(std::string field, const std::string& message);
  const std::string& field() const noexcept { return field_; }

 private:
  std::string field_;
};

enum class RatingMethod { iso6336, agma, lewis_hertz };
const char* to_string(RatingMethod method);  ///< "iso6336", "agma", "lewis-hertz"

/// Factors a user may impose instead of the computed value. Per-gear factors have a 1 and a 2
/// entry; "Z_NT" in a name list means both.
enum class Factor : int {
  K_v, K_Hbeta, K_Fbeta, K_Halpha, K_Falpha,
  Z_H, Z_E, Z_epsilon, Z_beta, Z_B, Z_D, Z_L, Z_v, Z_R, Z_X,
  Z_NT1, Z_NT2, Z_W1, Z_W2,
  Y_F1, Y_F2, Y_S1, Y_S2, Y_beta, Y_B1, Y_B2, Y_DT,
  Y_NT1, Y_NT2, Y_deltarelT1, Y_deltarelT2, Y_RrelT1, Y_RrelT2, Y_X1, Y_X2, Y_M1, Y_M2,
  // AGMA (Shigley chapter 14) and Lewis
  K_s1, K_s2, K_m, K_B1, K_B2, K_R, J1, J2, I, Y_N1, Y_N2, Z_N1, Z_N2, C_H, C_f, Y1, Y2,
  // scuffing (ISO/TS 6336-21)
  X_WrelT,
  count
};
constexpr int kFactorCount = static_cast<int>(Factor::count);

/// The name of a factor ("K_v", "Z_NT1").
std::string_view factor_name(Factor f);

/// The factors a name sets: "K_v" -> {K_v}; "Z_NT" -> {Z_NT1, Z_NT2}; "Z_NT2" -> {Z_NT2}.
/// Empty for an unknown name.
std::vector<Factor> factors_named(std::string_view name);

/// All names accepted by factors_named, for messages.
std::string factor_names();

/// Imposed values (NaN: computed).
struct ImposedFactors {
  std::array<double, kFactorCount> value;
  ImposedFactors() { value.fill(std::numeric_limits<double>::quiet_NaN()); }
  bool has(Factor f) const { return !std::isnan(value[static_cast<int>(f)]); }
  double get(Factor f) const { return value[static_cast<int>(f)]; }
  void set(Factor f, double v) { value[static_cast<int>(f)] = v; }
};

enum class RootShift { generating, nominal };  ///< which profile shift feeds Y_F, Y_S (ISO: generating x_E)
enum class AgmaMounting { open, commercial, precision, extra_precision };  ///< Shigley Eq. 14-34 (C_ma)
enum class LewisProfile { cast, cut, hobbed, ground };  ///< Barth / Shigley Eq. 14-4 (K_v)

/// How f_sh of ISO 6336-1 method C is found (docs/rating.md, "Face load factor").
enum class FaceLoadModel {
  pinion_shaft,  ///< the pinion on its own shaft between bearings (Eq. 43 with K', l, s, d_sh and B*)
  sun,           ///< a sun meshing with `planets` planets evenly spaced: no bending term (their forces
                 ///< balance), the sun body twisted by all planets' torque: B* = planets, K' term 0
};
const char* to_string(FaceLoadModel model);  ///< "pinion-shaft", "sun"

/// Inputs of K_Hbeta by ISO 6336-1:2019 method C (7.6) beyond the deviations: the pinion shaft for
/// f_sh (Eq. 43/44, Figure 13) and the flank line modification for B_1, B_2 (Eq. 38, Table 10).
struct FaceLoadInput {
  FaceLoadModel model = FaceLoadModel::pinion_shaft;
  double l = 0;     ///< bearing span of the pinion shaft, mm (0: not given; the pinion centred, K' term 0)
  double s = 0;     ///< offset of the pinion's face centre from the middle of the span, mm (>= 0)
  double d_sh = 0;  ///< outer diameter of the pinion shaft, mm (> 0 when l is given)
  iso6336::ShaftArrangement arrangement = iso6336::ShaftArrangement::a;  ///< Figure 13
  std::optional<bool> stiffening;  ///< Figure 13 column (empty: d_1/d_sh >= 1.15)
  double K_prime = std::numeric_limits<double>::quiet_NaN();  ///< imposed K' (NaN: from the arrangement)
  double torque_percent = 100;  ///< k of B* = 1 + 2 (100 - k)/k, percent of the pinion torque on this mesh, (0, 100]
  int planets = 1;              ///< with FaceLoadModel::sun: the planets meshing with the sun, >= 1
  iso6336::HelixModification modification = iso6336::HelixModification::none;
  /// True when any shaft data is given (l > 0, or K' imposed).
  bool has_shaft() const { return l > 0.0 || !std::isnan(K_prime); }
};

/// The oil and how it is used, for the scuffing rating by the integral temperature method
/// (ISO/TS 6336-21, iso6336_scuffing.hpp). Scuffing is rated when the oil's FZG load stage is
/// given; the oil temperature and nu_100 are then required (RatingError "theta_oil", "nu_100").
struct ScuffingInput {
  std::optional<int> fzg_stage;  ///< failure load stage of the oil in the FZG test A/8.3/90 (ISO 14635-1), 1..14
  double theta_oil = std::numeric_limits<double>::quiet_NaN();  ///< oil temperature (sump or injection), deg C
  double nu_100 = std::numeric_limits<double>::quiet_NaN();     ///< kinematic viscosity at 100 C, mm^2/s (< nu_40)
  double rho_15 = 0.89;  ///< density of the oil at 15 C, kg/dm^3 (0.5 .. 2)
  iso6336::OilBase oil = iso6336::OilBase::mineral;
  iso6336::Lubrication lubrication = iso6336::Lubrication::dip;
  bool gear1_driving = true;  ///< which gear drives (the approach factor X_Q)
  double S_Smin = 2.0;        ///< required minimum S_intS
};

/// The integral temperature rating of the mesh (ISO/TS 6336-21); the symbols of iso6336_scuffing.hpp,
/// index 1 the standard's pinion (`pinion` = 0 or 1: which gear of the pair it is).
struct ScuffingRating {
  int pinion = 0;
  double eps_1 = 0, eps_2 = 0, K_Bgamma = 1, w_Bt = 0, v_SigmaC = 0, rho_redC = 0;
  double nu_oil = 0, eta_oil = 0, X_R = 1, X_L = 1, mu_mC = 0, X_E = 1, X_M = 0, X_alphabeta = 1, X_BE = 0, X_Q = 1;
  double C_a = 0, C_eff = 0, X_Ca = 1, X_eps = 0, X_S = 1, X_WrelT = 1;
  double theta_flaE = 0, theta_flaint = 0, theta_M = 0, theta_int = 0;  ///< K (flash), deg C
  double T_1T = 0, theta_MT = 0, theta_flaintT = 0, theta_intS = 0;     ///< N m, deg C, K, deg C
  double S_intS = 0, S_SL = 0;
};

struct RatingInput {
  RatingMethod method = RatingMethod::iso6336;
  double T_1 = 0;             ///< N m, torque on gear 1 (pinion), > 0 (or 0 with T_2 given)
  /// N m, torque on gear 2 instead of T_1 (0: T_1 is given). rate_gear_pair takes
  /// T_1 = T_2 z1/z2 (magnitudes; mesh efficiency 1, as the rating of one mesh assumes).
  double T_2 = 0;
  double n_1 = 0;             ///< 1/min, speed of gear 1 relative to the carrier of the mesh, > 0
  double K_A = 1.0;           ///< application factor (ISO 6336-6 Annex A), AGMA overload factor K_o
  double K_gamma = 1.0;       ///< mesh load factor (load sharing of planets), >= 1
  std::array<Material, 2> material;
  /// ISO 1328-1 accuracy grade of the mesh (the coarser gear): class 1..11 of the 2013 edition or
  /// grade 0..12 of the 1995 edition (`iso1328_edition`); empty: not given. When given, the
  /// deviations below that are not given are that edition's tolerances (accuracy.hpp): f_pb =
  /// f_pT cos(alpha_t), f_falpha = f_falphaT, f_Hbeta = f_ma = f_HbetaT (larger of both gears).
  /// Also decides Y_DT (a grade <= 4 is high precision; without a grade Y_DT = 1, ISO 6336-3:2019
  /// clause 10) and gives the AGMA quality number Q_v = 17 - grade when Q_v is not given.
  std::optional<int> quality;
  Iso1328Edition iso1328_edition = Iso1328Edition::iso2013;  ///< edition of `quality`
  // Deviations, um (NaN: not given; then K_v, K_Halpha, K_Hbeta need them, the quality or an imposed factor).
  double f_pb = std::numeric_limits<double>::quiet_NaN();      ///< transverse base pitch deviation (larger gear value)
  double f_falpha = std::numeric_limits<double>::quiet_NaN();  ///< profile form deviation
  double F_betax = std::numeric_limits<double>::quiet_NaN();   ///< initial equivalent misalignment (given directly)
  double f_ma = std::numeric_limits<double>::quiet_NaN();      ///< mesh misalignment from manufacturing
  double f_sh = std::numeric_limits<double>::quiet_NaN();      ///< misalignment from shaft deflection (NaN: Eq. 43, B* = 1)
  double f_Hbeta = 0;                                          ///< helix slope deviation (F_betax,min)
  double C_a = std::numeric_limits<double>::quiet_NaN();       ///< tip relief (NaN: C_ay by running-in)
  FaceLoadInput face_load;    ///< shaft and flank line modification for f_sh, F_betax (method C)
  double life_h = 20000;      ///< required life, h, > 0
  /// Required life as load cycles of gear 1 (NaN: life_h). rate_gear_pair takes
  /// life_h = N_L1 / (60 n_1 cycles_per_rev[0]); not with a spectrum (its rows are hours).
  double N_L1 = std::numeric_limits<double>::quiet_NaN();
  double nu_40 = 220;         ///< kinematic viscosity of the oil at 40 C, mm^2/s
  std::array<double, 2> R_z_flank{3.0, 3.0};   ///< um, flank roughness R_z (6 R_a)
  std::array<double, 2> R_z_root{10.0, 10.0};  ///< um, root roughness R_z
  std::array<double, 2> s_R{0.0, 0.0};         ///< rim thickness, mm (0: solid)
  std::array<double, 2> cycles_per_rev{1.0, 1.0};  ///< load cycles per turn of each gear relative to the carrier
  std::array<bool, 2> reversed_bending{false, false};  ///< idler or planet: fully reversed bending, Y_M = 0.7
  double S_Hmin = 1.0, S_Fmin = 1.4;  ///< required minimum safety factors
  bool limited_pitting = false;   ///< Z_NT line with limited pitting permitted
  bool optimum_long_life = false; ///< Z_NT = Y_NT = 1 at 1e10 (optimum conditions) instead of 0.85
  RootShift root_shift = RootShift::generating;
  double s_pr = 0;                ///< residual protuberance of the tools / m_n (both gears)
  /// Residual protuberance s_pr/m_n of the tool of each gear (s_pr = p_r - q: protuberance less
  /// the grinding stock), when the gears are cut by different tools; empty: s_pr.
  std::array<std::optional<double>, 2> s_pr_gear;
  /// Upper normal tooth thickness allowance A_sne of each gear, mm, for the generating shift
  /// x_E = x + A_sne/(2 m_n tan alpha_n) of the root rating; empty: the gear table's A_sn
  /// (GearPairInput A_sn1, A_sn2). Front ends set it from the inspection's allowances
  /// (given, DIN 3967 or ISO/TR 10064-2), so that one allowance serves table, inspection and rating.
  std::array<std::optional<double>, 2> A_sne;
  /// Usable tip diameter d_Na of each gear, mm (magnitude): where the involute ends below a tip
  /// chamfer or rounding. Empty: the tip diameter of the table, less 2 h_K with a chamfer. The
  /// rating's contact ratio, Z_B/Z_D and the load point of Y_F use it (ISO 6336-1/3: d_Na);
  /// the table (clearances) keeps d_a. External: d_b < d_Na <= d_a; ring: d_b < d_a <= d_Na.
  std::array<std::optional<double>, 2> d_Na;
  std::array<std::optional<double>, 2> h_K;  ///< radial tip chamfer of each gear, mm (d_Na = d_a -+ 2 h_K)
  std::vector<iso6336::LoadBin> spectrum;  ///< load spectrum (empty: T_1, n_1 for life_h)
  double reliability = 0.99;      ///< AGMA
  int Q_v = 0;                    ///< AGMA quality number 3..16 for K_v (0: 17 - quality)
  AgmaMounting agma_mounting = AgmaMounting::commercial;
  bool agma_crowned = false;
  LewisProfile lewis_profile = LewisProfile::hobbed;
  ScuffingInput scuffing;  ///< the oil for scuffing (ISO method only; not rated without the FZG stage)
  ImposedFactors factors;
};

struct GearRating {
  double n = 0;              ///< 1/min relative speed
  double N_L = 0;            ///< load cycles over the life (or the spectrum)
  double Z_B_or_D = 1, sigma_H = 0, sigma_HG = 0, sigma_HP = 0, S_H = 0;
  double Z_NT = 1, Z_L = 1, Z_v = 1, Z_R = 1, Z_W = 1, Z_X = 1;
  double s_Fn = NAN, rho_F = NAN, h_Fe = NAN, alpha_Fen = NAN;
  double Y_F = NAN, Y_S = NAN, Y_beta = 1, Y_B = 1, Y_DT = 1, Y_M = 1;
  double Y_deltarelT = 1, Y_RrelT = 1, Y_X = 1, Y_NT = 1;
  double sigma_F0 = 0, sigma_F = 0, sigma_FG = 0, sigma_FP = 0, S_F = 0;
  double life_H_h = 0, life_F_h = 0;  ///< hours to reach S_min (inf: unlimited)
  double damage_H = 0, damage_F = 0;  ///< Miner sums for the required life or the spectrum
  std::vector<std::pair<std::string, double>> extra;  ///< method-specific factors (AGMA K_s, J, Y_N, ...)
};

struct PairRating {
  RatingMethod method = RatingMethod::iso6336;
  double T_1 = 0, n_1 = 0, F_t = 0, v = 0;
  double K_A = 1, K_gamma = 1, K_v = 1, K_Hbeta = 1, K_Halpha = 1, K_Fbeta = 1, K_Falpha = 1;
  double c_th = NAN, c_prime = NAN, c_gamma_alpha = NAN, c_gamma_beta = NAN;
  double m_red = NAN, n_E1 = NAN, N = NAN, N_S = NAN;
  iso6336::ResonanceRange range = iso6336::ResonanceRange::subcritical;
  double F_betax = NAN, F_betay = NAN, f_sh = NAN, y_alpha = NAN;
  double K_prime = NAN, B_star = NAN;  ///< of f_sh by Eq. 43 (NaN: f_sh given, or F_betax given)
  double Z_H = 1, Z_E = 1, Z_epsilon = 1, Z_beta = 1, sigma_H0 = 0;
  double eps_alpha = 0, eps_beta = 0, eps_gamma = 0;
  double T_eq = NAN;  ///< equivalent torque of a spectrum for pitting of gear 1 (N m)
  std::array<GearRating, 2> gear;
  std::optional<ScuffingRating> scuffing;  ///< empty: not rated (no FZG stage, or not the ISO method)
  std::vector<std::pair<std::string, double>> extra;
  ImposedFactors imposed;  ///< which factors were imposed (copy of the input's)
  std::vector<std::string> warnings;
};

/// Rates the pair. @throws RatingError naming the input field when the input is invalid
/// (T_1 <= 0 without T_2, T_1 and T_2 both given, T_2 < 0, N_L1 <= 0 or with a spectrum, n_1 <= 0, face width 0, an invalid material, life <= 0, a grade outside its edition
/// (2013: 1..11, 1995: 0..12),
/// missing deviations for a computed K_v / K_Hbeta / K_Halpha, a spectrum row with T <= 0, shaft
/// data that is incomplete or out of range ("face_load") ...).
PairRating rate_gear_pair(const GearPairInput& geometry_input, const GearPairResult& geometry, const RatingInput& input);

/// Checks the load input alone (same errors as rate_gear_pair for the load fields).
void validate(const RatingInput& input);

}  // namespace gearkit::gear
