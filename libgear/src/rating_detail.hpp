#pragma once
// Internal steps of rating.cpp shared by the method files (not installed).
#include <gearkit/gear/rating.hpp>

#include <array>

namespace gearkit::gear::detail {

/// What the rating needs of the gear table, magnitudes (a ring's diameters positive).
struct Mesh {
  std::array<int, 2> z{};
  bool internal = false;
  double m_n = 0, alpha_n = 0, alpha_t = 0, beta = 0, beta_b = 0, alpha_wt = 0;
  std::array<double, 2> d{}, d_b{}, d_a{}, d_f{}, d_w{}, x{}, A_sn{}, z_n{};
  std::array<double, 2> d_Na{};  ///< usable tip diameters: eps_alpha, Z_B/Z_D and Y_F use them (d_a unless given)
  double u = 1, b = 0;  ///< b: the common face width
  std::array<double, 2> b_F{};  ///< face width of each gear for its root stress (root_face_width)
  std::array<double, 2> h_fP{1.25, 1.25}, rho_fP{0.38, 0.38};  ///< coefficients of each gear's tool
  double eps_alpha = 0, eps_beta = 0, eps_gamma = 0;
};

Mesh mesh_of(const GearPairInput& in, const GearPairResult& r);
bool surface_hardened(MaterialClass k);
bool cast_iron(MaterialClass k);
double imposed_or(const ImposedFactors& f, Factor which, double computed);
/// Factor `first` (a ...1 entry) for gear i (0 or 1).
Factor per_gear(Factor first, int i);
double hours_for_cycles(double N, double n, double cycles_per_rev);

/// A rating with the load of the operating point (T_1, n_1, F_t, v, K_A, K_gamma, contact ratios) filled in.
PairRating operating_point(RatingMethod method, const Mesh& m, const RatingInput& in, double T_1, double n_1);

/// ISO 6336 at one operating point (no life evaluation).
PairRating iso_operating_point(const Mesh& m, const RatingInput& in, double T_1, double n_1);
/// sigma_H, sigma_HP, S_H and the factors of ISO 6336-2 for both gears (needs r's K factors).
void contact_of_gears(const Mesh& m, const RatingInput& in, PairRating& r);
/// sigma_F, sigma_FP, S_F and the factors of ISO 6336-3 for both gears.
void root_of_gears(const Mesh& m, const RatingInput& in, PairRating& r);

PairRating rate_iso6336(const Mesh& m, const RatingInput& in);
PairRating rate_agma(const Mesh& m, const RatingInput& in);
PairRating rate_lewis_hertz(const Mesh& m, const RatingInput& in);

/// The integral temperature scuffing rating of the mesh into r.scuffing (needs r's K factors and
/// stiffness; nothing without RatingInput::scuffing.fzg_stage).
void scuffing_of_mesh(const Mesh& m, const RatingInput& in, PairRating& r);

/// Warnings for safety factors below their minimum and damage sums above 1.
void safety_warnings(const RatingInput& in, PairRating& r);

}  // namespace gearkit::gear::detail
