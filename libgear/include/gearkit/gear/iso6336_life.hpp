#pragma once
// Life factors of ISO 6336-2:2019 (Z_NT, Table 2) and ISO 6336-3:2019 (Y_NT, Table 3), and the
// service life under a load spectrum by the Palmgren-Miner rule (ISO 6336-6:2019).
#include <gearkit/gear/materials.hpp>

#include <array>
#include <vector>

namespace gearkit::gear::iso6336 {

/// A life line: the factor at N_static and below, straight lines in log-log coordinates through
/// the knee points up to N = 1e10, constant beyond.
struct LifeLine {
  int points = 0;
  std::array<double, 4> N{};
  std::array<double, 4> factor{};
};

/// Z_NT line for the material class (ISO 6336-2:2019 Table 2): St, V, GGG, GTS, Eh, IF with
/// `limited_pitting` (6e5: 1.6, 1e7: 1.3, 1e9: 1.0, 1e10: 0.85) or without (1e5: 1.6,
/// 5e7: 1.0, 1e10: 0.85); GG, GGG ferritic, NT, NV nitrided (1e5: 1.3, 2e6: 1.0, 1e10: 0.85);
/// NV nitrocarburized (1e5: 1.1, 2e6: 1.0, 1e10: 0.85). `optimum` (optimum lubrication,
/// material, manufacturing and experience) raises the 1e10 value to 1.0.
LifeLine pitting_life_line(MaterialClass kind, bool limited_pitting, bool optimum);

/// Y_NT line (ISO 6336-3:2019 Table 3): St, V, GGG perlitic (1e4: 2.5, 3e6: 1.0, 1e10: 0.85);
/// Eh, IF root hardened (1e3: 2.5, 3e6: 1.0, 1e10: 0.85); NT, NV nitrided, GG, GGG ferritic
/// (1e3: 1.6, 3e6: 1.0, 1e10: 0.85); NV nitrocarburized (1e3: 1.1, 3e6: 1.0, 1e10: 0.85);
/// `optimum` raises the 1e10 value to 1.0.
LifeLine root_life_line(MaterialClass kind, bool optimum);

/// The life factor at N_L load cycles (log-log interpolation of the line).
double life_factor(const LifeLine& line, double N_L);

/// The number of load cycles at which the line reaches `factor`: 0 when the factor exceeds the
/// static value (no life at all), +infinity when it is at or below the value at 1e10.
double cycles_at_factor(const LifeLine& line, double factor);

/// One row of a load spectrum: pinion torque (N m), pinion speed (1/min), hours.
struct LoadBin {
  double T_1 = 0;
  double n_1 = 0;
  double hours = 0;
};

/// Palmgren-Miner damage sum D = sum n_i / N_i (ISO 6336-6:2019 clause 5): `cycles` the load
/// cycles of each bin, `allowed` the cycles to failure at that bin's stress (+inf: no damage).
double miner_damage(const std::vector<double>& cycles, const std::vector<double>& allowed);

}  // namespace gearkit::gear::iso6336
