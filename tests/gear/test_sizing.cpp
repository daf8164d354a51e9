// Tests for gearkit/gear/sizing.hpp: every candidate carries the load with the required safety,
// is the narrowest whole-millimetre face that does, respects the ratio and the limits.
#include <gearkit/gear/sizing.hpp>

#include <gearkit/gear/inspection.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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
