// Tests for gearkit/gear/inspection.hpp.
#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/inspection.hpp>
#include <gearkit/gear/measurement.hpp>
#include <gearkit/gear/thickness_tolerance.hpp>

#include "kisssoft_stage3.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace gg = gearkit::gear;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
const double kCos20 = std::cos(20 * kDeg), kTan20 = std::tan(20 * kDeg);

gg::GearPairInput spur_20_40() {
  gg::GearPairInput in;
  in.z1 = 20;
  in.z2 = 40;
  in.module = 3.0;
  in.face_width = 30.0;
  return in;
}

gg::InspectionInput grade(int q1, int q2) {
  gg::InspectionInput ii;
  ii.grade = {q1, q2};
  return ii;
}

std::string field_of(const gg::GearPairInput& in, const gg::InspectionInput& ii) {
  try {
    gg::compute_inspection(in, gg::compute_gear_pair(in), ii);
  } catch (const gg::GeometryError& e) {
    return e.field();
  }
  return "";
}

}  // namespace

// z = 20/40, m = 3 mm, b = 30 mm, ISO 1328-1:2013 class 7, ISO/TR 10064-2 allowances, by hand:
// a = 90 mm: j_bn,min = 2/3 (0.06 + 0.045 + 0.09) = 0.13 mm; centre distance js8 (grade 7-8), IT8 of
// 90 mm = 54 um -> A_a = +-0.027 mm. Gear 1 (d = 60 mm): F_pT = (0.12 + 4.2603 + 2.1 + 12) 2 = 36.96,
// F_rT = 0.9 * 36.96 = 33.26 -> 33 um; b_r = IT9(60) = 74 um; T_sn = 2 tan 20 sqrt(33^2 + 74^2) =
// 58.98 um. Gear 2 (d = 120 mm): F_pT = (0.24 + 6.0249 + 2.1 + 12) 2 = 40.73, F_rT = 36.66 -> 37 um;
// b_r = IT9(120) = 87 um; T_sn = 0.72794 sqrt(37^2 + 87^2) = 68.82 um.
TEST(Inspection, IsoTrAllowancesOfASpurPair) {
  const auto in = spur_20_40();
  const auto table = gg::compute_gear_pair(in);
  const auto r = gg::compute_inspection(in, table, grade(7, 7));
  EXPECT_EQ(r.pair.centre_distance_field, "js8");
  EXPECT_DOUBLE_EQ(r.pair.A_ae, 0.027);
  EXPECT_DOUBLE_EQ(r.pair.A_ai, -0.027);
  EXPECT_NEAR(r.pair.j_bn_min_target, 0.13, 1e-12);
  EXPECT_DOUBLE_EQ(r.gear[0].tolerances->F_rT, 33.0);
  EXPECT_DOUBLE_EQ(r.gear[1].tolerances->F_rT, 37.0);
  EXPECT_DOUBLE_EQ(r.gear[0].b_r, 74.0);
  EXPECT_DOUBLE_EQ(r.gear[1].b_r, 87.0);
  EXPECT_NEAR(r.gear[0].T_sn, 0.05898, 1e-5);
  EXPECT_NEAR(r.gear[1].T_sn, 0.06882, 1e-5);
  // Equal upper allowances that leave exactly j_bn,min at the smallest centre distance; linear
  // rule: 2 A_sne cos(alpha_n) = -(j_bn,min + 2 * 0.027 sin(alpha_w)) (alpha_w = 20 deg here).
  EXPECT_DOUBLE_EQ(r.gear[0].allowances.A_sne, r.gear[1].allowances.A_sne);
  EXPECT_NEAR(r.pair.range.min.j_n, 0.13, 1e-12);
  EXPECT_NEAR(r.gear[0].allowances.A_sne, -(0.13 + 0.054 * std::sin(20 * kDeg)) / (2 * kCos20), 3e-5);
  EXPECT_EQ(r.gear[0].source, gg::AllowanceSource::iso_tr_10064_2);
  // Largest backlash: both tolerances and the whole centre distance field on top (linear rule).
  EXPECT_NEAR(r.pair.range.max.j_n, 0.13 + (0.05898 + 0.06882) * kCos20 + 4 * 0.027 * std::sin(20 * kDeg), 2e-5);
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
}

// Span limits: W_k changes by exactly A cos(alpha_n) (ISO 21771: W_k = ... + 2 x m_n sin alpha_n),
// with the DIN 3967 runout term 0.72 F_r sin(alpha_n) taken off both limits.
TEST(Inspection, SpanLimitsFollowDin3967) {
  const auto in = spur_20_40();
  const auto table = gg::compute_gear_pair(in);
  const auto r = gg::compute_inspection(in, table, grade(7, 7));
  for (int i = 0; i < 2; ++i) {
    const auto& g = r.gear[i];
    const double runout = 0.72 * 1e-3 * g.F_r * std::sin(20 * kDeg);
    EXPECT_NEAR(g.W_k_max, table.gear[i].W_k + g.allowances.A_sne * kCos20 - runout, 1e-12);
    EXPECT_NEAR(g.W_k_min, table.gear[i].W_k + g.allowances.A_sni * kCos20 + runout, 1e-12);
    EXPECT_GT(g.d_W_min, table.gear[i].d_Ff);
    EXPECT_LT(g.d_W_max, table.gear[i].d_a);
  }
}

// Pins: the exact limits against the linearised rule of the tolerance sheets,
// dM = dW / (sin(alpha_Mt) cos(beta_b)) for even z (qiqiwenku "齿轮公差计算": E_ms = E_wms / (sin
// alpha_Mt cos beta_b)), on a helical gear.
TEST(Inspection, PinLimitsAgreeWithTheLinearisedRule) {
  gg::GearPairInput in = spur_20_40();
  in.helix_angle = 15 * kDeg;
  const auto table = gg::compute_gear_pair(in);
  const auto r = gg::compute_inspection(in, table, grade(6, 6));
  const auto& g = table.gear[0];
  const auto nominal = gg::make_tooth_data(20, 3.0, 20 * kDeg, 15 * kDeg, g.s_t);
  const double alpha_Mt = gg::pin_centre_pressure_angle(nominal, g.pin_diameter);
  const double per_span = 1.0 / (std::sin(alpha_Mt) * std::cos(g.beta_b));
  const auto& gi = r.gear[0];
  // Linearised: within 1 % (alpha_Mt itself moves with the thickness).
  EXPECT_NEAR(gi.M_d_max - g.M_d, (gi.W_k_max - g.W_k) * per_span, 0.01 * std::fabs(gi.M_d_max - g.M_d));
  EXPECT_NEAR(gi.M_d_min - g.M_d, (gi.W_k_min - g.W_k) * per_span, 0.01 * std::fabs(gi.M_d_min - g.M_d));
  EXPECT_LT(gi.D_M_min, gi.D_M);
  EXPECT_GT(gi.D_M_max, gi.D_M);
  // The face width the spans need: the largest span measured (here the nominal W_k, as both
  // allowances are negative) times sin(beta_b).
  EXPECT_NEAR(gi.b_min_span, std::max({g.W_k, gi.W_k_max, gi.W_k_min}) * std::sin(g.beta_b), 1e-12);
  EXPECT_GT(g.W_k, gi.W_k_max);
}

TEST(Inspection, GivenAllowancesAndCentreDistance) {
  const auto in = spur_20_40();
  const auto table = gg::compute_gear_pair(in);
  gg::InspectionInput ii;
  ii.allowances = {gg::ThicknessAllowances{-0.05, -0.1}, gg::ThicknessAllowances{-0.06, -0.12}};
  ii.centre_distance_allowances = gg::ThicknessAllowances{0.02, -0.01};
  const auto r = gg::compute_inspection(in, table, ii);
  EXPECT_EQ(r.gear[0].source, gg::AllowanceSource::given);
  EXPECT_FALSE(r.gear[0].tolerances.has_value());
  EXPECT_DOUBLE_EQ(r.gear[1].T_sn, 0.06);
  // No grade, no runout term: W_k limits are the allowances themselves, cos(alpha_n) apart.
  EXPECT_NEAR(r.gear[0].W_k_max - r.gear[0].W_k_min, 0.05 * kCos20, 1e-12);
  EXPECT_NEAR(r.pair.range.min.j_n, 0.11 * kCos20 - 0.02 * std::sin(20 * kDeg), 2e-5);
  EXPECT_NEAR(r.pair.range.max.j_n, 0.22 * kCos20 + 0.04 * std::sin(20 * kDeg), 2e-5);
  EXPECT_TRUE(std::isnan(r.pair.j_bn_min_target));
}

// DIN 3967 designation 25cd on z = 20/41, m = 2 (d = 40 / 82 mm): Table 1 cd = -54 / -70 um,
// Table 2 series 25 = 30 / 40 um; without a grade no runout term, so the span limits are exactly
// the allowances times cos(alpha_n) (DIN 3967 Appendix B, A_We = A_sne cos alpha_n).
TEST(Inspection, Din3967Designations) {
  gg::GearPairInput in;
  in.z1 = 20;
  in.z2 = 41;
  in.module = 2.0;
  const auto table = gg::compute_gear_pair(in);
  gg::InspectionInput ii;
  ii.din3967 = {gg::parse_din3967("25cd"), gg::parse_din3967("25cd")};
  const auto r = gg::compute_inspection(in, table, ii);
  EXPECT_EQ(r.gear[0].source, gg::AllowanceSource::din3967);
  EXPECT_EQ(r.gear[1].din3967, "25cd");
  EXPECT_NEAR(r.gear[0].allowances.A_sne, -0.054, 1e-12);
  EXPECT_NEAR(r.gear[0].allowances.A_sni, -0.084, 1e-12);
  EXPECT_NEAR(r.gear[1].allowances.A_sni, -0.110, 1e-12);
  EXPECT_NEAR(r.gear[1].W_k_max, table.gear[1].W_k - 0.070 * kCos20, 1e-12);
  EXPECT_EQ(r.pair.centre_distance_field, "none");  // no grade, no field given: the nominal distance
  EXPECT_NEAR(r.pair.range.min.j_n, 0.124 * kCos20, 1e-12);
  // With a grade too, DIN 3967's runout term narrows the span limits (F_rT of class 8).
  ii.grade = {8, 8};
  const auto q = gg::compute_inspection(in, table, ii);
  EXPECT_EQ(q.gear[0].source, gg::AllowanceSource::din3967);
  EXPECT_NEAR(q.gear[0].W_k_max, table.gear[0].W_k + (-0.054 - 0.72e-3 * q.gear[0].F_r * kTan20) * kCos20, 1e-12);
}

TEST(Inspection, NegativeMinimumBacklashIsAWarning) {
  const auto in = spur_20_40();
  gg::InspectionInput ii;
  ii.allowances = {gg::ThicknessAllowances{0.0, -0.03}, gg::ThicknessAllowances{0.0, -0.03}};
  ii.centre_distance_it = 8;
  const auto r = gg::compute_inspection(in, gg::compute_gear_pair(in), ii);
  EXPECT_LT(r.pair.range.min.j_n, 0.0);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.back().find("minimum backlash"), std::string::npos);
}

// Operating temperatures: with an aluminium housing 60 K warmer and steel gears 40 K warmer the
// allowances are chosen for the tighter of the two states; j_n,min then holds in both.
TEST(Inspection, ThermalStateSetsTheAllowances) {
  const auto in = spur_20_40();
  const auto table = gg::compute_gear_pair(in);
  auto ii = grade(7, 7);
  ii.T_gears = 60.0;
  ii.T_housing = 40.0;  // housing cooler than the gears: the warm state is the tighter one
  const auto r = gg::compute_inspection(in, table, ii);
  ASSERT_TRUE(r.pair.operating.has_value());
  EXPECT_NEAR(r.pair.operating->min.j_n, 0.13, 1e-9);
  EXPECT_GT(r.pair.range.min.j_n, 0.13);
  // Linear check: gears 40 K, housing 20 K above 20 deg C, both steel: the bores move apart by
  // a (e_h - e_g) = 90 * 11.5e-6 * (20 - 40) mm, costing 2 |da| sin(alpha_w) of backlash.
  EXPECT_NEAR(r.pair.range.min.j_n - 0.13, 2 * 90 * 11.5e-6 * 20 * std::sin(20 * kDeg), 5e-5);
}

TEST(Inspection, RingGear) {
  gg::GearPairInput in;
  in.z1 = 17;
  in.z2 = 60;
  in.internal = true;
  in.module = 2.0;
  in.x1 = 0.2;
  in.x2 = 0.2;
  const auto r = gg::compute_inspection(in, gg::compute_gear_pair(in), grade(8, 8));
  EXPECT_TRUE(std::isnan(r.gear[1].W_k_max));       // no span on a ring
  EXPECT_TRUE(std::isnan(r.gear[1].D_M_min));       // pin range needs the ring's cutter
  EXPECT_GT(r.gear[1].M_d_max, r.gear[1].M_d_min);  // between pins, thin teeth give the larger value
  EXPECT_NEAR(r.pair.range.min.j_n, r.pair.j_bn_min_target, 1e-9);
}

TEST(Inspection, BadInputNamesTheField) {
  const auto in = spur_20_40();
  gg::InspectionInput none;
  none.grade = {7, std::nullopt};
  EXPECT_EQ(field_of(in, none), "grade2");
  EXPECT_EQ(field_of(in, grade(12, 7)), "grade1");
  gg::InspectionInput crossed = grade(7, 7);
  crossed.allowances[0] = gg::ThicknessAllowances{-0.1, -0.05};
  EXPECT_EQ(field_of(in, crossed), "allowances1");
  gg::InspectionInput a = grade(7, 7);
  a.centre_distance_allowances = gg::ThicknessAllowances{-0.1, 0.05};
  EXPECT_EQ(field_of(in, a), "centre_distance_allowances");
  gg::InspectionInput it = grade(7, 7);
  it.centre_distance_it = 3;
  EXPECT_EQ(field_of(in, it), "centre_distance_it");
  EXPECT_EQ(gg::default_centre_distance_it(4), 6);
  EXPECT_EQ(gg::default_centre_distance_it(6), 7);
  EXPECT_EQ(gg::default_centre_distance_it(7), 8);
  EXPECT_EQ(gg::default_centre_distance_it(10), 9);
  EXPECT_EQ(gg::default_centre_distance_it(11), 10);
}

// A thickness tolerance narrower than the runout term (DIN 3967: 0.72 F_r tan(alpha_n) off each
// limit) leaves no acceptance band. Gear 1, class 7: F_rT = 33 um, term 8.65 um > 5 um, so the
// measurement allowances cross: span and pin limits are both undefined (before, W_k_max < W_k_min
// while M_d was silently re-sorted). Gear 2: F_rT = 37 um, term 9.70 um < 10 um: a band remains.
TEST(Inspection, NoAcceptanceBandLeavesSpanAndPinsUndefinedAlike) {
  const auto in = spur_20_40();
  gg::InspectionInput ii = grade(7, 7);
  ii.allowances = {gg::ThicknessAllowances{0.005, -0.005}, gg::ThicknessAllowances{0.0, -0.02}};
  const auto r = gg::compute_inspection(in, gg::compute_gear_pair(in), ii);
  const auto& g1 = r.gear[0];
  EXPECT_NEAR(g1.measured.A_sne, 0.005 - 0.72 * 0.033 * kTan20, 1e-12);
  EXPECT_FALSE(g1.acceptance_band);
  for (double v : {g1.W_k_max, g1.W_k_min, g1.M_d_max, g1.M_d_min, g1.d_W_max, g1.d_W_min}) EXPECT_TRUE(std::isnan(v));
  EXPECT_DOUBLE_EQ(g1.b_min_span, 0.0);  // still defined: a spur span needs no face width
  const auto& g2 = r.gear[1];
  EXPECT_TRUE(g2.acceptance_band);
  EXPECT_GT(g2.W_k_max, g2.W_k_min);
  EXPECT_GT(g2.M_d_max, g2.M_d_min);
  int band_warnings = 0;
  for (const auto& w : r.warnings) band_warnings += w.find("no acceptance band") != std::string::npos ? 1 : 0;
  EXPECT_EQ(band_warnings, 1);
}

// ISO 1328-1:1995 has grades 0..12: grade 0 gets its tolerances and ISO/TR 10064-2 allowances
// (b_r = IT6/1.26, thickness_tolerance.hpp); it was rejected.
TEST(Inspection, Iso1328_1995GradeZero) {
  const auto in = spur_20_40();
  gg::InspectionInput ii = grade(0, 0);
  ii.edition = gg::Iso1328Edition::iso1995;
  const auto r = gg::compute_inspection(in, gg::compute_gear_pair(in), ii);
  EXPECT_EQ(r.gear[0].tolerances->grade, 0);
  EXPECT_NEAR(r.gear[0].b_r, gg::radial_infeed_tolerance(1, 60.0) / 1.26, 1e-12);
  EXPECT_LT(r.gear[0].allowances.A_sni, r.gear[0].allowances.A_sne);
  EXPECT_EQ(r.pair.centre_distance_field, "js6");
}

// One face-width warning per gear: the gear table warns when the nominal span does not fit; the
// inspection only when its limits need more face width than that.
TEST(Inspection, OneFaceWidthWarningForTheSpan) {
  gg::GearPairInput in = spur_20_40();
  in.helix_angle = 30.0 * kDeg;
  in.face_width = 8.0;
  const auto table = gg::compute_gear_pair(in);
  auto count = [](const std::vector<std::string>& ws) {
    int n = 0;
    for (const auto& w : ws) n += w.find("too narrow") != std::string::npos ? 1 : 0;
    return n;
  };
  ASSERT_EQ(count(table.warnings), 2);  // both gears' nominal spans need more than 8 mm
  EXPECT_EQ(count(gg::compute_inspection(in, table, grade(7, 7)).warnings), 0);
  // Thicker teeth (A_sne > 0) need more than the nominal span: a face width between both needs.
  gg::InspectionInput thick = grade(7, 7);
  thick.allowances = {gg::ThicknessAllowances{0.4, 0.3}, gg::ThicknessAllowances{0.4, 0.3}};
  const auto probe = gg::compute_inspection(in, table, thick);
  const double nominal_need = table.gear[0].W_k * std::sin(std::fabs(table.gear[0].beta_b));
  ASSERT_GT(probe.gear[0].b_min_span, nominal_need + 0.05);
  in.face_width = 0.5 * (nominal_need + probe.gear[0].b_min_span);
  const auto wider = gg::compute_gear_pair(in);
  const auto r = gg::compute_inspection(in, wider, thick);
  bool gear1_inspection = false;
  for (const auto& w : r.warnings) gear1_inspection |= w.rfind("gear 1: face width", 0) == 0;
  bool gear1_table = false;
  for (const auto& w : wider.warnings) gear1_table |= w.rfind("gear 1: face width", 0) == 0;
  EXPECT_TRUE(gear1_inspection);
  EXPECT_FALSE(gear1_table);
}

// KISSsoft 03/2017 report "stage_03" (kisssoft_stage3.hpp), section 6 "Measurements for tooth
// thickness" and 7 "Gear accuracy": DIN 3967 cd25 on both gears, centre distance js6, ISO
// 1328-1:1995 grade 6, pins/balls D_M = 28 / 25 mm. KISSsoft
// takes no runout term off the span (A_W = A_sn cos alpha_n): here no grade is given to the
// thickness system, as in the report. Its normal backlash is j_t cos(alpha_n) cos(beta) (DIN 3967),
// gearkit's j_t cos(alpha_wt) cos(beta_b) (ISO 21771): the circumferential backlash is compared.
TEST(Inspection, KisssoftStage3Report) {
  gg::GearPairInput in = gearkit::testing::kisssoft_stage3_geometry();
  in.pin_diameter1 = 28.0;
  in.pin_diameter2 = 25.0;
  const auto table = gg::compute_gear_pair(in);
  gg::InspectionInput ii;
  ii.din3967 = {gg::Din3967Designation{25, "cd"}, gg::Din3967Designation{25, "cd"}};
  ii.centre_distance_it = 6;
  const auto r = gg::compute_inspection(in, table, ii);
  const double A_sne[2] = {-0.130, -0.240}, A_sni[2] = {-0.190, -0.340};
  const int k[2] = {4, 13};
  const double W_k[2] = {154.167, 542.490}, W_max[2] = {154.045, 542.264}, W_min[2] = {153.989, 542.171};
  const double M_d[2] = {397.284, 1404.574}, M_max[2] = {397.035, 1403.997}, M_min[2] = {396.921, 1403.756};
  for (int i = 0; i < 2; ++i) {
    const auto& g = r.gear[i];
    EXPECT_NEAR(g.allowances.A_sne, A_sne[i], 1e-12) << i;
    EXPECT_NEAR(g.allowances.A_sni, A_sni[i], 1e-12) << i;
    EXPECT_EQ(g.k, k[i]);
    EXPECT_NEAR(table.gear[i].W_k, W_k[i], 0.0005) << i;
    EXPECT_NEAR(g.W_k_max, W_max[i], 0.0006) << i;
    EXPECT_NEAR(g.W_k_min, W_min[i], 0.0005) << i;
    // Gear 2 (odd z, helical): the report's two-ball measure MdK (its pins "MdR" differ for odd z).
    EXPECT_NEAR(table.gear[i].M_d, M_d[i], 0.0005) << i;
    EXPECT_NEAR(g.M_d_max, M_max[i], 0.0005) << i;
    EXPECT_NEAR(g.M_d_min, M_min[i], 0.0005) << i;
  }
  EXPECT_DOUBLE_EQ(r.pair.A_ae, 0.028);  // js6 of 861 mm: IT6 = 56 um
  EXPECT_NEAR(r.pair.range.max.j_t, 0.571, 0.0005);
  EXPECT_NEAR(r.pair.range.min.j_t, 0.359, 0.0005);
  // ISO 1328-1:1995 grade 6, both gears (section 7): f_pt, F_p, F_alpha, f_falpha, f_Halpha,
  // F_beta, f_fbeta = f_Hbeta, F_r (ISO 1328-2:1997 Annex B).
  const double f_pt[2] = {14, 17}, F_p[2] = {50, 78}, F_a[2] = {23, 28}, f_fa[2] = {18, 22}, f_Ha[2] = {15, 18};
  const double F_b[2] = {25, 27}, f_b[2] = {18, 19}, F_r[2] = {40, 63};
  for (int i = 0; i < 2; ++i) {
    const auto t = gg::flank_tolerances({table.gear[i].d, 14.0, 360.0, table.gear[i].z, table.gear[i].beta, 6,
                                         gg::Iso1328Edition::iso1995});
    EXPECT_DOUBLE_EQ(t.f_pT, f_pt[i]) << i;
    EXPECT_DOUBLE_EQ(t.F_pT, F_p[i]) << i;
    EXPECT_DOUBLE_EQ(t.F_alphaT, F_a[i]) << i;
    EXPECT_DOUBLE_EQ(t.f_falphaT, f_fa[i]) << i;
    EXPECT_DOUBLE_EQ(t.f_HalphaT, f_Ha[i]) << i;
    EXPECT_DOUBLE_EQ(t.F_betaT, F_b[i]) << i;
    EXPECT_DOUBLE_EQ(t.f_fbetaT, f_b[i]) << i;
    EXPECT_DOUBLE_EQ(t.f_HbetaT, f_b[i]) << i;
    EXPECT_DOUBLE_EQ(t.F_rT, F_r[i]) << i;
  }
}
