#include <gearkit/train/synthesis.hpp>

#include <boost/multiprecision/cpp_int.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <tuple>

namespace gearkit::train {

namespace {

using Wide = boost::multiprecision::checked_int128_t;

void check_bounds(int z_min, int z_max) {
  if (z_min < 1 || z_min > z_max) throw std::invalid_argument("synthesis: expected 1 <= z_min <= z_max");
}

double relative_error(const Rational& ratio, const Rational& target) {
  return std::fabs(to_double(Rational(ratio / target - 1)));
}

bool better_reducer(const CoaxialReducer& a, const CoaxialReducer& b) {
  if (a.relative_error != b.relative_error) return a.relative_error < b.relative_error;
  if (a.stage_imbalance != b.stage_imbalance) return a.stage_imbalance < b.stage_imbalance;
  if (a.centre_distance_mm != b.centre_distance_mm) return a.centre_distance_mm < b.centre_distance_mm;
  return std::tie(a.z1, a.z2, a.z3) < std::tie(b.z1, b.z2, b.z3);
}

bool better_planetary(const Planetary& a, const Planetary& b) {
  if (a.relative_error != b.relative_error) return a.relative_error < b.relative_error;
  if (a.z_ring != b.z_ring) return a.z_ring < b.z_ring;
  return a.z_sun < b.z_sun;
}

// Keeps the best `keep` candidates found so far: a wide tolerance admits millions of tooth-count
// sets, which must not all be held in memory (the list is pruned whenever it doubles).
template <class T, class Better>
void add_candidate(std::vector<T>& found, T candidate, std::size_t keep, Better better) {
  found.push_back(std::move(candidate));
  if (found.size() < 2 * std::max<std::size_t>(keep, 1)) return;
  std::nth_element(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(keep), found.end(), better);
  found.resize(keep);
}

template <class T, class Better>
void keep_best(std::vector<T>& found, std::size_t keep, Better better) {
  std::sort(found.begin(), found.end(), better);
  if (found.size() > keep) found.resize(keep);
}

}  // namespace

std::vector<CoaxialReducer> synthesise_coaxial_reducer(const CoaxialReducerSpec& spec) {
  if (!(spec.module_1_mm > 0) || !(spec.module_2_mm > 0)) throw std::invalid_argument("synthesis: modules must be > 0");
  if (spec.target_ratio <= 0) throw std::invalid_argument("synthesis: the target ratio must be > 0");
  if (!(spec.tolerance >= 0)) throw std::invalid_argument("synthesis: the tolerance must be >= 0");
  check_bounds(spec.z_min, spec.z_max);
  if (spec.z1 && (*spec.z1 < spec.z_min || *spec.z1 > spec.z_max))
    throw std::invalid_argument("synthesis: z1 outside the tooth-count bounds");

  // Coaxiality m1 (z1 + z2) = m2 (z3 + z4) in integers: k1 (z1 + z2) = k2 (z3 + z4).
  const Rational m1 = rational_from_double(spec.module_1_mm, 1e-9);
  const Rational m2 = rational_from_double(spec.module_2_mm, 1e-9);
  const Rational r = m1 / m2;
  const long long k1 = boost::multiprecision::numerator(r).convert_to<long long>();
  const long long k2 = boost::multiprecision::denominator(r).convert_to<long long>();
  const long long t_num = boost::multiprecision::numerator(spec.target_ratio).convert_to<long long>();
  const long long t_den = boost::multiprecision::denominator(spec.target_ratio).convert_to<long long>();
  const double target = to_double(spec.target_ratio);

  std::vector<CoaxialReducer> found;
  const int z1_lo = spec.z1.value_or(spec.z_min), z1_hi = spec.z1.value_or(spec.z_max);
  for (int z1 = z1_lo; z1 <= z1_hi; ++z1) {
    for (int z2 = spec.z_min; z2 <= spec.z_max; ++z2) {
      const long long s12 = z1 + z2;
      if ((k1 * s12) % k2 != 0) continue;
      const long long s34 = k1 * s12 / k2;
      // i = z1 z3 / (z2 (s34 - z3)) grows with z3: the z3 within tolerance form one interval.
      const double rho_lo = target * (1 - spec.tolerance) * z2 / z1;
      const double rho_hi = target * (1 + spec.tolerance) * z2 / z1;
      const double z3_lo = s34 * rho_lo / (1 + rho_lo);
      const double z3_hi = s34 * rho_hi / (1 + rho_hi);
      const long long first = std::max<long long>({spec.z_min, s34 - spec.z_max, static_cast<long long>(std::floor(z3_lo)) - 1});
      const long long last = std::min<long long>({spec.z_max, s34 - spec.z_min, static_cast<long long>(std::ceil(z3_hi)) + 1});
      for (long long z3 = first; z3 <= last; ++z3) {
        const long long z4 = s34 - z3;
        // Exact test |z1 z3 t_den - z2 z4 t_num| <= tol * z2 z4 t_num, in checked 128-bit integers.
        const Wide num = Wide(z1) * z3 * t_den;
        const Wide den = Wide(z2) * z4 * t_num;
        const Wide diff = num > den ? Wide(num - den) : Wide(den - num);
        const long double error = diff.convert_to<long double>() / den.convert_to<long double>();
        if (error > static_cast<long double>(spec.tolerance)) continue;
        if (spec.equal_stages && static_cast<long long>(z1) * z4 != static_cast<long long>(z2) * z3) continue;
        add_candidate(found, CoaxialReducer{
            z1, z2, static_cast<int>(z3), static_cast<int>(z4),
            static_cast<long long>(z1) * z3 / std::gcd(static_cast<long long>(z1) * z3, static_cast<long long>(z2) * z4),
            static_cast<long long>(z2) * z4 / std::gcd(static_cast<long long>(z1) * z3, static_cast<long long>(z2) * z4),
            static_cast<double>(error),
            spec.module_1_mm * static_cast<double>(s12) / 2.0,
            std::fabs(std::log((static_cast<double>(z1) / z2) / (static_cast<double>(z3) / z4)))},
            spec.max_results, better_reducer);
      }
    }
  }
  keep_best(found, spec.max_results, better_reducer);
  return found;
}

Rational planetary_ratio(int z_sun, int z_ring, PlanetaryMember fixed, PlanetaryMember input, PlanetaryMember output) {
  if (fixed == input || fixed == output || input == output)
    throw std::invalid_argument("planetary: fixed, input and output must be three different members");
  // z_s w_s + z_r w_r - (z_s + z_r) w_c = 0 with w_fixed = 0.
  const auto coefficient = [&](PlanetaryMember m) -> long long {
    switch (m) {
      case PlanetaryMember::sun: return z_sun;
      case PlanetaryMember::ring: return z_ring;
      case PlanetaryMember::carrier: return -(static_cast<long long>(z_sun) + z_ring);
    }
    return 0;
  };
  return make_rational(-coefficient(input), coefficient(output));
}

std::vector<Planetary> synthesise_planetary(const PlanetarySpec& spec) {
  if (spec.target_ratio == 0) throw std::invalid_argument("synthesis: the target ratio must not be 0");
  if (!(spec.tolerance >= 0)) throw std::invalid_argument("synthesis: the tolerance must be >= 0");
  if (spec.planets < 1) throw std::invalid_argument("synthesis: at least one planet");
  check_bounds(spec.z_min, spec.z_max);
  planetary_ratio(1, 3, spec.fixed, spec.input, spec.output);  // validates the arrangement

  std::vector<Planetary> found;
  const double neighbour_sine = std::sin(std::numbers::pi / spec.planets);
  for (int zs = spec.z_min; zs <= spec.z_max; ++zs) {
    for (int zp = spec.z_min; zp <= spec.z_max; ++zp) {
      const int zr = zs + 2 * zp;
      if (zr > spec.z_ring_max) break;
      if ((zs + zr) % spec.planets != 0) continue;
      if (spec.planets > 1 && !((zs + zp) * neighbour_sine > zp + 2)) continue;
      const Rational ratio = planetary_ratio(zs, zr, spec.fixed, spec.input, spec.output);
      if (ratio.sign() != spec.target_ratio.sign()) continue;
      const double error = relative_error(ratio, spec.target_ratio);
      if (error > spec.tolerance) continue;
      add_candidate(found,
                    Planetary{zs, zp, zr, boost::multiprecision::numerator(ratio).convert_to<long long>(),
                              boost::multiprecision::denominator(ratio).convert_to<long long>(), error},
                    spec.max_results, better_planetary);
    }
  }
  keep_best(found, spec.max_results, better_planetary);
  return found;
}

}  // namespace gearkit::train
