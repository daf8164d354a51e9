// Tests for gearkit/gear/iso6336_life.hpp: life lines of ISO 6336-2/-3 and Miner's rule.
#include <gearkit/gear/iso6336_life.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace iso = gearkit::gear::iso6336;
using gearkit::gear::MaterialClass;

TEST(LifeLines, KneePointsOfTheTables) {
  // ISO 6336-2:2019 Table 2, line for St, V, Eh... without pitting: 1.6 up to 1e5, 1.0 at 5e7, 0.85 at 1e10.
  const auto Z = iso::pitting_life_line(MaterialClass::case_carburized, false, false);
  EXPECT_DOUBLE_EQ(iso::life_factor(Z, 1e4), 1.6);
  EXPECT_NEAR(iso::life_factor(Z, 5e7), 1.0, 1e-12);
  EXPECT_NEAR(iso::life_factor(Z, 1e10), 0.85, 1e-12);
  EXPECT_NEAR(iso::life_factor(Z, 1e12), 0.85, 1e-12);
  // Log-log interpolation: ISO/TR 6336-30 example 1 gives Z_NT = 0.910 at 1.08e9 cycles.
  EXPECT_NEAR(iso::life_factor(Z, 1.08e9), 0.910, 0.0005);
  // Y_NT for case-carburized steel (ISO 6336-3:2019 Table 3): 2.5 up to 1e3, 1 at 3e6.
  const auto Y = iso::root_life_line(MaterialClass::case_carburized, false);
  EXPECT_DOUBLE_EQ(iso::life_factor(Y, 1e3), 2.5);
  EXPECT_NEAR(iso::life_factor(Y, 3e6), 1.0, 1e-12);
  const auto Yst = iso::root_life_line(MaterialClass::through_hardened_alloy, false);
  EXPECT_DOUBLE_EQ(iso::life_factor(Yst, 1e4), 2.5);
}

TEST(LifeLines, CyclesAtFactorInvertsTheLine) {
  const auto Z = iso::pitting_life_line(MaterialClass::nitrided, false, false);
  for (double N : {2e5, 1e6, 3e6, 1e8, 5e9}) EXPECT_NEAR(iso::cycles_at_factor(Z, iso::life_factor(Z, N)) / N, 1.0, 1e-9);
  EXPECT_TRUE(std::isinf(iso::cycles_at_factor(Z, 0.8)));
  EXPECT_DOUBLE_EQ(iso::cycles_at_factor(Z, 1.5), 0.0);
}

TEST(Miner, SumsTheCycleRatios) {
  EXPECT_DOUBLE_EQ(iso::miner_damage({1e6, 2e6}, {4e6, 8e6}), 0.5);
  EXPECT_DOUBLE_EQ(iso::miner_damage({1e6}, {INFINITY}), 0.0);
}
