#pragma once
// Tooth-count synthesis: all tooth counts within bounds that give a target speed ratio within a
// relative tolerance, ranked by ratio error. Ratios are computed exactly from the tooth counts.
#include <gearkit/train/rational.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace gearkit::train {

/// Two-stage coaxial ("recurrent") reducer: 1 meshes 2 (module m1), 3 on the shaft of 2 meshes 4
/// (module m2), output shaft 4 coaxial with input shaft 1: m1 (z1 + z2) = m2 (z3 + z4), zero
/// profile shift. Ratio w4/w1 = (z1 z3)/(z2 z4) (two external meshes, positive).
struct CoaxialReducerSpec {
  double module_1_mm = 0;         ///< m1 > 0
  double module_2_mm = 0;         ///< m2 > 0
  Rational target_ratio;          ///< w_out / w_in, > 0 (1/16 for a 16:1 reducer)
  double tolerance = 1e-6;        ///< accepted |i / i_target - 1|, >= 0
  int z_min = 12;                 ///< bounds for every gear, 1 <= z_min <= z_max
  int z_max = 150;
  std::optional<int> z1;          ///< fix the input pinion
  bool equal_stages = false;      ///< require z1/z2 = z3/z4 exactly
  std::size_t max_results = 20;
};

struct CoaxialReducer {
  int z1 = 0, z2 = 0, z3 = 0, z4 = 0;
  long long ratio_numerator = 0;  ///< (z1 z3)/(z2 z4) reduced: numerator
  long long ratio_denominator = 1;
  double relative_error = 0;      ///< |ratio / target - 1|
  double centre_distance_mm = 0;  ///< m1 (z1 + z2) / 2
  double stage_imbalance = 0;     ///< |ln((z1/z2) / (z3/z4))|, 0 for equal stage ratios
};

/// Candidates sorted by relative error, then stage imbalance, then centre distance.
/// @throws std::invalid_argument for a module <= 0, a target <= 0, a negative tolerance, bounds
///   with z_min < 1 or z_min > z_max, or z1 outside the bounds.
std::vector<CoaxialReducer> synthesise_coaxial_reducer(const CoaxialReducerSpec& spec);

enum class PlanetaryMember { sun, carrier, ring };

/// Simple planetary set (sun s, N planets p, ring r, one carrier), standard gears of one module:
/// coaxial z_r = z_s + 2 z_p; equal spacing (z_s + z_r)/N integer; neighbours clear:
/// (z_s + z_p) sin(pi/N) > z_p + 2. One member is fixed; ratio = w_output / w_input.
struct PlanetarySpec {
  Rational target_ratio;  ///< any sign, not 0
  double tolerance = 1e-6;
  int planets = 3;         ///< N >= 1
  int z_min = 12;          ///< bounds for sun and planet
  int z_max = 150;
  int z_ring_max = 400;    ///< bound for the ring
  PlanetaryMember fixed = PlanetaryMember::ring;
  PlanetaryMember input = PlanetaryMember::sun;
  PlanetaryMember output = PlanetaryMember::carrier;
  std::size_t max_results = 20;
};

struct Planetary {
  int z_sun = 0, z_planet = 0, z_ring = 0;
  long long ratio_numerator = 0;  ///< w_output / w_input reduced, sign on the numerator
  long long ratio_denominator = 1;
  double relative_error = 0;
};

/// Candidates sorted by relative error, then by ring size.
/// @throws std::invalid_argument for a zero target, negative tolerance, planets < 1, bad bounds,
///   or fixed/input/output not three different members.
std::vector<Planetary> synthesise_planetary(const PlanetarySpec& spec);

/// The ratio w_output / w_input of a simple planetary with `fixed` held, from Willis' equation
/// z_s w_s + z_r w_r = (z_s + z_r) w_c. @throws std::invalid_argument as above.
Rational planetary_ratio(int z_sun, int z_ring, PlanetaryMember fixed, PlanetaryMember input, PlanetaryMember output);

}  // namespace gearkit::train
