// Service life of the ISO 6336 rating (ISO 6336-6:2019): the life at the rated load and the
// Palmgren-Miner damage of a load spectrum, both on the life lines of parts 2 and 3 with the
// required minimum safety factors applied; and the safety warnings of every method.
#include "rating_detail.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <tuple>

namespace gearkit::gear::detail {

namespace iso = iso6336;

namespace {

// Cycles to reach S_Hmin at this contact stress, on the Z_NT line of gear i.
double allowed_cycles_H(const RatingInput& in, const GearRating& g, int i) {
  const Material& mat = in.material[i];
  const double needed = in.S_Hmin * g.sigma_H / (mat.sigma_Hlim * g.Z_L * g.Z_v * g.Z_R * g.Z_W * g.Z_X);
  return iso::cycles_at_factor(iso::pitting_life_line(mat.kind, in.limited_pitting, in.optimum_long_life), needed);
}

// Cycles to reach S_Fmin at this root stress, on the Y_NT line of gear i.
double allowed_cycles_F(const RatingInput& in, const GearRating& g, int i) {
  const Material& mat = in.material[i];
  const double needed = in.S_Fmin * g.sigma_F / (2.0 * mat.sigma_Flim * g.Y_deltarelT * g.Y_RrelT * g.Y_X * g.Y_M);
  return iso::cycles_at_factor(iso::root_life_line(mat.kind, in.optimum_long_life), needed);
}

void constant_load_life(const RatingInput& in, PairRating& r) {
  for (int i = 0; i < 2; ++i) {
    GearRating& g = r.gear[i];
    const double N_H = allowed_cycles_H(in, g, i), N_F = allowed_cycles_F(in, g, i);
    g.life_H_h = hours_for_cycles(N_H, g.n, in.cycles_per_rev[i]);
    g.life_F_h = hours_for_cycles(N_F, g.n, in.cycles_per_rev[i]);
    g.damage_H = iso::miner_damage({g.N_L}, {N_H});
    g.damage_F = iso::miner_damage({g.N_L}, {N_F});
  }
}

void spectrum_life(const Mesh& m, const RatingInput& in, PairRating& r) {
  double hours = 0.0;
  std::array<std::vector<double>, 2> n, N_H, N_F;
  for (const auto& bin : in.spectrum) {
    const PairRating p = iso_operating_point(m, in, bin.T_1, bin.n_1);
    hours += bin.hours;
    for (int i = 0; i < 2; ++i) {
      n[i].push_back(p.gear[i].n * 60.0 * bin.hours * in.cycles_per_rev[i]);
      N_H[i].push_back(allowed_cycles_H(in, p.gear[i], i));
      N_F[i].push_back(allowed_cycles_F(in, p.gear[i], i));
    }
  }
  for (int i = 0; i < 2; ++i) {
    GearRating& g = r.gear[i];
    g.N_L = 0.0;
    for (double c : n[i]) g.N_L += c;
    g.damage_H = iso::miner_damage(n[i], N_H[i]);
    g.damage_F = iso::miner_damage(n[i], N_F[i]);
    g.life_H_h = g.damage_H > 0.0 ? hours / g.damage_H : std::numeric_limits<double>::infinity();
    g.life_F_h = g.damage_F > 0.0 ? hours / g.damage_F : std::numeric_limits<double>::infinity();
  }
  // Equivalent torque for pitting of gear 1: the constant torque that does the same damage over
  // the same cycles, with sigma_H proportional to sqrt(T) around the rated point.
  const GearRating& g = r.gear[0];
  if (g.damage_H > 0.0 && std::isfinite(g.damage_H)) {
    const double N_eq = g.N_L / g.damage_H;
    const auto line = iso::pitting_life_line(in.material[0].kind, in.limited_pitting, in.optimum_long_life);
    const double sigma_eq = iso::life_factor(line, N_eq) * in.material[0].sigma_Hlim * g.Z_L * g.Z_v * g.Z_R * g.Z_W * g.Z_X / in.S_Hmin;
    r.T_eq = r.T_1 * (sigma_eq / g.sigma_H) * (sigma_eq / g.sigma_H);
  }
}

}  // namespace

PairRating rate_iso6336(const Mesh& m, const RatingInput& in) {
  PairRating r = iso_operating_point(m, in, in.T_1, in.n_1);
  if (in.spectrum.empty()) {
    constant_load_life(in, r);
  } else {
    spectrum_life(m, in, r);
  }
  if (r.range == iso::ResonanceRange::main_resonance && !in.factors.has(Factor::K_v)) {
    r.warnings.push_back(fmt::format("the pinion runs in the main resonance range (N = n_1/n_E1 = {:.3f}, n_E1 = {:.0f} 1/min)",
                                     r.N, r.n_E1));
  }
  return r;
}

void safety_warnings(const RatingInput& in, PairRating& r) {
  for (int i = 0; i < 2; ++i) {
    const GearRating& g = r.gear[i];
    if (g.S_H < in.S_Hmin) {
      r.warnings.push_back(fmt::format("gear {}: pitting safety S_H = {:.3f} below S_Hmin = {:.2f}", i + 1, g.S_H, in.S_Hmin));
    }
    if (g.S_F < in.S_Fmin) {
      r.warnings.push_back(fmt::format("gear {}: tooth-root safety S_F = {:.3f} below S_Fmin = {:.2f}", i + 1, g.S_F, in.S_Fmin));
    }
    for (auto [what, D, life] : {std::tuple{"pitting", g.damage_H, g.life_H_h}, {"tooth-root", g.damage_F, g.life_F_h}}) {
      if (std::isinf(D)) {
        r.warnings.push_back(fmt::format("gear {}: {} stress above the static limit of the life line (no life at S_min)", i + 1, what));
      } else if (D > 1.0) {
        r.warnings.push_back(fmt::format("gear {}: {} damage sum {:.3f} > 1 (life {:.4g} h)", i + 1, what, D, life));
      }
    }
  }
}

}  // namespace gearkit::gear::detail
