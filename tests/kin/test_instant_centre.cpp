// Instant centres against the seed's constructions and Kennedy's theorem.
#include <gearkit/kin/instant_centre.hpp>
#include <gearkit/kin/solve.hpp>

#include <gtest/gtest.h>

#include "mechanisms.hpp"

namespace gearkit::kin {
namespace {

using testing::kDeg;

// Seed 004, exam 2020-21 exercise 1 c): I_QR is where the horizontal line through Q meets the
// line OP; I_RT is on line OS and on the line through I_QR and R (three-centre theorem).
TEST(InstantCentre, PantographSeedConstruction) {
  Model m = testing::pantograph(-45 * kDeg);
  Data data(m);
  ASSERT_TRUE(solve_position(m, data, 0.0).converged);
  ASSERT_TRUE(solve_velocity(m, data));
  auto P = [&](int body, const char* name) { return point_position(data, testing::at(m, body, name)); };
  const Eigen::Vector2d O(0, 0), Pp = P(0, "P"), Q = P(1, "Q"), R = P(1, "R"), S = P(4, "S");
  const auto i_qr = instant_centre(data, 1);
  ASSERT_TRUE(i_qr);
  const auto expected_qr = line_intersection(Q, Q + Eigen::Vector2d(1, 0), O, Pp);
  ASSERT_TRUE(expected_qr);
  EXPECT_NEAR((*i_qr - *expected_qr).norm(), 0.0, 1e-10);
  const auto i_rt = instant_centre(data, 3);
  const auto expected_rt = line_intersection(O, S, *i_qr, R);
  ASSERT_TRUE(i_rt && expected_rt);
  EXPECT_NEAR((*i_rt - *expected_rt).norm(), 0.0, 1e-10);
}

// Kennedy: I_ij, I_0i and I_0j are collinear for every pair of a four-bar's links; and the
// crank's centre is its ground pivot.
TEST(InstantCentre, KennedyCollinearity) {
  Model m = testing::four_bar({0.04, 0.12, 0.08, 0.1}, 35 * kDeg);
  Data data(m);
  ASSERT_TRUE(solve_position(m, data, 0.0).converged);
  ASSERT_TRUE(solve_velocity(m, data));
  EXPECT_NEAR(instant_centre(data, 0)->norm(), 0.0, 1e-12);
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const auto ij = instant_centre(data, i, j), i0 = instant_centre(data, i), j0 = instant_centre(data, j);
      ASSERT_TRUE(ij && i0 && j0);
      EXPECT_NEAR(cross(*i0 - *ij, *j0 - *ij), 0.0, 1e-12) << i << j;
    }
  // The coupler's centre relative to the crank is the joint A.
  EXPECT_NEAR((*instant_centre(data, 1, 0) - point_position(data, testing::at(m, 0, "A"))).norm(), 0.0, 1e-12);
}

TEST(InstantCentre, TranslationHasNoCentre) {
  Model m = testing::pantograph(-45 * kDeg);
  Data data(m);
  ASSERT_TRUE(solve_position(m, data, 0.0).converged);
  ASSERT_TRUE(solve_velocity(m, data));
  EXPECT_FALSE(instant_centre(data, 2));  // the slider only translates
  EXPECT_FALSE(line_intersection({0, 0}, {1, 0}, {0, 1}, {2, 1}));
}

// A seat carried by a parallelogram (seed OTM 2015 problem 1) translates, but its computed angular
// speed is rounding noise, not 0: with v = 0.75 m/s and omega = 1e-17 rad/s the centre would sit
// v/omega = 7.5e16 m away. It is a translation; a real rotation about a far point stays a centre.
TEST(InstantCentre, RoundingNoiseRotationIsATranslation) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(3), v(3);
  q << 1.2, -0.4, 0.0;
  v << 0.0, 0.75, 1e-17;
  EXPECT_FALSE(instant_centre(q, v, 0));
  v << 0.0, 0.75, 0.75 / 500.0;  // about a point 500 m away: still a centre, at (1.2 - 500, -0.4)
  const auto c = instant_centre(q, v, 0);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->x(), 1.2 - 500.0, 1e-9);
  EXPECT_NEAR(c->y(), -0.4, 1e-9);
}

}  // namespace
}  // namespace gearkit::kin
