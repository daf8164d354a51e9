#include "train_fixtures.hpp"

#include <gearkit/train/assembly.hpp>

#include <gtest/gtest.h>

#include <numbers>

namespace gearkit::train {
namespace {

using namespace testing;

const AssemblyCheck* find(const std::vector<AssemblyCheck>& checks, const std::string& condition) {
  for (const auto& c : checks)
    if (c.condition == condition) return &c;
  return nullptr;
}

TrainDescription with_module(TrainDescription d, double m) {
  for (auto& g : d.gears) g.module_mm = m;
  return d;
}

// The LECAD test run (lecad.uni-lj.si/~leon/FS/PlanetryTransmissions/node8.html): sun 21, three
// planets 43, ring 108: (21 + 108)/3 = 43, equally spaced. Its zero-shift centre distances differ
// (the source uses profile shift to make them equal), so coaxiality fails without shifts.
TEST(Assembly, LjubljanaSetSpacingAndCoaxialityWithoutShift) {
  const TrainModel model = make_train_model(with_module(simple_planetary(21, 43, 108, 1, 1, 3), 1.75));
  const auto checks = check_assembly(model);
  ASSERT_NE(find(checks, "equal spacing"), nullptr);
  EXPECT_TRUE(find(checks, "equal spacing")->satisfied);
  const AssemblyCheck* coax = find(checks, "coaxiality");
  ASSERT_NE(coax, nullptr);
  EXPECT_TRUE(coax->checked);
  EXPECT_FALSE(coax->satisfied);  // 1.75 (21+43)/2 = 56 mm against 1.75 (108-43)/2 = 56.875 mm
}

TEST(Assembly, CentreDistanceFunctionIsUsed) {
  // With profile shift the reference function gives up; an injected working centre distance
  // (here a stand-in returning the same value for both meshes) decides.
  TrainDescription d = with_module(simple_planetary(21, 43, 108, 1, 1, 3), 1.75);
  d.gears[0].x = 0.438;
  d.gears[1].x = 0.0426;
  const TrainModel model = make_train_model(d);
  EXPECT_FALSE(find(check_assembly(model), "coaxiality")->checked);
  const auto working = [](const Gear&, const Gear&) -> std::optional<double> { return 56.8; };
  const auto checks = check_assembly(model, working);
  const AssemblyCheck* coax = find(checks, "coaxiality");
  EXPECT_TRUE(coax->checked);
  EXPECT_TRUE(coax->satisfied);
}

// Issue 11 item 8: two planets on a carrier that mesh no central gear read central[0] of an
// empty list (a segfault). Nothing can be spaced against: the check says so.
TEST(Assembly, PlanetsThatMeshNoCentralGearAreNotChecked) {
  TrainDescription d;
  d.members = {{"a", "ground", 1}, {"p", "a", 2}};
  const auto checks = check_assembly(make_train_model(d));
  const AssemblyCheck* spacing = find(checks, "equal spacing");
  ASSERT_NE(spacing, nullptr);
  EXPECT_FALSE(spacing->checked);
  EXPECT_NE(spacing->detail.find("meshes no central gear"), std::string::npos) << spacing->detail;
}

// Equal spacing of a simple planetary: (z_s + z_r)/N integer.
TEST(Assembly, EqualSpacingSimplePlanetary) {
  const TrainModel ok = make_train_model(simple_planetary(24, 18, 60, 1, 1, 3));  // 84/3 = 28
  EXPECT_TRUE(find(check_assembly(ok), "equal spacing")->satisfied);
  const TrainModel bad = make_train_model(simple_planetary(25, 18, 61, 1, 1, 3));  // 86/3
  EXPECT_FALSE(find(check_assembly(bad), "equal spacing")->satisfied);
}

// Stepped planet (seed 004, second exam: z1 = 48 sun, planet 24/18, ring 90), three planets:
// (z1 z3 + z4 z2)/(N gcd(z2, z3)) = (864 + 2160)/(3*6) = 168, an integer.
TEST(Assembly, SteppedPlanetSpacing) {
  TrainDescription d;
  d.members = {member("1"), member("b"), member("45"), member("23", "b", 3)};
  d.gears = {gear("z1", "1", 48), gear("z2", "23", 24), gear("z3", "23", 18), gear("z4", "45", 90, GearKind::internal)};
  d.meshes = {mesh("z1", "z2", "b"), mesh("z3", "z4", "b")};
  EXPECT_TRUE(find(check_assembly(make_train_model(d)), "equal spacing")->satisfied);
  // Four planets: 3024 / (4*6) = 126 still integer; five: 3024/30 is not.
  d.members[3].planet_count = 5;
  EXPECT_FALSE(find(check_assembly(make_train_model(d)), "equal spacing")->satisfied);
}

// Neighbour clearance in modules: (z_s + z_p) sin(pi/N) > z_p + 2.
TEST(Assembly, NeighbourClearance) {
  // Sun 12, planets 30, ring 72, N = 4: (42) sin 45 deg = 29.7 < 32 -> collide.
  const TrainModel bad = make_train_model(simple_planetary(12, 30, 72, 1, 1, 4));
  EXPECT_FALSE(find(check_assembly(bad), "neighbour clearance")->satisfied);
  const TrainModel ok = make_train_model(simple_planetary(24, 18, 60, 1, 1, 3));
  EXPECT_TRUE(find(check_assembly(ok), "neighbour clearance")->satisfied);
}

TEST(Assembly, InternalGearMustBeLarger) {
  const TrainModel model = make_train_model(simple_planetary(24, 18, 16));
  EXPECT_FALSE(find(check_assembly(model), "internal mesh")->satisfied);
}

TEST(Assembly, ReferenceCentreDistance) {
  Gear a, b;
  a.z = 15;
  b.z = 60;
  a.module_mm = b.module_mm = 6.0;
  // OTM 2015 problem 3: a = 6/2 (15 + 60) = 225 mm.
  EXPECT_DOUBLE_EQ(reference_centre_distance(a, b).value(), 225.0);
  b.kind = GearKind::internal;
  EXPECT_DOUBLE_EQ(reference_centre_distance(a, b).value(), 135.0);
  b.module_mm = 5.0;
  EXPECT_FALSE(reference_centre_distance(a, b).has_value());
}

// Helical pair (ISO 21771): a = m_n (z1 + z2) / (2 cos beta) = 2 (20 + 40) / (2 cos 15 deg)
// = 62.1166 mm.
TEST(Assembly, HelicalReferenceCentreDistance) {
  Gear a, b;
  a.z = 20;
  b.z = 40;
  a.module_mm = b.module_mm = 2.0;
  a.beta = 15.0 * std::numbers::pi / 180.0;
  b.beta = -a.beta;
  EXPECT_NEAR(reference_centre_distance(a, b).value(), 62.1166, 5e-5);
}

}  // namespace
}  // namespace gearkit::train
