// Names of the factors a user may impose (`--factor NAME=VALUE`, `factors:` in a pair file).
#include <gearkit/gear/rating.hpp>

#include <array>

namespace gearkit::gear {

namespace {

constexpr std::array<std::string_view, kFactorCount> kNames = {
    "K_v", "K_Hbeta", "K_Fbeta", "K_Halpha", "K_Falpha",
    "Z_H", "Z_E", "Z_epsilon", "Z_beta", "Z_B", "Z_D", "Z_L", "Z_v", "Z_R", "Z_X",
    "Z_NT1", "Z_NT2", "Z_W1", "Z_W2",
    "Y_F1", "Y_F2", "Y_S1", "Y_S2", "Y_beta", "Y_B1", "Y_B2", "Y_DT",
    "Y_NT1", "Y_NT2", "Y_deltarelT1", "Y_deltarelT2", "Y_RrelT1", "Y_RrelT2", "Y_X1", "Y_X2", "Y_M1", "Y_M2",
    "K_s1", "K_s2", "K_m", "K_B1", "K_B2", "K_R", "J1", "J2", "I", "Y_N1", "Y_N2", "Z_N1", "Z_N2", "C_H", "C_f", "Y1", "Y2",
    "X_WrelT"};

bool ends_with_1(std::string_view s) { return !s.empty() && s.back() == '1'; }

}  // namespace

std::string_view factor_name(Factor f) { return kNames[static_cast<int>(f)]; }

std::vector<Factor> factors_named(std::string_view name) {
  for (int i = 0; i < kFactorCount; ++i) {
    if (kNames[i] == name) return {static_cast<Factor>(i)};
  }
  // A per-gear factor named without its gear number sets both gears.
  for (int i = 0; i + 1 < kFactorCount; ++i) {
    const std::string_view n = kNames[i];
    if (ends_with_1(n) && n.substr(0, n.size() - 1) == name) return {static_cast<Factor>(i), static_cast<Factor>(i + 1)};
  }
  return {};
}

std::string factor_names() {
  std::string s;
  for (const auto n : kNames) {
    if (!s.empty()) s += ", ";
    s += n;
  }
  return s;
}

}  // namespace gearkit::gear
