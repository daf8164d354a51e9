// Speeds, ratios, degrees of freedom and modes against the seeds, published examples and hand
// derivations, plus property tests on random trains.
#include "train_fixtures.hpp"

#include <gearkit/train/kinematics.hpp>
#include <gearkit/train/willis.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace gearkit::train {
namespace {

using namespace testing;

Rational ratio_of(const TrainModel& model, const std::vector<Condition>& conditions, const std::string& out,
                  const std::string& in) {
  const SpeedSolution s = solve_speeds(model, conditions);
  const auto r = speed_ratio(s, id(model, out), id(model, in));
  EXPECT_TRUE(r.has_value());
  return r.value_or(Rational(0));
}

// Seed 004, 2020-21 exam, exercise 2: tau_1 = w2/w1 = -35/90; with w5 = w1, tau_t = wb/w1 = 47/72.
TEST(Kinematics, SeedCvtTrainGives47Over72) {
  const TrainModel model = make_train_model(seed_cvt_train());
  const std::vector<Condition> c{couple(model, "5", "1"), input(model, "1")};
  EXPECT_EQ(ratio_of(model, c, "b", "1"), Rational(47, 72));
  EXPECT_EQ(ratio_of(model, c, "23", "1"), Rational(-35, 90));
  // Seed: 2 degrees of freedom before the coupling.
  EXPECT_EQ(analyse_structure(model).dof, 2u);
}

// Seed 004, exercise 2 b): tau_2 = (w5 - wb)/(w3 - wb) = -1/3 with the arm as reference.
TEST(Kinematics, SeedCvtTrainEpicyclicRelation) {
  const TrainModel model = make_train_model(seed_cvt_train());
  // Arm held: w5/w3 must be tau_2.
  EXPECT_EQ(ratio_of(model, {fix(model, "b"), input(model, "23")}, "5", "23"), Rational(-1, 3));
}

// Seed 004, second 2020-21 exam, exercise 1: w7/w1 = 7/5 (wb = 0), 9/7 (w45 = 0), 1 (wb = w45).
TEST(Kinematics, SeedTwoEpicyclicStagesModes) {
  const TrainModel model = make_train_model(seed_two_epicyclic_stages());
  EXPECT_EQ(analyse_structure(model).dof, 2u);
  EXPECT_EQ(ratio_of(model, {fix(model, "b"), input(model, "1")}, "7", "1"), Rational(7, 5));
  EXPECT_EQ(ratio_of(model, {fix(model, "45"), input(model, "1")}, "7", "1"), Rational(9, 7));
  EXPECT_EQ(ratio_of(model, {couple(model, "b", "45"), input(model, "1")}, "7", "1"), Rational(1));
  // Partial ratios of the seed: tau_1 = -2/5, tau_2 = -7/2 with the arm held.
  EXPECT_EQ(ratio_of(model, {fix(model, "b"), input(model, "1")}, "45", "1"), Rational(-2, 5));

  const auto modes = transmission_modes(model, {}, id(model, "1"), id(model, "7"));
  ASSERT_EQ(modes.size(), 3u);  // w_b = 0, w_45 = 0, w_b = w_45 (planets are not candidates)
  EXPECT_EQ(modes[0].label, "w_b = 0");
  EXPECT_EQ(modes[0].ratio.value(), Rational(7, 5));
  EXPECT_EQ(modes[1].label, "w_45 = 0");
  EXPECT_EQ(modes[1].ratio.value(), Rational(9, 7));
  EXPECT_EQ(modes[2].label, "w_b = w_45");
  EXPECT_EQ(modes[2].ratio.value(), Rational(1));

  // A fix among the base conditions is what the modes replace: the same three ratios.
  const auto again = transmission_modes(model, {fix(model, "b")}, id(model, "1"), id(model, "7"));
  ASSERT_EQ(again.size(), 3u);
  EXPECT_EQ(again[1].ratio.value(), Rational(9, 7));
}

// Seed 004 CVT train: the modes keep the base's couplings (w5 = w1 is a link of the machine).
// Holding 5 then holds the input too (contradictory); without the coupling the same mode would
// give, from the seed's equations with w5 = 0, w_b/w_1 = -tau_1 tau_2/(1 - tau_2) = -7/72.
TEST(Kinematics, ModesKeepCouplings) {
  const TrainModel model = make_train_model(seed_cvt_train());
  const auto with = transmission_modes(model, {couple(model, "5", "1")}, id(model, "1"), id(model, "b"));
  ASSERT_EQ(with.size(), 3u);  // w_23 = 0, w_5 = 0, w_23 = w_5 (b is the output, 4 a planet)
  EXPECT_EQ(with[0].label, "w_23 = 0");
  EXPECT_EQ(with[0].status, TransmissionMode::Status::contradictory);  // 23 is geared to the input
  EXPECT_EQ(with[1].label, "w_5 = 0");
  EXPECT_EQ(with[1].status, TransmissionMode::Status::contradictory);
  const auto without = transmission_modes(model, {}, id(model, "1"), id(model, "b"));
  EXPECT_EQ(without[1].ratio.value(), Rational(-7, 72));
}

// University of Ljubljana, LECAD "Analysis of Planetary Transmissions", test run
// (lecad.uni-lj.si/~leon/FS/PlanetryTransmissions/node8.html): sun 21 input, ring 108 fixed,
// planets 43, carrier output: transmission ratio 6.14286 (= w_sun / w_carrier).
TEST(Kinematics, PublishedLjubljanaPlanetary) {
  const TrainModel model = make_train_model(simple_planetary(21, 43, 108));
  const Rational r = ratio_of(model, {fix(model, "ring"), input(model, "sun")}, "sun", "carrier");
  EXPECT_NEAR(to_double(r), 6.14286, 5e-6);
  EXPECT_EQ(r, Rational(129, 21));
}

// homeworksource.com problem 1031202 ("planetary speed reducer ... the arm is the input"):
// sun A fixed (23 teeth), internal gear C (55 teeth) output, arm at 100 rpm -> 141.8 rpm.
TEST(Kinematics, PublishedArmInputSunFixed) {
  const TrainModel model = make_train_model(simple_planetary(23, 16, 55));
  const Rational r = ratio_of(model, {fix(model, "sun"), input(model, "carrier")}, "ring", "carrier");
  EXPECT_NEAR(100.0 * to_double(r), 141.8, 0.05);
  EXPECT_EQ(r, Rational(78, 55));
}

// realservices.com "Planetary gears" (Analytical Almanac): carrier held, sun input; ratio of planet
// to sun -24/16 = -3/2 for a 24-tooth sun and 16-tooth planets.
TEST(Kinematics, PublishedCarrierHeldPlanetSpeed) {
  const TrainModel model = make_train_model(simple_planetary(24, 16, 56));
  EXPECT_EQ(ratio_of(model, {fix(model, "carrier"), input(model, "sun")}, "planet", "sun"), Rational(-3, 2));
}

// Ravigneaux set (examples/trains/ravigneaux.yaml), hand derivation there: w_r/w_s1 = 50/77,
// w_c/w_s1 = 5/11 with the large sun held.
TEST(Kinematics, RavigneauxByHand) {
  TrainDescription d;
  d.members = {member("s1"), member("s2"), member("carrier"), member("ring"), member("short", "carrier"),
               member("long", "carrier")};
  d.gears = {gear("zs1", "s1", 30), gear("zs2", "s2", 36), gear("zshort", "short", 18), gear("zlong", "long", 24),
             gear("zring", "ring", 84, GearKind::internal)};
  d.meshes = {mesh("zs1", "zshort", "carrier"), mesh("zshort", "zlong", "carrier"), mesh("zlong", "zs2", "carrier"),
              mesh("zlong", "zring", "carrier")};
  const TrainModel model = make_train_model(d);
  EXPECT_EQ(analyse_structure(model).dof, 2u);
  const std::vector<Condition> c{fix(model, "s2"), input(model, "s1")};
  EXPECT_EQ(ratio_of(model, c, "ring", "s1"), Rational(50, 77));
  EXPECT_EQ(ratio_of(model, c, "carrier", "s1"), Rational(5, 11));
  // Carrier held: (w_r - w_c)/(w_s1 - w_c) = (-30/18)(-18/24)(+24/84) = 5/14 (reverse-type chain).
  EXPECT_EQ(ratio_of(model, {fix(model, "carrier"), input(model, "s1")}, "ring", "s1"), Rational(5, 14));
}

// Wolfrom train (examples/trains/wolfrom.yaml), hand derivation: w_r2/w_s = 1/76.
TEST(Kinematics, WolfromByHand) {
  TrainDescription d;
  d.members = {member("sun"), member("carrier"), member("planet", "carrier"), member("ring1"), member("ring2")};
  d.gears = {gear("s", "sun", 12), gear("p1", "planet", 24), gear("p2", "planet", 21),
             gear("r1", "ring1", 60, GearKind::internal), gear("r2", "ring2", 57, GearKind::internal)};
  d.meshes = {mesh("s", "p1", "carrier"), mesh("p1", "r1", "carrier"), mesh("p2", "r2", "carrier")};
  const TrainModel model = make_train_model(d);
  EXPECT_EQ(ratio_of(model, {fix(model, "ring1"), input(model, "sun")}, "ring2", "sun"), Rational(1, 76));
}

// Two fixed-axis stages of OTM 2015 problem 3 (seed 000): (15/60)(18/72) = 1/16.
TEST(Kinematics, OrdinaryTwoStageReducer) {
  TrainDescription d;
  d.members = {member("in"), member("mid"), member("out")};
  d.gears = {gear("1", "in", 15), gear("2", "mid", 60), gear("3", "mid", 18), gear("4", "out", 72)};
  d.meshes = {mesh("1", "2"), mesh("3", "4")};
  const TrainModel model = make_train_model(d);
  EXPECT_EQ(analyse_structure(model).dof, 1u);
  EXPECT_EQ(ratio_of(model, {input(model, "in")}, "out", "in"), Rational(1, 16));
  EXPECT_EQ(ratio_of(model, {input(model, "in")}, "mid", "in"), Rational(-1, 4));
}

TEST(Kinematics, UnderDeterminedNamesTheFreeMember) {
  const TrainModel model = make_train_model(simple_planetary(24, 18, 60));
  const SpeedSolution s = solve_speeds(model, {input(model, "sun")});
  EXPECT_EQ(s.remaining_dof, 1u);
  ASSERT_EQ(s.free_members.size(), 1u);
  EXPECT_EQ(model.member(s.free_members[0]).name, "carrier");
  EXPECT_FALSE(s.speeds[id(model, "ring")].determined);
  EXPECT_TRUE(s.speeds[id(model, "sun")].determined);
  EXPECT_FALSE(speed_ratio(s, id(model, "ring"), id(model, "sun")).has_value());
}

TEST(Kinematics, OverDeterminedConditionIsNamed) {
  const TrainModel model = make_train_model(simple_planetary(24, 18, 60));
  // Ring and carrier held lock the sun: an input speed on it contradicts them.
  try {
    solve_speeds(model, {fix(model, "ring"), fix(model, "carrier"), input(model, "sun")});
    FAIL() << "expected ConditionError";
  } catch (const ConditionError& e) {
    EXPECT_EQ(e.index(), 2u);
    EXPECT_NE(std::string(e.what()).find("input sun"), std::string::npos);
  }
}

TEST(Kinematics, RedundantConditionIsReported) {
  const TrainModel model = make_train_model(simple_planetary(24, 18, 60));
  const SpeedSolution s = solve_speeds(model, {fix(model, "ring"), fix(model, "carrier"), fix(model, "sun")});
  ASSERT_EQ(s.redundant_conditions.size(), 1u);
  EXPECT_EQ(s.redundant_conditions[0], 2u);
}

TEST(Kinematics, LockedLoopOfFixedAxisGears) {
  // Three external gears meshing in a triangle on fixed axes cannot turn.
  TrainDescription d;
  d.members = {member("a"), member("b"), member("c")};
  d.gears = {gear("ga", "a", 20), gear("gb", "b", 30), gear("gc", "c", 40)};
  d.meshes = {mesh("ga", "gb"), mesh("gb", "gc"), mesh("gc", "ga")};
  const Structure s = analyse_structure(make_train_model(d));
  EXPECT_EQ(s.dof, 0u);
  EXPECT_EQ(s.locked.size(), 3u);
}

TEST(Kinematics, ConsistentLoopIsRedundantNotLocked) {
  // Sun driving two planets explicitly drawn on the same carrier with the same ring: the second
  // planet repeats the constraints (statically indeterminate), the train keeps 2 DOF.
  TrainDescription d = simple_planetary(24, 18, 60);
  d.members.push_back(member("planet2", "carrier"));
  d.gears.push_back(gear("p2", "planet2", 18));
  d.meshes.push_back(mesh("s", "p2", "carrier"));
  d.meshes.push_back(mesh("p2", "r", "carrier"));
  const Structure s = analyse_structure(make_train_model(d));
  EXPECT_EQ(s.dof, 2u);
  EXPECT_TRUE(s.locked.empty());
}

// ---- Property tests on random compound trains --------------------------------------------------

// A random train of simple planetary stages and fixed-axis pairs whose members are shared at
// random, so that stages feed each other (compound trains of arbitrary shape).
TrainDescription random_train(std::mt19937& rng, int stages) {
  std::uniform_int_distribution<int> teeth(12, 90);
  std::uniform_int_distribution<int> coin(0, 2);
  TrainDescription d;
  std::vector<std::string> central;  // members turning about the main axis
  int counter = 0;
  const auto new_member = [&](const std::string& carried_by = "ground") {
    const std::string name = "m" + std::to_string(counter++);
    d.members.push_back(member(name, carried_by));
    if (carried_by == "ground") central.push_back(name);
    return name;
  };
  const auto pick_or_new = [&]() {
    if (!central.empty() && coin(rng) == 0) {
      std::uniform_int_distribution<std::size_t> pick(0, central.size() - 1);
      return central[pick(rng)];
    }
    return new_member();
  };
  for (int k = 0; k < stages; ++k) {
    const std::string tag = std::to_string(k);
    if (coin(rng) == 2) {  // a fixed-axis pair
      std::string a = pick_or_new(), b = new_member();
      d.gears.push_back(gear("fa" + tag, a, teeth(rng)));
      d.gears.push_back(gear("fb" + tag, b, teeth(rng)));
      d.meshes.push_back(mesh("fa" + tag, "fb" + tag));
      continue;
    }
    std::string sun = pick_or_new();
    std::string carrier = new_member();
    std::string ring = new_member();
    const std::string planet = new_member(carrier);
    const int zs = teeth(rng), zp = teeth(rng);
    d.gears.push_back(gear("s" + tag, sun, zs));
    d.gears.push_back(gear("p" + tag, planet, zp));
    d.gears.push_back(gear("r" + tag, ring, zs + 2 * zp, GearKind::internal));
    d.meshes.push_back(mesh("s" + tag, "p" + tag, carrier));
    d.meshes.push_back(mesh("p" + tag, "r" + tag, carrier));
  }
  return d;
}

// Willis' equation checked from the tooth counts, independently of willis_row():
// z_b (w_b - w_c) = s z_a (w_a - w_c), s = -1 external pair, +1 with an internal gear.
void expect_willis_holds(const TrainModel& model, const SpeedSolution& s, std::size_t input) {
  for (const Mesh& m : model.meshes()) {
    const Gear& a = model.gear(m.gear_a);
    const Gear& b = model.gear(m.gear_b);
    const int sign = (a.kind == GearKind::internal || b.kind == GearKind::internal) ? 1 : -1;
    const Rational& wa = s.speeds[a.member].per_input[input];
    const Rational& wb = s.speeds[b.member].per_input[input];
    const Rational& wc = s.speeds[m.carrier].per_input[input];
    EXPECT_EQ(Rational(b.z * (wb - wc)), Rational(sign * a.z * (wa - wc))) << "mesh " << m.name;
  }
}

TEST(KinematicsProperty, RandomTrainsSatisfyEveryWillisEquationExactly) {
  std::mt19937 rng(20261121);
  for (int trial = 0; trial < 60; ++trial) {
    const TrainModel model = make_train_model(random_train(rng, 1 + trial % 6));
    const Structure st = analyse_structure(model);
    std::vector<Condition> conditions;
    for (MemberId m : st.independent) conditions.push_back(Condition{Condition::Kind::input, m, ground, "in"});
    const SpeedSolution s = solve_speeds(model, conditions);
    ASSERT_EQ(s.remaining_dof, 0u) << "trial " << trial;
    for (const MemberSpeed& speed : s.speeds) ASSERT_TRUE(speed.determined);
    for (std::size_t i = 0; i < st.independent.size(); ++i) expect_willis_holds(model, s, i);
    // DOF = members without ground - rank: every independent input is needed exactly once.
    EXPECT_TRUE(s.redundant_conditions.empty());
  }
}

TEST(KinematicsProperty, FixingAMemberOfATwoDofTrainLeavesOne) {
  std::mt19937 rng(7);
  int checked = 0;
  for (int trial = 0; trial < 200 && checked < 40; ++trial) {
    const TrainModel model = make_train_model(random_train(rng, 1 + trial % 3));
    const Structure st = analyse_structure(model);
    if (st.dof != 2) continue;
    for (MemberId m = 1; m < model.member_count(); ++m) {
      if (std::find(st.locked.begin(), st.locked.end(), m) != st.locked.end()) continue;
      const SpeedSolution s = solve_speeds(model, {Condition{Condition::Kind::fix, m, ground, "fix"}});
      EXPECT_EQ(s.remaining_dof, 1u) << "trial " << trial << " member " << model.member(m).name;
    }
    ++checked;
  }
  EXPECT_GE(checked, 10);
}

}  // namespace
}  // namespace gearkit::train
