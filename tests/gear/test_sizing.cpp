// Tests for gearkit/gear/sizing.hpp: every candidate carries the load with the required safety,
// is the narrowest whole-millimetre face that does, respects the ratio and the limits.
#include <gearkit/gear/sizing.hpp>

#include <gearkit/gear/inspection.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace gg = gearkit::gear;

namespace {

gg::SizingInput reducer() {
  gg::SizingInput s;
  s.load.T_1 = 500.0;
  s.load.n_1 = 1450.0;
  s.load.quality = 6;
  s.load.material = {gg::material_by_name("18CrNiMo7-6"), gg::material_by_name("18CrNiMo7-6")};
  s.ratio = 3.5;
  s.modules = {2.0, 2.5, 3.0, 4.0, 5.0};
  return s;
}

// The smallest margin min(S_H / S_Hmin, S_F / S_Fmin) of a candidate rated again at width b, its
// tooth root with the upper allowances ISO/TR 10064-2 gives the grade (as `gearkit gear --quality`).
double margin(const gg::SizingCandidate& c, const gg::SizingInput& s, double b) {
  gg::GearPairInput g;
  g.z1 = c.z1;
  g.z2 = c.z2;
  g.module = c.m_n;
  g.x1 = c.x1;
  g.x2 = c.x2;
  g.face_width = b;
  const auto table = gg::compute_gear_pair(g);
  gg::InspectionInput ii;
  ii.grade = {*s.load.quality, *s.load.quality};
  const auto inspection = gg::compute_inspection(g, table, ii);
  gg::RatingInput load = s.load;
  for (int i = 0; i < 2; ++i) load.A_sne[i] = inspection.gear[i].allowances.A_sne;
  const auto r = gg::rate_gear_pair(g, table, load);
  return std::min({r.gear[0].S_H / s.load.S_Hmin, r.gear[1].S_H / s.load.S_Hmin, r.gear[0].S_F / s.load.S_Fmin,
                   r.gear[1].S_F / s.load.S_Fmin});
}

}  // namespace

TEST(Sizing, CandidatesAreSafeAndNarrowest) {
  const gg::SizingInput s = reducer();
  const gg::SizingResult r = gg::size_gear_pair(s);
  ASSERT_FALSE(r.best.empty());
  EXPECT_LE(static_cast<int>(r.best.size()), s.count);
  for (std::size_t i = 0; i < r.best.size(); ++i) {
    const auto& c = r.best[i];
    EXPECT_GE(margin(c, s, c.b), 1.0);
    if (c.b - 1.0 >= s.width_module_min * c.m_n) {
      EXPECT_LT(margin(c, s, c.b - 1.0), 1.0);
    }
    EXPECT_LE(std::fabs(c.u / s.ratio - 1.0), s.ratio_tolerance + 1e-12);
    EXPECT_LE(c.b, s.width_ratio_max * c.d1 + 1e-9);
    EXPECT_GE(c.b, s.width_module_min * c.m_n - 1e-9);
    EXPECT_NEAR(c.volume, c.b * std::acos(-1.0) / 4.0 * (c.d1 * c.d1 + c.d2 * c.d2), 1e-6 * c.volume);
    if (i > 0) {
      EXPECT_GE(c.volume, r.best[i - 1].volume);
    }
  }
}

TEST(Sizing, MoreTorqueNeedsMoreGear) {
  gg::SizingInput s = reducer();
  const double v1 = gg::size_gear_pair(s).best.front().volume;
  s.load.T_1 *= 2.0;
  EXPECT_GT(gg::size_gear_pair(s).best.front().volume, v1);
}

TEST(Sizing, LimitsAndBadInput) {
  gg::SizingInput s = reducer();
  s.modules.assign(40, 3.0);
  s.z1_min = 5;
  s.z1_max = 500;
  try {
    gg::size_gear_pair(s);
    ADD_FAILURE() << "no error for too many combinations";
  } catch (const gg::RatingError& e) {
    EXPECT_EQ(e.field(), "modules");
  }
  s = reducer();
  s.ratio = 0.5;
  EXPECT_THROW(gg::size_gear_pair(s), gg::RatingError);
  s = reducer();
  s.load.T_1 = 1e9;  // nothing carries it: an empty list, not an error
  EXPECT_TRUE(gg::size_gear_pair(s).best.empty());
}

namespace {

double involute(double a) { return std::tan(a) - a; }

// ISO 21771: inv alpha_wt = inv alpha_t + 2 tan(alpha_n) (x1 + x2)/(z1 + z2), solved by Newton
// (d inv/d alpha = tan^2 alpha), then a = a_d cos(alpha_t) / cos(alpha_wt) with
// a_d = m_n (z1 + z2) / (2 cos beta). Independent of libgear's geometry.
double working_centre_distance(const gg::SizingCandidate& c, double alpha_n, double beta) {
  const double alpha_t = std::atan(std::tan(alpha_n) / std::cos(beta));
  const double target = involute(alpha_t) + 2.0 * std::tan(alpha_n) * (c.x1 + c.x2) / (c.z1 + c.z2);
  double a = alpha_t;
  for (int i = 0; i < 50; ++i) a -= (involute(a) - target) / (std::tan(a) * std::tan(a));
  const double a_d = c.m_n * (c.z1 + c.z2) / (2.0 * std::cos(beta));
  return a_d * std::cos(alpha_t) / std::cos(a);
}

}  // namespace

TEST(Sizing, EveryCandidateHasTheRequiredCentreDistance) {
  gg::SizingInput s = reducer();
  s.centre_distance = 160.0;
  s.helix_angle = 12.0 * std::acos(-1.0) / 180.0;
  s.count = 20;
  const gg::SizingResult r = gg::size_gear_pair(s);
  ASSERT_FALSE(r.best.empty());
  bool shifted = false;
  for (const auto& c : r.best) {
    EXPECT_NEAR(working_centre_distance(c, s.pressure_angle, s.helix_angle), 160.0, 1e-6) << c.m_n << " " << c.z1 << "/" << c.z2;
    EXPECT_NEAR(c.a, 160.0, 1e-6);
    EXPECT_GE(c.x1 + c.x2, s.x_sum_min - 1e-12);
    EXPECT_LE(c.x1 + c.x2, s.x_sum_max + 1e-12);
    shifted = shifted || std::fabs(c.x1 + c.x2) > 1e-3;
  }
  EXPECT_TRUE(shifted) << "160 mm is not a reference centre distance of every pair: some need a shift sum";
  s.centre_distance = -1.0;
  EXPECT_THROW(gg::size_gear_pair(s), gg::RatingError);
}

TEST(Sizing, HuntingTeethShareNoFactor) {
  gg::SizingInput s = reducer();
  s.ratio = 4.0;  // u z1 is a multiple of z1: without the flag every pair shares the factor z1
  s.ratio_tolerance = 0.03;
  s.count = 20;
  const gg::SizingResult plain = gg::size_gear_pair(s);
  ASSERT_FALSE(plain.best.empty());
  for (const auto& c : plain.best) EXPECT_EQ(c.z2, 4 * c.z1);
  s.hunting_tooth = true;
  const gg::SizingResult hunting = gg::size_gear_pair(s);
  ASSERT_FALSE(hunting.best.empty());
  for (const auto& c : hunting.best) {
    EXPECT_EQ(std::gcd(c.z1, c.z2), 1) << c.z1 << "/" << c.z2;
    EXPECT_LE(std::fabs(c.u / s.ratio - 1.0), s.ratio_tolerance + 1e-12);
  }
}
