// Tests for gearkit/gear/measurement.hpp.
#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/involute.hpp>
#include <gearkit/gear/measurement.hpp>
#include <gearkit/gear/tooth_form.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace gg = gearkit::gear;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kAlpha = 20.0 * kDeg;

gg::ToothData tooth(int z, double m_n, double x, double beta = 0.0) {
  const double m_t = gg::transverse_module(m_n, beta);
  return gg::make_tooth_data(z, m_n, kAlpha, beta, gg::reference_tooth_thickness(m_t, x, kAlpha));
}

}  // namespace

TEST(Span, PublishedSpurExample) {
  // machinecalcs.com "Span Measurement Over Teeth Calculator", worked example: z = 20, m = 2,
  // alpha = 20 deg, x = 0: k = round(20/9 + 0.5) = 3, W = 15.321 mm, contact diameter 40.59 mm.
  const auto g = tooth(20, 2.0, 0.0);
  EXPECT_EQ(gg::span_teeth(g), 3);
  const double W = gg::span_measurement(g, 3);
  EXPECT_NEAR(W, 15.321, 5e-4);
  EXPECT_NEAR(gg::span_contact_diameter(g, W), 40.59, 5e-3);
}

TEST(Span, IsoFormulaForShiftedHelicalGears) {
  // ISO 21771 / DIN 3960: W_k = m_n cos a_n ((k - 0.5) pi + z inv a_t) + 2 x m_n sin a_n,
  // evaluated here directly (the library uses the base-thickness form).
  for (double beta : {0.0, 15.0 * kDeg, 30.0 * kDeg}) {
    for (double x : {-0.3, 0.0, 0.45}) {
      const int z = 27;
      const double m_n = 2.5;
      const auto g = tooth(z, m_n, x, beta);
      const double alpha_t = gg::transverse_pressure_angle(kAlpha, beta);
      for (int k = 2; k <= 6; ++k) {
        const double iso = m_n * std::cos(kAlpha) * ((k - 0.5) * std::numbers::pi + z * gg::involute(alpha_t)) +
                           2.0 * x * m_n * std::sin(kAlpha);
        EXPECT_NEAR(gg::span_measurement(g, k), iso, 1e-11);
      }
    }
  }
}

TEST(Span, TeethSpannedRule) {
  // Textbook rule for x = 0 spur gears: k = round(z alpha / 180 deg + 0.5) (machinecalcs.com
  // example: k = round(z/9 + 0.5)); with shift the KHK/Niemann rule puts the anvils at d + 2 x m,
  // so the wanted diameter lies between the contact diameters of k - 1 and k + 1 teeth, and the
  // contact of the chosen k stays on the flank (between base and tip circles).
  for (int z : {10, 12, 24, 40, 75, 140}) {
    EXPECT_EQ(gg::span_teeth(tooth(z, 3.0, 0.0)), static_cast<int>(std::lround(z / 9.0 + 0.5))) << z;
    for (double x : {-0.4, 0.0, 0.5}) {
      const auto g = tooth(z, 3.0, x);
      const int k = gg::span_teeth(g);
      const double target = z * 3.0 + 2.0 * x * 3.0;
      auto contact = [&](int kk) { return gg::span_contact_diameter(g, gg::span_measurement(g, kk)); };
      if (k > 1) {
        EXPECT_LE(contact(k - 1), target + 1e-9) << z << " " << x;
      }
      EXPECT_GE(contact(k + 1), target - 1e-9) << z << " " << x;
      EXPECT_GT(contact(k), z * 3.0 * std::cos(kAlpha));
      EXPECT_LT(contact(k), z * 3.0 + 2.0 * 3.0 * (1.0 + x));
    }
  }
  EXPECT_THROW(gg::span_teeth(tooth(-60, 3.0, 0.0)), std::domain_error);
}

TEST(Pins, ClassicalPinDiameterRule) {
  // Textbook: for a standard spur gear the pin touching at the reference circle has
  // alpha_M = alpha + pi/(2z) (hand derivation) and, for many teeth, D -> pi m / (2 cos alpha)
  // = 1.6716 m (the "1.68 m" workshop rule, tandwiel.info lists 1.75 m as the nearest standard pin).
  const auto g = tooth(40, 2.0, 0.0);
  const double d = 80.0, d_b = d * std::cos(kAlpha);
  const double D = gg::pin_diameter_for_contact_at(g, d);
  const double alpha_M = kAlpha + std::numbers::pi / 80.0;
  EXPECT_NEAR(D, d_b * (std::tan(alpha_M) - std::tan(kAlpha)), 1e-12);
  EXPECT_NEAR(gg::pin_centre_pressure_angle(g, D), alpha_M, 1e-12);
  EXPECT_NEAR(gg::dimension_over_pins(g, D), d_b / std::cos(alpha_M) + D, 1e-10);
  // Second-order term m sin(a) pi^2 / (4 z cos^2 a) = 0.956 m / z: 1e-5 at z = 100000.
  EXPECT_NEAR(gg::pin_diameter_for_contact_at(tooth(100000, 1.0, 0.0), 100000.0), std::numbers::pi / (2.0 * std::cos(kAlpha)), 2e-5);
  EXPECT_NEAR(std::numbers::pi / (2.0 * std::cos(kAlpha)), 1.6716, 1e-4);
}

TEST(Pins, OddToothCountUsesTheChordAcross) {
  // Odd z: the pins sit (z - 1)/2 pitches apart, M = d_M cos(90 deg / z) + D.
  const auto g = tooth(25, 2.0, 0.2);
  const double D = 3.5;
  const double a_M = gg::pin_centre_pressure_angle(g, D);
  const double d_M = 50.0 * std::cos(kAlpha) / std::cos(a_M);
  EXPECT_NEAR(gg::dimension_over_pins(g, D), d_M * std::cos(std::numbers::pi / 50.0) + D, 1e-10);
}

TEST(Pins, PinTouchesTheGeneratedFlank) {
  // Independent check with the tooth form: the pin centre lies on the space centre line at
  // radius d_M/2 and its distance to the generated involute flank equals D/2.
  for (double x : {-0.2, 0.0, 0.5}) {
    const int z = 30;
    const double m = 4.0;
    const auto g = tooth(z, m, x);
    const double D = gg::pin_diameter_for_contact_at(g, z * m + 2.0 * x * m);
    const double d_M = z * m * std::cos(kAlpha) / std::cos(gg::pin_centre_pressure_angle(g, D));
    gg::ToothFormSpec spec;
    spec.z = z;
    spec.m_n = m;
    spec.x = x;
    spec.d_a = z * m + 2.0 * m * (1.0 + x);
    spec.tolerance = 1e-5;
    const auto flank = gg::space_flank(spec);
    double dmin = std::numeric_limits<double>::infinity();
    for (const auto& p : flank) dmin = std::min(dmin, std::hypot(p.x, p.y - 0.5 * d_M));
    EXPECT_NEAR(dmin, 0.5 * D, 2e-5) << x;
  }
}

TEST(Pins, InternalGearBetweenPins) {
  // Internal gear: the ring space is shaped like a pinion tooth; with signed values
  // inv a_M = inv a + e/|d| - D/|d_b| and M = d_M - D (even z) (hand derivation, DIN 3960
  // measurement between balls). z = -60, m = 2, x = 0: e = pi m / 2.
  const gg::ToothData ring = gg::make_tooth_data(-60, 2.0, kAlpha, 0.0, gg::reference_tooth_thickness(2.0, 0.0, kAlpha));
  const double D = 3.0, d = 120.0, d_b = d * std::cos(kAlpha);
  const double inv_M = gg::involute(kAlpha) + std::numbers::pi / 120.0 - D / d_b;
  const double d_M = d_b / std::cos(gg::inverse_involute(inv_M));
  EXPECT_NEAR(gg::dimension_over_pins(ring, D), d_M - D, 1e-10);
  const double D_ref = gg::pin_diameter_for_contact_at(ring, -120.0);
  EXPECT_GT(D_ref, 1.5);
  EXPECT_LT(D_ref, 1.75 * 2.0);  // tandwiel.info: about 1.65 m for internal 20 deg gears
}

TEST(ToothData, DerivedMembers) {
  const auto g = tooth(31, 3.5, 0.25, 21.0 * kDeg);
  EXPECT_NEAR(g.alpha_t / kDeg, 21.2990642859, 1e-9);  // ISO 21771 spreadsheet (see test_gear_pair.cpp)
  EXPECT_NEAR(g.x, 0.25, 1e-14);
  EXPECT_NEAR(g.d_b, g.d * std::cos(g.alpha_t), 1e-12);
  EXPECT_THROW(gg::make_tooth_data(0, 3.0, kAlpha, 0.0, 4.0), std::domain_error);
}

TEST(ToothData, ThicknessAtADiameterMatchesTheGeneralFormula) {
  for (double d_y : {50.0, 53.0, 60.0 * std::cos(kAlpha) + 1e-3}) {
    const auto g = tooth(20, 2.5, 0.3);
    EXPECT_NEAR(gg::tooth_thickness_at(g, d_y), gg::tooth_thickness_at(g.s_t, g.d, g.d_b, g.alpha_t, d_y), 1e-12);
  }
}

TEST(Chordal, PublishedSpurAndHelicalExamples) {
  // SDP/SI "Elements of Metric Gear Technology" Table 10-1: m = 10, z = 12, x = +0.3,
  // h_a = 13.000 -> s_j = 17.8256, h_j = 13.6657.
  const auto g = tooth(12, 10.0, 0.3);
  EXPECT_NEAR(gg::chordal_thickness(g), 17.8256, 5e-5);
  EXPECT_NEAR(gg::chordal_height(g, 120.0 + 26.0), 13.6657, 5e-5);
  // Table 10-4 (helical, normal system): m_n = 5, beta = 25 deg, z = 16, x_n = +0.2, h_a = 6:
  // s_n = 8.5819, z_v = z/cos^3(beta) = 21.4928, s_j = 8.5728, h_j = 6.1712.
  const auto h = tooth(16, 5.0, 0.2, 25.0 * kDeg);
  const double d = gg::reference_diameter(16, 5.0, 25.0 * kDeg);
  EXPECT_NEAR(h.s_t * std::cos(25.0 * kDeg), 8.5819, 5e-5);
  EXPECT_NEAR(gg::chordal_thickness(h), 8.5728, 5e-5);
  EXPECT_NEAR(gg::chordal_height(h, d + 12.0), 6.1712, 5e-5);
}

TEST(Pins, UsableRangeStandsOutOfTheTip) {
  // z = 20, m = 3, x = 0: the pin flush with the tip has zero protrusion, a bigger one stands out,
  // and the classical pin touching at the reference circle (about 1.68 m) lies within the range
  // between the flush pin and the pin touching at the tip circle.
  const auto g = tooth(20, 3.0, 0.0);
  const double d_a = 66.0;
  const double D_flush = gg::pin_diameter_flush_with_tip(g, d_a);
  EXPECT_NEAR(gg::pin_protrusion(g, D_flush, d_a), 0.0, 1e-9);
  EXPECT_GT(gg::pin_protrusion(g, D_flush * 1.05, d_a), 0.0);
  const double D_ref = gg::pin_diameter_for_contact_at(g, 60.0);
  EXPECT_GT(D_ref, D_flush);
  EXPECT_LT(D_ref, gg::pin_diameter_for_contact_at(g, d_a));
  // Protrusion by hand for the reference pin: (d_M + D - d_a) / 2 with d_M from M_d (even z).
  EXPECT_NEAR(gg::pin_protrusion(g, D_ref, d_a), 0.5 * (gg::dimension_over_pins(g, D_ref) - d_a), 1e-12);
  EXPECT_THROW(gg::pin_diameter_flush_with_tip(tooth(-40, 3.0, 0.0), -114.0), std::domain_error);
}
