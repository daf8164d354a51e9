// Tests for gearkit/gear/tooth_form.hpp.
#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/involute.hpp>
#include <gearkit/gear/tooth_form.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace gg = gearkit::gear;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kAlpha = 20.0 * kDeg;

gg::ToothFormSpec spur(int z, double m, double x) {
  gg::ToothFormSpec s;
  s.z = z;
  s.m_n = m;
  s.x = x;
  s.d_a = z * m + 2.0 * m * (1.0 + x);
  return s;
}

// Involute half space angle at radius r of an external spur gear (ISO 21771 thickness formula).
double involute_eta(int z, double m, double x, double r) {
  const double d = z * m, d_b = d * std::cos(kAlpha);
  const double e = std::numbers::pi * m - gg::reference_tooth_thickness(m, x, kAlpha);
  return e / d - gg::involute(kAlpha) + gg::involute(std::acos(d_b / (2.0 * r)));
}

// Replaces every bulged segment by 64 chords along its arc (DXF bulge: tan(theta/4), centre on
// the left of the chord for positive bulges), so the polygon follows the true arcs.
std::vector<gg::ProfileVertex> densified(const std::vector<gg::ProfileVertex>& poly) {
  std::vector<gg::ProfileVertex> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    out.push_back({a.x, a.y, 0.0});
    if (a.bulge == 0.0) continue;
    const double theta = 4.0 * std::atan(a.bulge);
    const double cx = b.x - a.x, cy = b.y - a.y, c = std::hypot(cx, cy);
    const double R = c / (2.0 * std::sin(theta / 2.0));
    const double h = R * std::cos(theta / 2.0);  // centre distance from the chord midpoint
    const double mx = 0.5 * (a.x + b.x) - h * cy / c, my = 0.5 * (a.y + b.y) + h * cx / c;
    const double a0 = std::atan2(a.y - my, a.x - mx);
    for (int k = 1; k < 64; ++k) {
      const double t = a0 + theta * k / 64.0;
      out.push_back({mx + std::fabs(R) * std::cos(t), my + std::fabs(R) * std::sin(t), 0.0});
    }
  }
  return out;
}

bool inside(const std::vector<gg::ProfileVertex>& poly, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const auto& a = poly[i];
    const auto& b = poly[j];
    if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

double distance_to(const std::vector<gg::ProfileVertex>& poly, double x, double y) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const double ax = poly[j].x, ay = poly[j].y, bx = poly[i].x, by = poly[i].y;
    const double l2 = (bx - ax) * (bx - ax) + (by - ay) * (by - ay);
    const double t = l2 > 0 ? std::clamp(((x - ax) * (bx - ax) + (y - ay) * (by - ay)) / l2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(x - (ax + t * (bx - ax)), y - (ay + t * (by - ay))));
  }
  return best;
}

}  // namespace

TEST(ToothForm, FlankRunsFromRootToTipOnTheInvolute) {
  for (auto [z, x] : {std::pair{12, 0.6}, {24, 0.36}, {40, -0.2}, {100, 0.0}}) {
    const double m = 3.0;
    const auto f = gg::space_flank(spur(z, m, x));
    const double r_f = 0.5 * z * m - m * (1.25 - x), r_a = 0.5 * z * m + m * (1.0 + x);
    EXPECT_NEAR(std::hypot(f.front().x, f.front().y), r_f, 1e-9) << z;
    EXPECT_NEAR(std::hypot(f.back().x, f.back().y), r_a, 1e-9) << z;
    // Above the form circle (rack-generated, ISO 21771 / DIN 3960 d_Ff) every point is on the involute.
    const double rho_Ff = gg::form_roll_length(z, m, 0.0, x, gg::Rack{});
    const double r_Ff = std::hypot(0.5 * z * m * std::cos(kAlpha), rho_Ff);
    int checked = 0;
    for (const auto& p : f) {
      const double r = std::hypot(p.x, p.y);
      EXPECT_GE(r, r_f - 1e-9);
      EXPECT_LE(r, r_a + 1e-9);
      if (r > r_Ff + 1e-6) {
        EXPECT_NEAR(std::atan2(p.x, p.y), involute_eta(z, m, x, r), 1e-9) << z << " r = " << r;
        ++checked;
      }
    }
    EXPECT_GT(checked, 10);
  }
}

TEST(ToothForm, FilletEndsOnTheInvoluteAtTheFormCircle) {
  // The trochoidal fillet (envelope of the tool tip rounding) must meet the involute at the form
  // diameter given by the independent rack formula rho_Ff = r_b tan a - (h_fP - rho_fP(1 - sin a) - x) m / sin a.
  const int z = 24;
  const double m = 3.0, x = 0.36;
  auto spec = spur(z, m, x);
  spec.fillet_points = 400;
  const auto f = gg::space_flank(spec);
  const double rho_Ff = gg::form_roll_length(z, m, 0.0, x, gg::Rack{});
  const double r_Ff = std::hypot(0.5 * z * m * std::cos(kAlpha), rho_Ff);
  double best = std::numeric_limits<double>::infinity();
  for (const auto& p : f) best = std::min(best, std::fabs(std::hypot(p.x, p.y) - r_Ff));
  EXPECT_LT(best, 1e-6);
  // The fillet's steps stay small (no jump between fillet and involute).
  for (std::size_t i = 1; i < f.size(); ++i) EXPECT_LT(std::hypot(f[i].x - f[i - 1].x, f[i].y - f[i - 1].y), 0.35);
}

TEST(ToothForm, UndercutIsTrimmedAtTheTrochoidCrossing) {
  // z = 8, x = 0: undercut. The profile still starts on the root circle and ends on the tip, and
  // never crosses the space centre line.
  const auto f = gg::space_flank(spur(8, 2.0, 0.0));
  EXPECT_NEAR(std::hypot(f.front().x, f.front().y), 8.0 - 2.5, 1e-9);
  EXPECT_NEAR(std::hypot(f.back().x, f.back().y), 10.0, 1e-9);
  for (const auto& p : f) EXPECT_GE(p.x, -1e-12);
}

TEST(ToothForm, OutlineHasEveryToothAndExactArcs) {
  const auto spec = spur(20, 2.0, 0.0);
  const auto o = gg::gear_outline(spec);
  const auto f = gg::space_flank(spec);
  EXPECT_EQ(o.size(), 20 * 2 * f.size());
  int arcs = 0;
  for (const auto& v : o) {
    const double r = std::hypot(v.x, v.y);
    EXPECT_GE(r, 17.5 - 1e-9);
    EXPECT_LE(r, 22.0 + 1e-9);
    arcs += v.bulge != 0.0;
    EXPECT_GE(v.bulge, 0.0);  // counter-clockwise arcs only
  }
  EXPECT_EQ(arcs, 40);  // one root arc and one tip arc per tooth
}

TEST(ToothForm, PairMeshesWithoutPenetrationAndTouches) {
  // Both gears placed at the working centre distance: no vertex of one gear lies inside the other
  // (beyond rounding), and with zero backlash the flanks touch. Both pairs are free of interference
  // warnings (with x1 = 0.3 the ring pair warns, and the overlap then really appears).
  for (int variant = 0; variant < 3; ++variant) {
    const bool internal = variant == 1;
    gg::GearPairInput in;
    in.helix_angle = variant == 2 ? 20.0 * kDeg : 0.0;  // helical: transverse section
    in.z1 = 13;
    in.z2 = internal ? 47 : 29;
    in.internal = internal;
    in.module = 2.0;
    in.x1 = internal ? 0.6 : 0.3;
    in.x2 = internal ? 0.0 : 0.1;
    const auto r = gg::compute_gear_pair(in);
    EXPECT_TRUE(r.warnings.empty());
    auto outlines = gg::pair_outlines(in, r);
    outlines[1] = densified(outlines[1]);
    double closest = std::numeric_limits<double>::infinity();
    for (const auto& v : outlines[0]) {
      const double dist = distance_to(outlines[1], v.x, v.y);
      closest = std::min(closest, dist);
      // For a ring the polygon is the hole; the pinion must stay inside it (outside the ring's material).
      const bool in_material = internal ? !inside(outlines[1], v.x, v.y) : inside(outlines[1], v.x, v.y);
      // Tolerance: chord error of the flank polylines (48 chords per involute flank).
      if (in_material) {
        EXPECT_LT(dist, 2e-4) << "penetration at " << v.x << ", " << v.y;
      }
    }
    EXPECT_LT(closest, 0.02) << "flanks should touch";
    // With a backlash allowance the flanks separate.
    in.backlash_target = 0.2;
    const auto rb = gg::compute_gear_pair(in);
    auto ob = gg::pair_outlines(in, rb);
    ob[1] = densified(ob[1]);
    double closest_b = std::numeric_limits<double>::infinity();
    for (const auto& v : ob[0]) closest_b = std::min(closest_b, distance_to(ob[1], v.x, v.y));
    EXPECT_GT(closest_b, 0.02);
  }
}

TEST(ToothForm, BulgesFollowTheRootAndTipCircles) {
  // The densified arcs of the outline stay on the root and tip circles (checks the bulge sign
  // and size against the DXF definition).
  const auto spec = spur(20, 2.0, 0.0);
  const auto o = gg::gear_outline(spec);
  const auto dense = densified(o);
  for (const auto& v : dense) {
    const double r = std::hypot(v.x, v.y);
    EXPECT_GE(r, 17.5 - 1e-9);
    EXPECT_LE(r, 22.0 + 1e-9);
  }
  EXPECT_GT(dense.size(), o.size());
}

TEST(ToothForm, Placement) {
  const auto p = gg::placed({{1.0, 0.0, 0.5}}, std::numbers::pi / 2.0, 10.0, 0.0);
  EXPECT_NEAR(p[0].x, 10.0, 1e-15);
  EXPECT_NEAR(p[0].y, 1.0, 1e-15);
  EXPECT_EQ(p[0].bulge, 0.5);
}
