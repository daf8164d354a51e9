// Grashof classes and the transmission angle.
#include <gearkit/kin/fourbar.hpp>
#include <gearkit/kin/solve.hpp>

#include <gtest/gtest.h>

#include "mechanisms.hpp"

namespace gearkit::kin {
namespace {

using testing::kDeg;

// Grashof condition s + l <= p + q (Norton, Design of Machinery, sec. 2.12).
TEST(Grashof, Classes) {
  EXPECT_EQ(grashof(0.10, 0.04, 0.12, 0.08).kind, GrashofClass::crank_rocker);
  EXPECT_EQ(grashof(0.04, 0.10, 0.12, 0.08).kind, GrashofClass::double_crank);
  EXPECT_EQ(grashof(0.10, 0.08, 0.04, 0.12).kind, GrashofClass::double_rocker);
  EXPECT_EQ(grashof(0.10, 0.05, 0.10, 0.05).kind, GrashofClass::change_point);
  EXPECT_EQ(grashof(0.12, 0.08, 0.09, 0.10).kind, GrashofClass::triple_rocker);
  EXPECT_NE(grashof(0.10, 0.04, 0.12, 0.08).text.find("crank-rocker"), std::string::npos);
  // In mm, as every report: s + l = 40 + 120 mm, p + q = 100 + 80 mm.
  EXPECT_NE(grashof(0.10, 0.04, 0.12, 0.08).text.find("(s + l = 160 mm < p + q = 180 mm)"), std::string::npos)
      << grashof(0.10, 0.04, 0.12, 0.08).text;
}

// Transmission angle by the law of cosines on triangle A B O4 (diagonal z = |A O4|):
// cos(mu) = (b^2 + c^2 - z^2) / (2 b c), taken acute.
TEST(TransmissionAngle, MatchesLawOfCosines) {
  const testing::FourBarDims f{0.040, 0.120, 0.080, 0.100};
  for (double deg : {0.0, 45.0, 120.0, 180.0, 270.0}) {
    Model m = testing::four_bar(f, deg * kDeg);
    const auto fb = find_four_bar(m);
    ASSERT_TRUE(fb);
    EXPECT_NEAR(fb->crank_length, f.a, 1e-12);
    EXPECT_NEAR(fb->coupler_length, f.b, 1e-12);
    EXPECT_NEAR(fb->rocker_length, f.c, 1e-12);
    EXPECT_NEAR(fb->ground, f.d, 1e-12);
    Data data(m);
    ASSERT_TRUE(solve_position(m, data, 0.0).converged);
    const double th = deg * kDeg;
    const double z2 = f.a * f.a + f.d * f.d - 2 * f.a * f.d * std::cos(th);
    double mu = std::acos((f.b * f.b + f.c * f.c - z2) / (2 * f.b * f.c));
    if (mu > M_PI / 2) mu = M_PI - mu;
    EXPECT_NEAR(transmission_angle(*fb, data), mu, 1e-9) << deg;
  }
}

TEST(FindFourBar, RejectsOtherMechanisms) {
  EXPECT_FALSE(find_four_bar(testing::pantograph(-50 * kDeg)));
  EXPECT_FALSE(find_four_bar(Model{}));
}

}  // namespace
}  // namespace gearkit::kin
