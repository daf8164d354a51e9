// Tests for gearkit/gear/accuracy.hpp: ISO 1328-1:2013 flank tolerances and their rounding, the
// 1995 edition's tabulated values and ISO 1328-2:1997 radial composite tolerances.
#include <gearkit/gear/accuracy.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gg = gearkit::gear;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

gg::FlankTolerances tolerances(double d, double m_n, double b, int grade,
                               gg::Iso1328Edition edition = gg::Iso1328Edition::iso2013) {
  gg::ToleranceInput in;
  in.d = d;
  in.m_n = m_n;
  in.b = b;
  in.grade = grade;
  in.edition = edition;
  return gg::flank_tolerances(in);
}

}  // namespace

// ISO 1328-1:2013 5.2.3: > 10 um to 1 um, 5..10 um to 0.5 um, < 5 um to 0.1 um.
TEST(Accuracy, RoundingRulesOfClause523) {
  EXPECT_DOUBLE_EQ(gg::round_iso1328(12.49), 12.0);
  EXPECT_DOUBLE_EQ(gg::round_iso1328(10.6), 11.0);
  EXPECT_DOUBLE_EQ(gg::round_iso1328(10.4), 10.0);
  EXPECT_DOUBLE_EQ(gg::round_iso1328(9.8), 10.0);
  EXPECT_DOUBLE_EQ(gg::round_iso1328(7.76), 8.0);
  EXPECT_DOUBLE_EQ(gg::round_iso1328(7.3), 7.5);
  EXPECT_DOUBLE_EQ(gg::round_iso1328(7.2), 7.0);
  EXPECT_DOUBLE_EQ(gg::round_iso1328(5.1), 5.0);
  EXPECT_DOUBLE_EQ(gg::round_iso1328(4.96), 5.0);
  EXPECT_DOUBLE_EQ(gg::round_iso1328(4.94), 4.9);
  EXPECT_DOUBLE_EQ(gg::round_iso1328(0.827), 0.8);
  EXPECT_TRUE(std::isnan(gg::round_iso1328(std::nan(""))));
}

// Hand derivation, ISO 1328-1:2013 formulas (5)-(12), d = 120 mm (z = 40, m_n = 3 mm), b = 30 mm,
// class 6 (factor sqrt 2): f_pT = (0.12 + 1.2 + 5) 1.41421 = 8.938 -> 9.0; F_pT = (0.24 + 6.0249 +
// 2.1 + 12) 1.41421 = 28.80 -> 29; f_HalphaT = 5.32 * 1.41421 = 7.524 -> 7.5; f_falphaT = 6.65 *
// 1.41421 = 9.405 -> 9.5; F_alphaT = hypot(7.524, 9.405) = 12.04 -> 12; f_HbetaT = (0.5477 + 1.9170
// + 4) 1.41421 = 9.143 -> 9.0; f_fbetaT = (0.7668 + 2.4648 + 4) 1.41421 = 10.23 -> 10; F_betaT =
// hypot = 13.72 -> 14; F_rT = 0.9 * 28.80 = 25.92 -> 26. The same gear and class is a published
// check of a public ISO 1328-1:2013 transcription (f_pT 9.0, F_pT 29, F_alphaT 12).
TEST(Accuracy, HandDerivedClass6Gear) {
  EXPECT_NEAR(gg::single_pitch_tolerance(120, 3, 6), 8.9378, 1e-4);
  EXPECT_NEAR(gg::total_cumulative_pitch_tolerance(120, 3, 6), 28.8004, 1e-4);
  const auto t = tolerances(120, 3, 30, 6);
  EXPECT_DOUBLE_EQ(t.f_pT, 9.0);
  EXPECT_DOUBLE_EQ(t.F_pT, 29.0);
  EXPECT_DOUBLE_EQ(t.f_HalphaT, 7.5);
  EXPECT_DOUBLE_EQ(t.f_falphaT, 9.5);
  EXPECT_DOUBLE_EQ(t.F_alphaT, 12.0);
  EXPECT_DOUBLE_EQ(t.f_HbetaT, 9.0);
  EXPECT_DOUBLE_EQ(t.f_fbetaT, 10.0);
  EXPECT_DOUBLE_EQ(t.F_betaT, 14.0);
  EXPECT_DOUBLE_EQ(t.F_rT, 26.0);
  EXPECT_TRUE(t.outside_scope.empty());
}

// Grid over modules, diameters and classes: ISO 1328-1:2013 formulas (5), (6), (7)-(9) evaluated
// independently (Python 3, decimal arithmetic, half-up rounding of 5.2.3) for each cell; cells with
// fewer than 5 teeth (d < 5 m_n) are left out as the standard does (5 <= z).
TEST(Accuracy, Iso2013GridOfModulesDiametersAndClasses) {
  struct Cell {
    double m_n, d;
    int A;
    double f_pT, F_pT, F_alphaT;
  };
  const Cell cells[] = {
#include "accuracy_grid_pitch.inc"
  };
  int n = 0;
  for (const Cell& c : cells) {
    const auto t = tolerances(c.d, c.m_n, 0.0, c.A);
    EXPECT_DOUBLE_EQ(t.f_pT, c.f_pT) << "m_n " << c.m_n << " d " << c.d << " A " << c.A;
    EXPECT_DOUBLE_EQ(t.F_pT, c.F_pT) << "m_n " << c.m_n << " d " << c.d << " A " << c.A;
    EXPECT_DOUBLE_EQ(t.F_alphaT, c.F_alphaT) << "m_n " << c.m_n << " d " << c.d << " A " << c.A;
    ++n;
  }
  EXPECT_EQ(n, 100);
}

// The same for the helix tolerances (10)-(12) over diameters, face widths and classes.
TEST(Accuracy, Iso2013GridOfDiametersFaceWidthsAndClasses) {
  struct Cell {
    double d, b;
    int A;
    double f_HbetaT, f_fbetaT, F_betaT;
  };
  const Cell cells[] = {
#include "accuracy_grid_helix.inc"
  };
  for (const Cell& c : cells) {
    const auto t = tolerances(c.d, 2.0, c.b, c.A);
    EXPECT_DOUBLE_EQ(t.f_HbetaT, c.f_HbetaT) << "d " << c.d << " b " << c.b << " A " << c.A;
    EXPECT_DOUBLE_EQ(t.f_fbetaT, c.f_fbetaT) << "d " << c.d << " b " << c.b << " A " << c.A;
    EXPECT_DOUBLE_EQ(t.F_betaT, c.F_betaT) << "d " << c.d << " b " << c.b << " A " << c.A;
  }
}

// 5.2.2: two classes apart the unrounded values differ by exactly a factor 2.
TEST(Accuracy, TwoClassesApartDoubleTheUnroundedValue) {
  for (int A = 1; A <= 9; ++A) {
    EXPECT_NEAR(gg::single_pitch_tolerance(300, 4, A + 2), 2 * gg::single_pitch_tolerance(300, 4, A), 1e-12);
    EXPECT_NEAR(gg::total_profile_tolerance(300, 4, A + 2), 2 * gg::total_profile_tolerance(300, 4, A), 1e-12);
    EXPECT_NEAR(gg::total_helix_tolerance(300, 50, A + 2), 2 * gg::total_helix_tolerance(300, 50, A), 1e-12);
  }
}

// ISO 1328-1:1995 Table 1 (+-f_pt) and Table 2 (F_p), row 5 <= d <= 20 mm, 0.5 <= m <= 2 mm, grades
// 0..12. The rows are the clause 6 formulas at the geometric means sqrt(5 * 20) = 10 mm and
// sqrt(0.5 * 2) = 1 mm: f_pt(5) = 0.3 (1 + 0.4 sqrt 10) + 4 = 4.679 -> 4.7, F_p(5) = 0.3 + 1.25 sqrt 10
// + 7 = 11.25 -> 11.
TEST(Accuracy, Iso1995TabulatedRowSmallGears) {
  const double f_pt[] = {0.8, 1.2, 1.7, 2.3, 3.3, 4.7, 6.5, 9.5, 13, 19, 26, 37, 53};
  const double F_p[] = {2.0, 2.8, 4.0, 5.5, 8.0, 11, 16, 23, 32, 45, 64, 90, 127};
  for (int Q = 0; Q <= 12; ++Q) {
    for (double d : {5.0, 12.0, 20.0}) {
      const auto t = tolerances(d, 1.5, 0.0, Q, gg::Iso1328Edition::iso1995);
      EXPECT_DOUBLE_EQ(t.f_pT, f_pt[Q]) << "Q " << Q << " d " << d;
      EXPECT_DOUBLE_EQ(t.F_pT, F_p[Q]) << "Q " << Q << " d " << d;
    }
  }
}

// 1995 edition, grade 6, d = 120 mm (range 50..125, mean 79.06 mm), m_n = 3 mm (2..3.5, mean
// 2.646 mm), b = 30 mm (20..40, mean 28.28 mm), by hand: f_pt = 0.3 (2.646 + 3.557) + 4 = 5.861 *
// 1.41421 = 8.29 -> 8.5; F_p = 0.794 + 11.114 + 7 = 18.91 * 1.41421 = 26.74 -> 27; F_alpha = 5.205 +
// 1.956 + 0.7 = 7.861 * 1.41421 = 11.12 -> 11; f_falpha = 8.60 -> 8.5; f_Halpha = 7.07 -> 7.0;
// F_beta = (0.889 + 3.350 + 4.2) 1.41421 = 11.94 -> 12; f_fbeta = f_Hbeta = 8.51 -> 8.5;
// F_r (ISO 1328-2:1997 Annex B, 0.8 F_p) = 21.39 -> 21.
TEST(Accuracy, Iso1995HandDerivedClass6Gear) {
  const auto t = tolerances(120, 3, 30, 6, gg::Iso1328Edition::iso1995);
  EXPECT_DOUBLE_EQ(t.f_pT, 8.5);
  EXPECT_DOUBLE_EQ(t.F_pT, 27.0);
  EXPECT_DOUBLE_EQ(t.F_alphaT, 11.0);
  EXPECT_DOUBLE_EQ(t.f_falphaT, 8.5);
  EXPECT_DOUBLE_EQ(t.f_HalphaT, 7.0);
  EXPECT_DOUBLE_EQ(t.F_betaT, 12.0);
  EXPECT_DOUBLE_EQ(t.f_fbetaT, 8.5);
  EXPECT_DOUBLE_EQ(t.f_HbetaT, 8.5);
  EXPECT_DOUBLE_EQ(t.F_rT, 21.0);
}

// ISO 1328-2:1997 Annex B: F_r = 0.8 F_p, written out as 0.24 m + 1.0 sqrt(d) + 5.6.
TEST(Accuracy, Iso1997RunoutIsEightTenthsOfTotalPitch) {
  for (double d : {10.0, 79.06, 1000.0}) {
    for (double m : {1.0, 3.16, 20.0}) {
      EXPECT_NEAR(gg::runout_tolerance_1997(d, m, 7), 0.8 * gg::total_cumulative_pitch_tolerance_1995(d, m, 7), 1e-12);
    }
  }
}

// ISO 1328-2:1997, grade 6, d = 120 mm (radial composite range 50..125: 79.06 mm), m_n = 3 mm
// (2.5..4: sqrt 10 = 3.162 mm): F_i'' = (10.119 + 8.980 + 6.4) 1.41421 = 36.06 -> 36;
// f_i'' = (9.360 + 0.089 + 0.8) 1.41421 = 14.49 -> 14.
TEST(Accuracy, Iso1997RadialCompositeHandDerived) {
  for (auto edition : {gg::Iso1328Edition::iso2013, gg::Iso1328Edition::iso1995}) {
    const auto t = tolerances(120, 3, 30, 6, edition);
    EXPECT_DOUBLE_EQ(t.F_idT, 36.0);
    EXPECT_DOUBLE_EQ(t.f_idT, 14.0);
  }
  EXPECT_TRUE(std::isnan(tolerances(120, 3, 30, 3).F_idT));    // grades 4..12 only
  EXPECT_TRUE(std::isnan(tolerances(120, 12, 30, 6).f_idT));   // m_n <= 10 mm
  EXPECT_TRUE(std::isnan(tolerances(1200, 3, 30, 6).F_idT));   // d <= 1000 mm
}

TEST(Accuracy, RangeMeanOfThe1995Tables) {
  const auto& d = gg::iso1328_1995_diameter_limits();
  EXPECT_DOUBLE_EQ(gg::iso1328_1995_range_mean(5.0, d), 10.0);
  EXPECT_DOUBLE_EQ(gg::iso1328_1995_range_mean(20.0, d), 10.0);  // upper limits belong to their range
  EXPECT_DOUBLE_EQ(gg::iso1328_1995_range_mean(20.5, d), std::sqrt(1000.0));
  EXPECT_DOUBLE_EQ(gg::iso1328_1995_range_mean(2.0, d), 10.0);   // below the table: first range
  EXPECT_DOUBLE_EQ(gg::iso1328_1995_range_mean(2e4, d), std::sqrt(8e7));
  EXPECT_THROW(gg::iso1328_1995_range_mean(1.0, {1.0}), std::invalid_argument);
}

TEST(Accuracy, ScopeAndMissingFaceWidth) {
  gg::ToleranceInput in;
  in.d = 3.0;
  in.m_n = 0.3;
  in.z = 10;
  in.beta = 50 * kDeg;
  in.grade = 7;
  const auto t = gg::flank_tolerances(in);
  EXPECT_EQ(t.outside_scope.size(), 3u);  // d, m_n, beta
  EXPECT_TRUE(std::isnan(t.F_betaT));     // no face width
  EXPECT_GT(t.f_pT, 0.0);                 // computed anyway, to be agreed
  in.b = 2000;
  in.d = 100;
  in.m_n = 2;
  in.beta = 0;
  EXPECT_EQ(gg::flank_tolerances(in).outside_scope.size(), 1u);  // b
}

TEST(Accuracy, GradeOutsideTheEditionIsAnError) {
  EXPECT_THROW(tolerances(100, 2, 20, 0), std::domain_error);
  EXPECT_THROW(tolerances(100, 2, 20, 12), std::domain_error);
  EXPECT_NO_THROW(tolerances(100, 2, 20, 12, gg::Iso1328Edition::iso1995));
  EXPECT_NO_THROW(tolerances(100, 2, 20, 0, gg::Iso1328Edition::iso1995));
  EXPECT_THROW(tolerances(100, 2, 20, 13, gg::Iso1328Edition::iso1995), std::domain_error);
  EXPECT_THROW(tolerances(0, 2, 20, 6), std::domain_error);
  EXPECT_THROW(tolerances(100, -1, 20, 6), std::domain_error);
  EXPECT_EQ(gg::min_grade(gg::Iso1328Edition::iso2013), 1);
  EXPECT_EQ(gg::max_grade(gg::Iso1328Edition::iso1995), 12);
}
