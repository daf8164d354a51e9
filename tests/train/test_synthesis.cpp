#include <gearkit/train/synthesis.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gearkit::train {
namespace {

// OTM 2015 problem 3 (seed 000_bc94d104a9983772.txt): z1 = 15, m1 = 6 mm, m2 = 5 mm, overall
// ratio 1/16 in two equal stages: z2 = 60, z3 = 18, z4 = 72 (a = 225 mm).
TEST(Synthesis, OtmReducerFromItsData) {
  CoaxialReducerSpec spec;
  spec.module_1_mm = 6;
  spec.module_2_mm = 5;
  spec.target_ratio = Rational(1, 16);
  spec.z1 = 15;
  const auto found = synthesise_coaxial_reducer(spec);
  ASSERT_FALSE(found.empty());
  EXPECT_EQ(found[0].z1, 15);
  EXPECT_EQ(found[0].z2, 60);
  EXPECT_EQ(found[0].z3, 18);
  EXPECT_EQ(found[0].z4, 72);
  EXPECT_EQ(found[0].relative_error, 0.0);
  EXPECT_DOUBLE_EQ(found[0].centre_distance_mm, 225.0);
  // With equal stages required it is the only answer.
  spec.equal_stages = true;
  const auto equal = synthesise_coaxial_reducer(spec);
  ASSERT_EQ(equal.size(), 1u);
  EXPECT_EQ(equal[0].z3, 18);
}

TEST(Synthesis, EveryReducerCandidateIsCoaxialAndWithinTolerance) {
  CoaxialReducerSpec spec;
  spec.module_1_mm = 2.5;
  spec.module_2_mm = 3;
  spec.target_ratio = Rational(1, 7);
  spec.tolerance = 1e-3;
  spec.z_min = 14;
  spec.z_max = 80;
  spec.max_results = 1000;
  const auto found = synthesise_coaxial_reducer(spec);
  ASSERT_FALSE(found.empty());
  double last = 0;
  for (const auto& c : found) {
    EXPECT_NEAR(2.5 * (c.z1 + c.z2), 3.0 * (c.z3 + c.z4), 1e-9);
    const double ratio = double(c.z1) * c.z3 / (double(c.z2) * c.z4);
    EXPECT_LE(std::fabs(ratio * 7 - 1), 1e-3 + 1e-12);
    EXPECT_GE(c.relative_error, last);
    last = c.relative_error;
    EXPECT_GE(std::min({c.z1, c.z2, c.z3, c.z4}), 14);
    EXPECT_LE(std::max({c.z1, c.z2, c.z3, c.z4}), 80);
  }
}

// Simple planetary, ring fixed, sun in, carrier out: ratio z_s/(z_s + z_r) = 1/4 exactly when
// z_r = 3 z_s, i.e. z_p = z_s; equal spacing (z_s + z_r)/3 = 4 z_s/3.
TEST(Synthesis, PlanetaryQuarterRatio) {
  PlanetarySpec spec;
  spec.target_ratio = Rational(1, 4);
  spec.tolerance = 0;
  spec.planets = 3;
  spec.z_min = 12;
  spec.z_max = 40;
  const auto found = synthesise_planetary(spec);
  ASSERT_FALSE(found.empty());
  for (const auto& c : found) {
    EXPECT_EQ(c.z_ring, c.z_sun + 2 * c.z_planet);
    EXPECT_EQ(c.z_planet, c.z_sun);
    EXPECT_EQ((c.z_sun + c.z_ring) % 3, 0);
    EXPECT_GT((c.z_sun + c.z_planet) * std::sin(std::numbers::pi / 3), c.z_planet + 2);
    EXPECT_EQ(c.ratio_numerator * 4, c.ratio_denominator);
  }
  EXPECT_EQ(found[0].z_sun, 12);  // smallest ring first: 12/12/36
}

TEST(Synthesis, PlanetaryRatioFormula) {
  // Willis, ring fixed: w_c/w_s = z_s/(z_s + z_r); carrier fixed: w_r/w_s = -z_s/z_r.
  EXPECT_EQ(planetary_ratio(24, 60, PlanetaryMember::ring, PlanetaryMember::sun, PlanetaryMember::carrier),
            Rational(2, 7));
  EXPECT_EQ(planetary_ratio(24, 60, PlanetaryMember::carrier, PlanetaryMember::sun, PlanetaryMember::ring),
            Rational(-2, 5));
  // Sun fixed, arm in, ring out (homeworksource 1031202: 23/55 -> 141.8 rpm at 100 rpm).
  EXPECT_NEAR(100 * to_double(planetary_ratio(23, 55, PlanetaryMember::sun, PlanetaryMember::carrier,
                                              PlanetaryMember::ring)), 141.8, 0.05);
}

TEST(Synthesis, RejectsBadSpecs) {
  CoaxialReducerSpec spec;
  spec.module_1_mm = 0;
  spec.module_2_mm = 5;
  spec.target_ratio = Rational(1, 16);
  EXPECT_THROW(synthesise_coaxial_reducer(spec), std::invalid_argument);
  spec.module_1_mm = 6;
  spec.z_min = 50;
  spec.z_max = 20;
  EXPECT_THROW(synthesise_coaxial_reducer(spec), std::invalid_argument);
  PlanetarySpec p;
  p.target_ratio = Rational(1, 4);
  p.input = PlanetaryMember::ring;
  EXPECT_THROW(synthesise_planetary(p), std::invalid_argument);
}

}  // namespace
}  // namespace gearkit::train
