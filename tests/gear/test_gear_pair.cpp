// Tests for gearkit/gear/gear_pair.hpp: complete tables against published worked examples.
#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/involute.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace gg = gearkit::gear;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

bool has_warning(const gg::GearPairResult& r, const std::string& text) {
  return std::any_of(r.warnings.begin(), r.warnings.end(),
                     [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

gg::GearPairInput pair(int z1, int z2, double m, double x1, double x2) {
  gg::GearPairInput in;
  in.z1 = z1;
  in.z2 = z2;
  in.module = m;
  in.x1 = x1;
  in.x2 = x2;
  return in;
}

}  // namespace

// ---- OTM 2015 problem 3 (seed 000_bc94d104a9983772.txt) ----

TEST(Otm2015Problem3, ToothNumbersOfBothStages) {
  // a) mu = 1/16 in two equal stages (mu1 = mu2 = 1/4); stage 1: z1 = 15, m1 = 6 -> z2 = 60;
  // a = m1 (z1 + z2)/2 = 225 mm; stage 2, m2 = 5: z3 + z4 = 90, z4 = 4 z3 -> z3 = 18, z4 = 72.
  const int z1 = 15, z2 = 4 * z1;
  EXPECT_EQ(z2, 60);
  const double a = gg::reference_centre_distance(z1, z2, 6.0);
  EXPECT_DOUBLE_EQ(a, 225.0);
  const double sum34 = gg::teeth_sum_for_centre_distance(a, 5.0, 0.0);
  EXPECT_DOUBLE_EQ(sum34, 90.0);
  const int z3 = static_cast<int>(sum34 / 5.0), z4 = 4 * z3;
  EXPECT_EQ(z3, 18);
  EXPECT_EQ(z4, 72);
  // b) the modified first stage: m = 9, z1' = 10, z2' = 40 fits the same a without shift sum.
  EXPECT_DOUBLE_EQ(gg::teeth_sum_for_centre_distance(a, 9.0, 0.0), 50.0);
}

TEST(Otm2015Problem3, TableOfTheModifiedFirstStage) {
  // c) solution table: V-0 pair, x = +-(14 - Z)/17 = +-0.2353 (x of the pinion from the seed's
  // practical undercut limit), given the same centre distance 225 mm.
  gg::GearPairInput in = pair(10, 40, 9.0, 4.0 / 17.0, 0.0);
  in.centre_distance = 225.0;
  in.split = gg::ShiftSplit::user_x1;
  const gg::GearPairResult r = gg::compute_gear_pair(in);
  const auto& p = r.gear[0];
  const auto& w = r.gear[1];
  EXPECT_EQ(r.pair.mounting, gg::Mounting::v_zero);
  EXPECT_NEAR(p.x, 0.2353, 5e-5);
  EXPECT_NEAR(w.x, -0.2353, 5e-5);
  EXPECT_NEAR(p.shift_mm, 2.1176, 1e-4);  // 36/17 mm
  EXPECT_NEAR(w.shift_mm, -2.1176, 1e-4);
  // Radii in the seed's table, 2 decimals (the seed truncates e = 12.5956 to 12.59).
  const double tol = 0.01;
  EXPECT_NEAR(p.d / 2, 45.0, 1e-12);
  EXPECT_NEAR(w.d / 2, 180.0, 1e-12);
  EXPECT_NEAR(p.d_w / 2, 45.0, 1e-9);
  EXPECT_NEAR(w.d_w / 2, 180.0, 1e-9);
  EXPECT_NEAR(p.d_b / 2, 42.29, tol);
  EXPECT_NEAR(w.d_b / 2, 169.14, tol);
  EXPECT_NEAR(p.d_a / 2, 56.12, tol);
  EXPECT_NEAR(w.d_a / 2, 186.88, tol);
  EXPECT_NEAR(p.d_f / 2, 35.87, tol);
  EXPECT_NEAR(w.d_f / 2, 166.63, tol);
  EXPECT_NEAR(p.p_t, 28.27, tol);
  EXPECT_NEAR(w.p_t, 28.27, tol);
  EXPECT_NEAR(p.e_t, 12.59, tol);
  EXPECT_NEAR(w.e_t, 15.68, tol);
  EXPECT_NEAR(p.s_t, 15.68, tol);
  EXPECT_NEAR(w.s_t, 12.59, tol);
  EXPECT_NEAR(r.pair.alpha_wt / kDeg, 20.0, 1e-9);
  EXPECT_NEAR(r.pair.a, 225.0, 1e-9);
  EXPECT_NEAR(r.pair.c1, 2.25, 1e-9);  // holgura radial = 0.25 m
  EXPECT_NEAR(r.pair.c2, 2.25, 1e-9);
  EXPECT_NEAR(r.pair.sum_x, 0.0, 1e-12);
}

TEST(Otm2015Problem3, MinimumShiftSplitByTheCourseCriterion) {
  // b) V-0 at the same centre distance, the pinion shifted just enough by the course's limit
  // (14 - z)/17: x = +-4/17, shifts +-36/17 mm; ISO's limit asks x1 = 1 - z sin^2(20)/2 (for ISO 53 A:
  // h_fP - rho_fP (1 - sin 20) - 5 sin^2 20 = 0.4151).
  gg::GearPairInput in = pair(10, 40, 9.0, 0.0, 0.0);
  in.centre_distance = 225.0;
  in.split = gg::ShiftSplit::min_shift;
  in.undercut_limit = gg::UndercutLimit::practical;
  gg::GearPairResult r = gg::compute_gear_pair(in);
  EXPECT_EQ(r.pair.mounting, gg::Mounting::v_zero);
  EXPECT_EQ(r.pair.split, gg::ShiftSplit::min_shift);
  EXPECT_NEAR(r.gear[0].x, 4.0 / 17.0, 1e-12);
  EXPECT_NEAR(r.gear[1].x, -4.0 / 17.0, 1e-12);
  EXPECT_NEAR(r.gear[0].shift_mm, 36.0 / 17.0, 1e-12);
  EXPECT_NEAR(r.gear[0].x_min_practical, 4.0 / 17.0, 1e-15);
  // ISO says undercut there, and the warning says which criterion says what.
  EXPECT_TRUE(has_warning(r, "undercut by ISO"));
  EXPECT_TRUE(has_warning(r, "practical limit"));
  in.undercut_limit = gg::UndercutLimit::iso;
  r = gg::compute_gear_pair(in);
  const double iso = 1.25 - 0.38 * (1 - std::sin(20 * kDeg)) - 5.0 * std::pow(std::sin(20 * kDeg), 2);
  EXPECT_NEAR(r.gear[0].x, iso, 1e-12);
  EXPECT_FALSE(has_warning(r, "undercut"));
  // Room for both: the least max |x| is the even split of the sum.
  gg::GearPairInput v = pair(20, 40, 3.0, 0.0, 0.0);
  v.centre_distance = gg::centre_distance(90.0, 20 * kDeg, gg::working_pressure_angle(20 * kDeg, 20 * kDeg, 20, 40, 0.3));
  v.split = gg::ShiftSplit::min_shift;
  r = gg::compute_gear_pair(v);
  EXPECT_NEAR(r.gear[0].x, 0.15, 1e-9);
  EXPECT_NEAR(r.gear[1].x, 0.15, 1e-9);
  // No room: 8 and 9 teeth at their reference distance; gear 1 gets its limit, with a warning.
  gg::GearPairInput tight = pair(8, 9, 2.0, 0.0, 0.0);
  tight.centre_distance = 17.0;
  tight.split = gg::ShiftSplit::min_shift;
  r = gg::compute_gear_pair(tight);
  EXPECT_TRUE(has_warning(r, "no split"));
  EXPECT_NEAR(r.gear[0].x, gg::min_shift_no_undercut(8, 0.0, gg::Rack{}), 1e-12);
}

// ---- External V pair: KHK example as reproduced by bolsover.com ----
// bolsover.com/utilitiesforalibre/profile-shifted-external-spur-gears.html: m = 3, alpha = 20,
// z = 12/24, x = 0.6/0.36, working centre distance 56.500 -> inv alpha_w = 0.034317,
// alpha_w = 26.0888 deg, y = 0.83333, d_b = 33.8289/67.6579, d_w = 37.667/75.333,
// h_a = 4.420/3.700, d_a = 44.840/79.400, d_f = 32.100/66.660, contact ratio 1.202.

TEST(KhkExternalVPair, GivenShifts) {
  const gg::GearPairResult r = gg::compute_gear_pair(pair(12, 24, 3.0, 0.6, 0.36));
  EXPECT_EQ(r.pair.mounting, gg::Mounting::v);
  EXPECT_NEAR(gg::involute(r.pair.alpha_wt), 0.034317, 1e-6);
  EXPECT_NEAR(r.pair.alpha_wt / kDeg, 26.0888, 5e-4);  // 4-digit print of a rounded inv
  EXPECT_NEAR(r.pair.a, 56.500, 5e-4);
  EXPECT_NEAR(r.gear[0].d_b, 33.8289, 5e-5);
  EXPECT_NEAR(r.gear[1].d_b, 67.6579, 5e-5);
  EXPECT_NEAR(r.gear[0].d_w, 37.667, 5e-4);
  EXPECT_NEAR(r.gear[1].d_w, 75.333, 5e-4);
  EXPECT_NEAR((r.gear[0].d_a - r.gear[0].d) / 2, 4.420, 5e-4);
  EXPECT_NEAR((r.gear[1].d_a - r.gear[1].d) / 2, 3.700, 5e-4);
  EXPECT_NEAR(r.gear[0].d_a, 44.840, 5e-4);
  EXPECT_NEAR(r.gear[1].d_a, 79.400, 5e-4);
  EXPECT_NEAR(r.gear[0].d_f, 32.100, 5e-4);
  EXPECT_NEAR(r.gear[1].d_f, 66.660, 5e-4);
  EXPECT_NEAR(r.pair.eps_alpha, 1.202, 5e-4);
  EXPECT_TRUE(r.pair.tip_shortened);
  // Tip shortening keeps the bottom clearance at c_P m = 0.75 mm on both sides.
  EXPECT_NEAR(r.pair.c1, 0.75, 1e-12);
  EXPECT_NEAR(r.pair.c2, 0.75, 1e-12);
  EXPECT_NEAR(r.pair.k, r.pair.sum_x - r.pair.y, 1e-15);
}

TEST(KhkExternalVPair, GivenCentreDistance) {
  gg::GearPairInput in = pair(12, 24, 3.0, 0.6, 0.0);
  in.centre_distance = 56.5;
  in.split = gg::ShiftSplit::user_x1;
  const gg::GearPairResult r = gg::compute_gear_pair(in);
  EXPECT_NEAR(r.pair.sum_x, 0.960, 5e-4);
  EXPECT_NEAR(r.pair.y, 0.83333, 5e-6);
  EXPECT_NEAR(r.pair.alpha_wt / kDeg, 26.0888, 5e-4);
  EXPECT_NEAR(r.gear[1].x, r.pair.sum_x - 0.6, 1e-15);
  EXPECT_NEAR(r.pair.a, 56.5, 1e-12);
  EXPECT_NEAR(r.pair.j_wt, 0.0, 1e-11);  // the split shifts mesh without backlash at 56.5 mm
}

TEST(GearPair, BalancedAndProportionalSplits) {
  gg::GearPairInput in = pair(12, 24, 3.0, 0.0, 0.0);
  in.centre_distance = 56.5;
  in.split = gg::ShiftSplit::balanced_sliding;
  const auto b = gg::compute_gear_pair(in);
  EXPECT_EQ(b.pair.split, gg::ShiftSplit::balanced_sliding);
  EXPECT_NEAR(b.pair.zeta1, b.pair.zeta2, 1e-9);
  EXPECT_NEAR(b.gear[0].x + b.gear[1].x, b.pair.sum_x, 1e-12);
  EXPECT_GT(b.gear[0].x, b.gear[1].x);  // the pinion takes more shift (textbook practice)
  in.split = gg::ShiftSplit::proportional;
  const auto q = gg::compute_gear_pair(in);
  EXPECT_NEAR(q.gear[0].x / q.gear[1].x, 12.0 / 24.0, 1e-12);
}

TEST(GearPair, ContactRatioTwoWays) {
  // ISO 21771 form with tip pressure angles and the textbook form path of contact / base pitch
  // (g_alpha = sqrt(r_a1^2 - r_b1^2) + sqrt(r_a2^2 - r_b2^2) - a sin alpha_w) must agree.
  const auto r = gg::compute_gear_pair(pair(12, 24, 3.0, 0.6, 0.36));
  const auto& g1 = r.gear[0];
  const auto& g2 = r.gear[1];
  const double iso = gg::transverse_contact_ratio(12, 24, std::acos(g1.d_b / g1.d_a), std::acos(g2.d_b / g2.d_a), r.pair.alpha_wt);
  EXPECT_NEAR(r.pair.eps_alpha, iso, 1e-12);
  const double ga = 0.5 * std::sqrt(g1.d_a * g1.d_a - g1.d_b * g1.d_b) + 0.5 * std::sqrt(g2.d_a * g2.d_a - g2.d_b * g2.d_b) -
                    r.pair.a * std::sin(r.pair.alpha_wt);
  EXPECT_NEAR(r.pair.eps_alpha, ga / (std::numbers::pi * 3.0 * std::cos(20.0 * kDeg)), 1e-12);
  // Internal pair (signed ISO form, z2 < 0).
  gg::GearPairInput in = pair(17, 96, 14.0, 0.2, -0.5);
  in.internal = true;
  const auto ri = gg::compute_gear_pair(in);
  const double iso_i = gg::transverse_contact_ratio(17, -96, std::acos(ri.gear[0].d_b / ri.gear[0].d_a),
                                                    std::acos(ri.gear[1].d_b / ri.gear[1].d_a), ri.pair.alpha_wt);
  EXPECT_NEAR(ri.pair.eps_alpha, iso_i, 1e-12);
}

TEST(GearPair, SpecificSlidingByHand) {
  // Zero pair z = 20/40, m = 1: rho_tip2 = sqrt(r_a2^2 - r_b2^2), g = a sin(alpha);
  // zeta1 = 1 - rho_tip2 / (g - rho_tip2) * z1/z2 (Niemann/Winter, specific sliding at the root).
  const auto r = gg::compute_gear_pair(pair(20, 40, 1.0, 0.0, 0.0));
  const double rb2 = 20.0 * std::cos(20.0 * kDeg), ra2 = 21.0;
  const double rho2 = std::sqrt(ra2 * ra2 - rb2 * rb2);
  const double g = 30.0 * std::sin(20.0 * kDeg);
  EXPECT_NEAR(r.pair.zeta1, 1.0 - rho2 / (g - rho2) * 0.5, 1e-12);
  EXPECT_EQ(r.pair.mounting, gg::Mounting::zero);
  EXPECT_FALSE(r.pair.tip_shortened);
}

// ---- Internal pair ----
// scribd "Cent'r Dist'Nce of Profile Shifted Gear Calc" (KHK method), internal gear: z1 = 17,
// z2 = 96, m = 14, x1 = 0.20, x2 = 0.50 (KHK sign; ISO 21771 x2 = -0.50), alpha = 20 deg:
// inv a_w = 0.01766871, a_w = 21.1251 deg, y = 0.29205297 (KHK, = -y ISO), a = 557.0887 mm.

TEST(InternalPair, GivenShifts) {
  gg::GearPairInput in = pair(17, 96, 14.0, 0.2, -0.5);
  in.internal = true;
  const auto r = gg::compute_gear_pair(in);
  EXPECT_NEAR(gg::involute(r.pair.alpha_wt), 0.01766871, 5e-9);
  EXPECT_NEAR(r.pair.alpha_wt / kDeg, 21.1251, 5e-5);
  EXPECT_NEAR(r.pair.a, 557.0887, 5e-5);
  EXPECT_NEAR(r.pair.y, -0.29205297, 5e-8);
  // KHK internal formulas: d_a2 = d2 - 2 (1 - x2_KHK) m = 1330, d_f2 = d2 + 2 (1.25 + x2_KHK) m = 1393.
  EXPECT_NEAR(r.gear[1].d_a, 1330.0, 1e-9);
  EXPECT_NEAR(r.gear[1].d_f, 1393.0, 1e-9);
  EXPECT_TRUE(r.gear[1].internal);
  // Clearances by hand, on the line of centres at the mesh: ring root radius - (a + r_a1), and
  // ring tip radius - (a + r_f1).
  EXPECT_NEAR(r.pair.c1, 1393.0 / 2 - r.pair.a - r.gear[0].d_a / 2, 1e-9);
  EXPECT_NEAR(r.pair.c2, 1330.0 / 2 - r.pair.a - r.gear[0].d_f / 2, 1e-9);
  EXPECT_GT(r.pair.eps_alpha, 1.2);
  EXPECT_NEAR(r.pair.j_wt, 0.0, 1e-10);
  EXPECT_TRUE(std::isnan(r.gear[1].W_k));  // no span measurement on a ring
}

TEST(InternalPair, GivenCentreDistance) {
  gg::GearPairInput in = pair(17, 96, 14.0, 0.2, 0.0);
  in.internal = true;
  in.centre_distance = 557.0887;
  in.split = gg::ShiftSplit::user_x1;
  const auto r = gg::compute_gear_pair(in);
  EXPECT_NEAR(r.gear[1].x, -0.5, 2e-5);
  EXPECT_NEAR(r.pair.alpha_wt / kDeg, 21.1251, 5e-5);
}

TEST(InternalPair, RingMustBeLargerThanPinion) {
  gg::GearPairInput in = pair(30, 30, 2.0, 0.0, 0.0);
  in.internal = true;
  try {
    gg::compute_gear_pair(in);
    FAIL() << "expected GeometryError";
  } catch (const gg::GeometryError& e) {
    EXPECT_EQ(e.field(), "z2");
  }
}

// ---- Helical pair ----
// ISO 21771 example spreadsheet (scribd "Gear Generating Profile Shift Calculations",
// "According to ISO 21771:2007", eq. 62): m_n = 3.5, alpha_n = 20, beta = 21 deg, z = 31/30,
// working centre distance 116.5 -> a_d = 114.3447280708, alpha_wt = 23.8707609654 deg,
// inv alpha_wt = 0.0259052382, inv alpha_t = 0.0181260949, x1 + x2 = 0.651877131252.

TEST(HelicalPair, GivenCentreDistanceIso21771) {
  gg::GearPairInput in = pair(31, 30, 3.5, 0.291, 0.0);
  in.helix_angle = 21.0 * kDeg;
  in.centre_distance = 116.5;
  in.split = gg::ShiftSplit::user_x1;
  in.face_width = 40.0;
  const auto r = gg::compute_gear_pair(in);
  EXPECT_NEAR(r.pair.a_d, 114.3447280708, 1e-9);
  EXPECT_NEAR(r.pair.alpha_wt / kDeg, 23.8707609654, 1e-9);
  EXPECT_NEAR(gg::involute(r.pair.alpha_wt), 0.0259052382, 1e-10);
  EXPECT_NEAR(gg::involute(r.gear[0].alpha_t), 0.0181260949, 1e-10);
  EXPECT_NEAR(r.pair.sum_x, 0.651877131252, 1e-11);
  EXPECT_NEAR(r.gear[1].x, 0.651877131252 - 0.291, 1e-11);
  // Overlap ratio eps_beta = b sin(beta) / (pi m_n) (ISO 21771 eq. for eps_beta).
  EXPECT_NEAR(r.pair.eps_beta, 40.0 * std::sin(21.0 * kDeg) / (std::numbers::pi * 3.5), 1e-12);
  EXPECT_NEAR(r.pair.eps_gamma, r.pair.eps_alpha + r.pair.eps_beta, 1e-15);
}

TEST(HelicalPair, GivenShiftsRoundTripsTheCentreDistance) {
  gg::GearPairInput in = pair(31, 30, 3.5, 0.291, 0.651877131252 - 0.291);
  in.helix_angle = 21.0 * kDeg;
  const auto r = gg::compute_gear_pair(in);
  EXPECT_NEAR(r.pair.a, 116.5, 1e-9);
}

TEST(HelicalPair, TransverseInputIsTheSamePair) {
  gg::GearPairInput n = pair(31, 30, 3.5, 0.3, 0.2);
  n.helix_angle = 21.0 * kDeg;
  gg::GearPairInput t = n;
  t.system = gg::ModuleSystem::transverse;
  t.module = 3.5 / std::cos(21.0 * kDeg);
  t.pressure_angle = 21.2990642859 * kDeg;
  const auto rn = gg::compute_gear_pair(n), rt = gg::compute_gear_pair(t);
  EXPECT_NEAR(rn.pair.a, rt.pair.a, 1e-8);
  EXPECT_NEAR(rn.gear[0].d_a, rt.gear[0].d_a, 1e-8);
  EXPECT_NEAR(rt.gear[0].alpha_n / kDeg, 20.0, 1e-9);
}

// ---- Checks reported as warnings ----

TEST(GearPairWarnings, UndercutPointedContactClearance) {
  EXPECT_TRUE(has_warning(gg::compute_gear_pair(pair(8, 30, 2.0, 0.0, 0.0)), "undercut"));
  EXPECT_TRUE(has_warning(gg::compute_gear_pair(pair(8, 30, 2.0, 0.0, 0.0)), "involute interference"));
  EXPECT_FALSE(has_warning(gg::compute_gear_pair(pair(30, 60, 2.0, 0.0, 0.0)), "undercut"));
  // z = 10 with x = 1.0: tip thickness below 0.2 m or pointed.
  const auto thin = gg::compute_gear_pair(pair(10, 30, 2.0, 1.0, 0.0));
  EXPECT_TRUE(has_warning(thin, "pointed") || has_warning(thin, "thin tip"));
  EXPECT_TRUE(has_warning(thin, "contact ratio"));
  // Without tip shortening a large shift sum eats the clearance.
  gg::GearPairInput in = pair(12, 24, 3.0, 1.2, 1.2);
  in.apply_tip_shortening = false;
  EXPECT_TRUE(has_warning(gg::compute_gear_pair(in), "negative tip clearance"));
  in.apply_tip_shortening = true;
  EXPECT_FALSE(has_warning(gg::compute_gear_pair(in), "negative tip clearance"));
}

TEST(GearPairWarnings, PinsMustStandOut) {
  gg::GearPairInput in = pair(20, 40, 2.0, 0.0, 0.0);
  in.pin_diameter1 = 2.6;  // 1.3 m, well below the 1.68 m rule: M_d = 41.4 < d_a = 44 (hand: inv a_M = 0.0056)
  EXPECT_TRUE(has_warning(gg::compute_gear_pair(in), "do not stand out"));
  in.pin_diameter1 = 3.5;
  EXPECT_FALSE(has_warning(gg::compute_gear_pair(in), "do not stand out"));
}

TEST(GearPairWarnings, SpanNeedsFaceWidth) {
  // Helical span measurement: the anvils need b > W_k sin(beta_b) (ISO 21771 / DIN 3960).
  gg::GearPairInput in = pair(31, 30, 3.5, 0.3, 0.3);
  in.helix_angle = 21.0 * kDeg;
  in.face_width = 10.0;  // W_5 sin(beta_b) = 16.5 mm here
  EXPECT_TRUE(has_warning(gg::compute_gear_pair(in), "too narrow"));
  in.face_width = 40.0;
  EXPECT_FALSE(has_warning(gg::compute_gear_pair(in), "too narrow"));
}

TEST(GearPairWarnings, RingTipInsideItsBaseCircle) {
  // Textbook: a standard 20 deg ring needs its tip circle outside the base circle,
  // z2 (1 - cos alpha) >= 2 h_a*, i.e. z2 >= 33.2 -> at least 34 teeth.
  gg::GearPairInput in = pair(20, 33, 2.0, 0.0, 0.0);
  in.internal = true;
  EXPECT_TRUE(has_warning(gg::compute_gear_pair(in), "ring tip circle lies inside its base circle"));
  in.z2 = 34;
  EXPECT_FALSE(has_warning(gg::compute_gear_pair(in), "ring tip circle lies inside its base circle"));
  // KHK involute interference of internal pairs, z1/z2 >= 1 - tan(alpha_a2)/tan(alpha_w):
  // 20/40 standard gives 0.5 < 0.593 -> interference.
  in.z2 = 40;
  EXPECT_TRUE(has_warning(gg::compute_gear_pair(in), "involute interference"));
}

TEST(GearPairWarnings, InternalTipInterference) {
  // A ring with few more teeth than its pinion fouls at the tips (KHK: internal gears with a small
  // tooth difference need large shifts).
  gg::GearPairInput in = pair(30, 34, 2.0, 0.0, 0.0);
  in.internal = true;
  EXPECT_TRUE(has_warning(gg::compute_gear_pair(in), "tip interference"));
}

TEST(GearPairErrors, FieldsAreNamed) {
  auto field_of = [](const gg::GearPairInput& in) -> std::string {
    try {
      gg::compute_gear_pair(in);
    } catch (const gg::GeometryError& e) {
      return e.field();
    }
    return "";
  };
  EXPECT_EQ(field_of(pair(0, 24, 3.0, 0, 0)), "z1");
  EXPECT_EQ(field_of(pair(12, 24, 0.0, 0, 0)), "module");
  gg::GearPairInput in = pair(12, 24, 3.0, 0, 0);
  in.pressure_angle = 50.0 * kDeg;
  EXPECT_EQ(field_of(in), "pressure_angle");
  in = pair(12, 24, 3.0, 0, 0);
  in.centre_distance = 40.0;  // below the sum of base radii 50.74 mm
  EXPECT_EQ(field_of(in), "centre_distance");
  // Too far apart: the shift sum needed (2.63) exceeds what the teeth allow before they become
  // pointed (hand check: at x1 + x2 = 2.63 no split leaves both tips with positive thickness).
  in.centre_distance = 60.0;
  EXPECT_EQ(field_of(in), "centre_distance");
  in.centre_distance = 1e6;
  EXPECT_EQ(field_of(in), "centre_distance");
  // An absurd shift sum given directly is reported against the shifts, never as a crash.
  in = pair(12, 24, 3.0, -1.0, -1.0);
  EXPECT_EQ(field_of(in), "x2");
}

TEST(GearPairTips, ExplicitTipAndRootDiameters) {
  // A spur pair z = 20/40, m = 3, x = 0: d_a = 66 / 126, d_f = 52.5 / 112.5 by the rack.
  gg::GearPairInput in;
  in.z1 = 20;
  in.z2 = 40;
  in.module = 3.0;
  const auto nominal = gg::compute_gear_pair(in);
  EXPECT_NEAR(nominal.gear[0].d_a, 66.0, 1e-9);
  in.d_a = {65.0, std::nullopt};  // tip turned down by 0.5 mm on the radius
  in.d_f = {std::nullopt, 112.0};  // not what the rack cuts: a warning
  const auto r = gg::compute_gear_pair(in);
  EXPECT_DOUBLE_EQ(r.gear[0].d_a, 65.0);
  EXPECT_DOUBLE_EQ(r.gear[1].d_f, 112.0);
  // eps_alpha = (sqrt(r_a1^2 - r_b1^2) + sqrt(r_a2^2 - r_b2^2) - a sin alpha) / (pi m cos alpha), a = 90.
  const double c = std::cos(20.0 * kDeg), s = std::sin(20.0 * kDeg);
  const double rb1 = 30.0 * c, rb2 = 60.0 * c;
  const double eps = (std::sqrt(32.5 * 32.5 - rb1 * rb1) + std::sqrt(63.0 * 63.0 - rb2 * rb2) - 90.0 * s) / (std::numbers::pi * 3.0 * c);
  EXPECT_NEAR(r.pair.eps_alpha, eps, 1e-9);
  EXPECT_NEAR(r.pair.c1, 90.0 - 32.5 - 56.0, 1e-9);  // c = a - r_a1 - r_f2
  const bool warned = std::any_of(r.warnings.begin(), r.warnings.end(), [](const std::string& w) {
    return w.find("gear 2: root diameter d_f = 112.0000 mm given, the tool") != std::string::npos;
  });
  EXPECT_TRUE(warned);
  in.d_a = {-1.0, std::nullopt};
  try {
    gg::compute_gear_pair(in);
    FAIL() << "negative d_a accepted";
  } catch (const gg::GeometryError& e) {
    EXPECT_EQ(e.field(), "d_a1");
  }
}

TEST(GearPairTips, HelixHandOfEachGear) {
  // helix_angle is gear 1's, > 0 right hand; the mate of an external pair has the other hand,
  // a ring the same (ISO 21771 4.3: a parallel-axis external pair meshes with opposite hands).
  gg::GearPairInput in;
  in.z1 = 20;
  in.z2 = 40;
  in.module = 3.0;
  EXPECT_EQ(gg::helix_hand(in, 0), gg::HelixHand::spur);
  in.helix_angle = 15.0 * kDeg;
  EXPECT_STREQ(gg::to_string(gg::helix_hand(in, 0)), "right");
  EXPECT_STREQ(gg::to_string(gg::helix_hand(in, 1)), "left");
  in.helix_angle = -15.0 * kDeg;
  EXPECT_EQ(gg::helix_hand(in, 0), gg::HelixHand::left);
  EXPECT_EQ(gg::helix_hand(in, 1), gg::HelixHand::right);
  in.internal = true;
  EXPECT_EQ(gg::helix_hand(in, 1), gg::HelixHand::left);
}
