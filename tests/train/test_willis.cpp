#include "train_fixtures.hpp"

#include <gearkit/train/willis.hpp>

#include <gtest/gtest.h>

namespace gearkit::train {
namespace {

using namespace testing;

// Seed 004 CVT train: tau_1 = -z1/z2 = -35/90 on fixed axes (as the seed writes it).
TEST(Willis, FixedAxisPairAsTheSeedWritesIt) {
  const TrainModel model = make_train_model(seed_cvt_train());
  EXPECT_EQ(willis_equation_text(model, 0), "w_23 / w_1 = -35/90");
  EXPECT_EQ(willis_linear_text(model, 0), "90·w_23 + 35·w_1 = 0");
  EXPECT_EQ(basic_ratio(model, 0), Rational(-35, 90));
}

TEST(Willis, PlanetMeshRelativeToTheArm) {
  const TrainModel model = make_train_model(seed_cvt_train());
  EXPECT_EQ(willis_equation_text(model, 2), "(w_5 - w_b) / (w_4 - w_b) = +20/60");
  EXPECT_EQ(willis_linear_text(model, 2), "60·(w_5 - w_b) - 20·(w_4 - w_b) = 0");
  EXPECT_EQ(basic_ratio(model, 2), Rational(1, 3));
}

TEST(Willis, CoefficientsAndMergedRow) {
  const TrainModel model = make_train_model(simple_planetary(24, 18, 60));
  // Sun-planet, external: 18 (w_p - w_c) + 24 (w_s - w_c) = 0.
  const WillisCoefficients c = willis_coefficients(model, 0);
  EXPECT_EQ(c.on_a, 24);
  EXPECT_EQ(c.on_b, 18);
  EXPECT_EQ(c.on_carrier, -42);
  const auto row = willis_row(model, 0);
  ASSERT_EQ(row.size(), 3u);
  EXPECT_EQ(row[0], (std::pair<MemberId, long long>{id(model, "sun"), 24}));
  EXPECT_EQ(row[1], (std::pair<MemberId, long long>{id(model, "carrier"), -42}));
  EXPECT_EQ(row[2], (std::pair<MemberId, long long>{id(model, "planet"), 18}));
  // Planet-ring, internal: 60 (w_r - w_c) - 18 (w_p - w_c) = 0.
  const WillisCoefficients d = willis_coefficients(model, 1);
  EXPECT_EQ(d.on_a, -18);
  EXPECT_EQ(d.on_b, 60);
  EXPECT_EQ(d.on_carrier, -42);
}

TEST(Willis, GearOnTheCarrierMergesIntoItsCoefficient) {
  // A gear fixed to the arm meshing a planet: -18 w_c... the row keeps only planet and carrier.
  TrainDescription d;
  d.members = {member("arm"), member("planet", "arm")};
  d.gears = {gear("ga", "arm", 30), gear("gp", "planet", 18)};
  d.meshes = {mesh("ga", "gp", "arm")};
  const TrainModel model = make_train_model(d);
  const auto row = willis_row(model, 0);
  ASSERT_EQ(row.size(), 2u);  // 18 (w_p - w_a) + 30 (w_a - w_a) = 0
  EXPECT_EQ(row[0].second, -18);
  EXPECT_EQ(row[1].second, 18);
}

TEST(Willis, SignOfBasicRatio) {
  Gear a, b;
  a.z = 20;
  b.z = 40;
  EXPECT_EQ(basic_ratio_sign(a, b), -1);
  b.kind = GearKind::internal;
  EXPECT_EQ(basic_ratio_sign(a, b), +1);
}

}  // namespace
}  // namespace gearkit::train
