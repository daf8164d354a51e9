#include <gearkit/gear/iso6336_life.hpp>

#include <cmath>
#include <limits>

namespace gearkit::gear::iso6336 {

namespace {

LifeLine line3(double N0, double f0, double N1, double f1, bool optimum) {
  return {3, {N0, N1, 1e10, 0}, {f0, f1, optimum ? 1.0 : 0.85, 0}};
}

}  // namespace

LifeLine pitting_life_line(MaterialClass kind, bool limited_pitting, bool optimum) {
  switch (kind) {
    case MaterialClass::grey_cast_iron:
    case MaterialClass::nitrided:
    case MaterialClass::nitrided_through_hardened: return line3(1e5, 1.3, 2e6, 1.0, optimum);
    case MaterialClass::nitrocarburized: return line3(1e5, 1.1, 2e6, 1.0, optimum);
    default:
      if (limited_pitting) return {4, {6e5, 1e7, 1e9, 1e10}, {1.6, 1.3, 1.0, optimum ? 1.0 : 0.85}};
      return line3(1e5, 1.6, 5e7, 1.0, optimum);
  }
}

LifeLine root_life_line(MaterialClass kind, bool optimum) {
  switch (kind) {
    case MaterialClass::case_carburized:
    case MaterialClass::induction_hardened: return line3(1e3, 2.5, 3e6, 1.0, optimum);
    case MaterialClass::nitrided:
    case MaterialClass::nitrided_through_hardened:
    case MaterialClass::grey_cast_iron: return line3(1e3, 1.6, 3e6, 1.0, optimum);
    case MaterialClass::nitrocarburized: return line3(1e3, 1.1, 3e6, 1.0, optimum);
    default: return line3(1e4, 2.5, 3e6, 1.0, optimum);
  }
}

double life_factor(const LifeLine& line, double N_L) {
  if (N_L <= line.N[0]) return line.factor[0];
  for (int i = 1; i < line.points; ++i) {
    if (N_L <= line.N[i]) {
      const double t = std::log(N_L / line.N[i - 1]) / std::log(line.N[i] / line.N[i - 1]);
      return std::exp(std::log(line.factor[i - 1]) + t * std::log(line.factor[i] / line.factor[i - 1]));
    }
  }
  return line.factor[line.points - 1];
}

double cycles_at_factor(const LifeLine& line, double factor) {
  if (factor > line.factor[0]) return 0.0;
  if (factor <= line.factor[line.points - 1]) return std::numeric_limits<double>::infinity();
  for (int i = 1; i < line.points; ++i) {
    if (factor >= line.factor[i]) {
      if (line.factor[i] == line.factor[i - 1]) return line.N[i - 1];
      const double t = std::log(factor / line.factor[i - 1]) / std::log(line.factor[i] / line.factor[i - 1]);
      return std::exp(std::log(line.N[i - 1]) + t * std::log(line.N[i] / line.N[i - 1]));
    }
  }
  return std::numeric_limits<double>::infinity();
}

double miner_damage(const std::vector<double>& cycles, const std::vector<double>& allowed) {
  double D = 0.0;
  for (std::size_t i = 0; i < cycles.size() && i < allowed.size(); ++i) {
    if (std::isinf(allowed[i])) continue;
    D += allowed[i] > 0.0 ? cycles[i] / allowed[i] : std::numeric_limits<double>::infinity();
  }
  return D;
}

}  // namespace gearkit::gear::iso6336
