// Model checks: every bad description is rejected with a message naming the culprit.
#include "train_fixtures.hpp"

#include <gearkit/train/model.hpp>

#include <gtest/gtest.h>

#include <numbers>

namespace gearkit::train {
namespace {

using namespace testing;

// Expects make_train_model to throw ModelError on `item` `index`, with `words` in the message.
void expect_error(const TrainDescription& d, ModelError::Item item, std::size_t index, const std::string& words) {
  try {
    make_train_model(d);
    FAIL() << "expected ModelError containing '" << words << "'";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.item(), item);
    EXPECT_EQ(e.index(), index);
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(Model, PressureAndHelixAngles) {
  const double deg = std::numbers::pi / 180.0;
  TrainDescription d = simple_planetary(24, 18, 60);
  EXPECT_DOUBLE_EQ(make_train_model(d).gear(0).alpha_n, 20.0 * deg);  // the documented default
  d.gears[0].alpha_n = 45.0 * deg;
  expect_error(d, ModelError::Item::gear, 0, "pressure angle in (0, 45) deg");
  d.gears[0].alpha_n = 25.0 * deg;
  expect_error(d, ModelError::Item::mesh, 0, "pressure angles 25 deg and 20 deg");
  for (auto& g : d.gears) g.alpha_n = 25.0 * deg;
  EXPECT_NO_THROW(make_train_model(d));
  // External sun-planet: opposite hands; internal planet-ring: the same hand.
  d.gears[0].beta = 20.0 * deg;
  d.gears[1].beta = -20.0 * deg;
  expect_error(d, ModelError::Item::mesh, 1, "same helix angle (same hand)");
  d.gears[2].beta = -20.0 * deg;
  EXPECT_NO_THROW(make_train_model(d));
  d.gears[1].beta = 20.0 * deg;
  expect_error(d, ModelError::Item::mesh, 0, "opposite helix angles");
  d.gears[1].beta = -50.0 * deg;
  expect_error(d, ModelError::Item::gear, 1, "helix angle in (-45, 45) deg");
}

TEST(Model, BuildsAndResolvesNames) {
  const TrainModel model = make_train_model(simple_planetary(24, 18, 60));
  EXPECT_EQ(model.member_count(), 5u);  // ground + 4
  EXPECT_EQ(model.member(ground).name, "ground");
  EXPECT_TRUE(model.is_planet(id(model, "planet")));
  EXPECT_FALSE(model.is_planet(id(model, "sun")));
  EXPECT_EQ(model.mesh(0).name, "s-p");
  EXPECT_EQ(model.gear(2).kind, GearKind::internal);
}

TEST(Model, MeshBetweenGearsOnTheSameMember) {
  TrainDescription d = simple_planetary(24, 18, 60);
  d.gears.push_back(gear("s2", "sun", 30));
  d.meshes.push_back(mesh("s", "s2"));
  expect_error(d, ModelError::Item::mesh, 2, "both on member 'sun'");
}

TEST(Model, GearOnUnknownMember) {
  TrainDescription d = simple_planetary(24, 18, 60);
  d.gears[1].member = "planett";
  expect_error(d, ModelError::Item::gear, 1, "unknown member 'planett'");
}

TEST(Model, NonPositiveTeeth) {
  TrainDescription d = simple_planetary(24, 18, 60);
  d.gears[0].z = 0;
  expect_error(d, ModelError::Item::gear, 0, "z > 0");
  d.gears[0].z = -5;
  expect_error(d, ModelError::Item::gear, 0, "found -5");
}

TEST(Model, UnknownCarrier) {
  TrainDescription d = simple_planetary(24, 18, 60);
  d.meshes[0].carrier = "arm";
  expect_error(d, ModelError::Item::mesh, 0, "carrier 'arm' is not a member");
}

TEST(Model, InternalInternalMesh) {
  TrainDescription d = simple_planetary(24, 18, 60);
  d.gears[1].kind = GearKind::internal;
  expect_error(d, ModelError::Item::mesh, 1, "both internal");
}

TEST(Model, MeshNotHeldByItsCarrier) {
  // Sun and ring are coaxial: they cannot mesh directly on the carrier.
  TrainDescription d = simple_planetary(24, 18, 60);
  d.meshes[1] = mesh("s", "r", "carrier");
  expect_error(d, ModelError::Item::mesh, 1, "neither 'sun' nor 'ring' is a planet");
  // A planet meshing on fixed axes: its axis moves with the carrier.
  TrainDescription e = simple_planetary(24, 18, 60);
  e.meshes[0].carrier = "ground";
  expect_error(e, ModelError::Item::mesh, 0, "carried by 'carrier'");
}

TEST(Model, DuplicateAndReservedNames) {
  TrainDescription d = simple_planetary(24, 18, 60);
  d.members.push_back(member("sun"));
  expect_error(d, ModelError::Item::member, 4, "declared twice");
  TrainDescription e = simple_planetary(24, 18, 60);
  e.members.push_back(member("ground"));
  expect_error(e, ModelError::Item::member, 4, "implicit");
}

TEST(Model, CarriedByLoopAndUnknown) {
  TrainDescription d;
  d.members = {member("a", "b"), member("b", "a")};
  expect_error(d, ModelError::Item::member, 0, "loops");
  TrainDescription e;
  e.members = {member("a", "zz")};
  expect_error(e, ModelError::Item::member, 0, "unknown member 'zz'");
}

TEST(Model, EfficiencyOutOfRange) {
  TrainDescription d = simple_planetary(24, 18, 60, 1.2);
  expect_error(d, ModelError::Item::mesh, 0, "efficiency in (0, 1]");
}

TEST(Model, UnknownGearInMesh) {
  TrainDescription d = simple_planetary(24, 18, 60);
  d.meshes[0].gear_b = "q";
  expect_error(d, ModelError::Item::mesh, 0, "unknown gear 'q'");
}

}  // namespace
}  // namespace gearkit::train
