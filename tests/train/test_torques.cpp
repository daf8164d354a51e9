// Torques by Willis' method: hand derivations, power balance on random trains, efficiency.
#include "train_fixtures.hpp"

#include <gearkit/train/torques.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace gearkit::train {
namespace {

using namespace testing;

// Simple planetary, ring fixed, 10 N*m on the sun (input), load on the carrier. Moment balance
// about the axis and the tooth force F = T_s / r_s give, by hand:
//   T_ring = T_s z_r / z_s,  T_carrier = -T_s (1 + z_r / z_s).
TEST(Torques, IdealSimplePlanetaryByHand) {
  const TrainModel model = make_train_model(simple_planetary(24, 18, 60));
  const std::vector<Condition> c{fix(model, "ring"), input(model, "sun")};
  const TorqueSolution t = solve_torques(model, c, id(model, "carrier"), id(model, "sun"));
  ASSERT_TRUE(t.balanced);
  EXPECT_EQ(t.external[id(model, "sun")].value(), Rational(1));
  EXPECT_EQ(t.external[id(model, "ring")].value(), Rational(60, 24));
  EXPECT_EQ(t.external[id(model, "carrier")].value(), Rational(-84, 24));
  EXPECT_EQ(t.external[id(model, "planet")].value(), Rational(0));
}

// Seed 004 CVT train with w5 = w1 (coupling) and a load on the arm. The coupling is internal to
// the machine: it carries a torque between members 5 and 1 but no net power. With 1 N*m given on
// member 1 at unit speed and w_b = 47/72: T_b = -72/47 (power balance), nothing else external.
TEST(Torques, IdealCouplingKeepsPowerBalance) {
  const TrainModel model = make_train_model(seed_cvt_train());
  const std::vector<Condition> c{couple(model, "5", "1"), input(model, "1")};
  const TorqueSolution t = solve_torques(model, c, id(model, "b"), id(model, "1"));
  ASSERT_TRUE(t.balanced);
  EXPECT_EQ(*t.external[id(model, "1")], Rational(1));
  EXPECT_EQ(*t.external[id(model, "5")], Rational(0));
  EXPECT_EQ(*t.external[id(model, "b")], Rational(-72, 47));
  // The coupling torque on 5 balances ring 5 alone. Ring 5 meshes planet 4 on arm b; planet 4
  // meshes sun 3 (member 23), which meshes gear 1 through 2: by hand, from the moment balance of
  // the epicyclic part, T_5 = T_3 z_5/z_3 = 3 T_3 and T_b = -(T_3 + T_5) = -4 T_3, so
  // T_5 = -(3/4) T_b = 54/47.
  ASSERT_TRUE(t.coupling[0].has_value());
  EXPECT_EQ(*t.coupling[0], Rational(54, 47));
}

// Willis' efficiency method for ring fixed, sun driving, carrier output (Müller, "Epicyclic Drive
// Trains", minus-gear, sun driving in the carrier frame): eta = (z_s + eta0 z_r) / (z_s + z_r) with
// eta0 the sun-to-ring efficiency with the carrier held (product of the two meshes).
TEST(Torques, EfficiencyOfSimplePlanetaryMatchesWillisFormula) {
  const TrainModel model = make_train_model(simple_planetary(24, 18, 60, 0.98, 0.99));
  const std::vector<Condition> c{fix(model, "ring"), input(model, "sun")};
  const SpeedSolution s = solve_speeds(model, c);
  const double w = 3000 * 2 * std::numbers::pi / 60;
  const PowerFlow f = analyse_power_flow(model, c, s, {w}, id(model, "carrier"), id(model, "sun"), 10.0);
  const double eta0 = 0.98 * 0.99;
  ASSERT_TRUE(f.efficiency.has_value());
  EXPECT_NEAR(*f.efficiency, (24 + eta0 * 60) / 84.0, 1e-12);
  ASSERT_TRUE(f.efficiency_exact.has_value());
  EXPECT_NEAR(to_double(*f.efficiency_exact), (24 + eta0 * 60) / 84.0, 1e-15);
  // Ring reaction with losses: eta0 T_s z_r / z_s.
  EXPECT_NEAR(f.torque_losses_Nm[id(model, "ring")].value(), eta0 * 10 * 60 / 24.0, 1e-9);
  EXPECT_EQ(f.drivers[0], MeshDriver::gear_a);  // sun gives power to the planet
  EXPECT_EQ(f.drivers[1], MeshDriver::gear_a);  // planet gives power to the ring
  EXPECT_FALSE(f.power_circulation);
}

// The same set driven from the carrier with the sun as output (step-up). In the carrier frame the
// ring now drives: both meshes flip direction and the receiving gear's torque is scaled by eta:
//   planet: mu1 z_p = mu2 eta_pr z_p;  T_s = -mu2 eta0 z_s,  T_r = -mu2 z_r  ->  T_s = eta0 (z_s/z_r) T_r
//   axis balance T_s + T_r + T_c = 0   ->  T_r = -T_c / (1 + eta0 z_s/z_r).
TEST(Torques, ReversedPowerFlowFlipsMeshDirections) {
  const TrainModel model = make_train_model(simple_planetary(24, 18, 60, 0.98, 0.99));
  const std::vector<Condition> c{fix(model, "ring"), input(model, "carrier")};
  const SpeedSolution s = solve_speeds(model, c);
  const PowerFlow f = analyse_power_flow(model, c, s, {100.0}, id(model, "sun"), id(model, "carrier"), 35.0);
  EXPECT_EQ(f.drivers[0], MeshDriver::gear_b);  // planet gives power to the sun
  EXPECT_EQ(f.drivers[1], MeshDriver::gear_b);  // ring gives power to the planet
  const double eta0 = 0.98 * 0.99, zs = 24, zr = 60, tc = 35.0;
  const double tr = -tc / (1 + eta0 * zs / zr);
  const double ts = tr * eta0 * zs / zr;
  EXPECT_NEAR(f.torque_losses_Nm[id(model, "sun")].value(), ts, 1e-9);
  EXPECT_NEAR(f.torque_losses_Nm[id(model, "ring")].value(), tr, 1e-9);
  // Efficiency -T_s w_s / (T_c w_c) with w_s = 3.5 w_c.
  EXPECT_NEAR(f.efficiency.value(), -ts * 3.5 / tc, 1e-12);
}

// Power balance on random 1-DOF configurations: sum over members of T w = 0, exactly.
TEST(TorquesProperty, IdealTorquesBalancePowerExactly) {
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> teeth(12, 80);
  int checked = 0;
  for (int trial = 0; trial < 80; ++trial) {
    // A chain of simple planetary stages: carrier of one stage drives the sun of the next,
    // rings held or coupled at random to earlier members.
    TrainDescription d;
    const int stages = 1 + trial % 4;
    d.members.push_back(member("in"));
    std::string previous = "in";
    std::vector<Condition> conditions;
    std::vector<std::string> rings;
    for (int k = 0; k < stages; ++k) {
      const std::string tag = std::to_string(k);
      d.members.push_back(member("c" + tag));
      d.members.push_back(member("r" + tag));
      d.members.push_back(member("p" + tag, "c" + tag));
      const int zs = teeth(rng), zp = teeth(rng);
      d.gears.push_back(gear("gs" + tag, previous, zs));
      d.gears.push_back(gear("gp" + tag, "p" + tag, zp));
      d.gears.push_back(gear("gr" + tag, "r" + tag, zs + 2 * zp, GearKind::internal));
      d.meshes.push_back(mesh("gs" + tag, "gp" + tag, "c" + tag));
      d.meshes.push_back(mesh("gp" + tag, "gr" + tag, "c" + tag));
      rings.push_back("r" + tag);
      previous = "c" + tag;
    }
    const TrainModel model = make_train_model(d);
    std::uniform_int_distribution<int> coin(0, 1);
    for (std::size_t k = 0; k < rings.size(); ++k) {
      if (k > 0 && coin(rng)) conditions.push_back(couple(model, rings[k], "in"));
      else conditions.push_back(fix(model, rings[k]));
    }
    conditions.push_back(input(model, "in"));
    const SpeedSolution s = solve_speeds(model, conditions);
    if (s.remaining_dof != 0) continue;
    const MemberId out = id(model, previous);
    if (s.speeds[out].per_input[0] == 0) continue;
    const TorqueSolution t = solve_torques(model, conditions, out, id(model, "in"));
    ASSERT_TRUE(t.balanced);
    Rational power(0);
    for (MemberId m = 1; m < model.member_count(); ++m) power += t.external[m].value() * s.speeds[m].per_input[0];
    EXPECT_EQ(power, Rational(0)) << "trial " << trial;
    // And each member is in equilibrium: external + mesh torques = 0 (checked through the output
    // torque against the ratio: T_out = -T_in / ratio).
    EXPECT_EQ(t.external[out].value(), Rational(-1 / s.speeds[out].per_input[0]));
    ++checked;
  }
  EXPECT_GE(checked, 40);
}

TEST(Torques, NoLoadPathIsReported) {
  // Sun input with nothing held: the given torque cannot be balanced (the train is free).
  const TrainModel model = make_train_model(simple_planetary(24, 18, 60));
  const TorqueSolution t = solve_torques(model, {input(model, "sun")}, id(model, "ring"), id(model, "sun"));
  EXPECT_FALSE(t.balanced);
  EXPECT_FALSE(t.message.empty());
}

TEST(Torques, RejectsGroundAsOutput) {
  const TrainModel model = make_train_model(simple_planetary(24, 18, 60));
  EXPECT_THROW(solve_torques(model, {}, ground, id(model, "sun")), std::invalid_argument);
}

}  // namespace
}  // namespace gearkit::train
