#pragma once
// Flank tolerances of cylindrical involute gears (accuracy grades).
//
// - ISO 1328-1:2013: flank tolerance classes A = 1..11, the formulas of clause 5.3 evaluated at the
//   gear's own reference diameter d, normal module m_n and face width b, rounded by 5.2.3.
// - ISO 1328-1:1995 (still cited on drawings in use): accuracy grades Q = 0..12; its tables give the
//   formulas of clause 6 evaluated at the geometric mean of the range of d, m_n and b the gear falls
//   in (ranges 5/20/50/125/... mm), rounded like the 2013 edition.
// - ISO 1328-2:1997: radial composite (two-flank) tolerances F_i'' and f_i'' (grades 4..12) and,
//   in its Annex B, runout F_r (grades 0..12); the 2013 edition of part 1 gives runout as
//   F_rT = 0.9 F_pT (its annex on runout).
//
// Inputs in mm (libgear), tolerances in micrometres as the standards print them. The single
// formulas take any class number so that they can be studied outside the range; the aggregate
// flank_tolerances() checks the range of the edition. Internal gears: pass magnitudes.

#include <string>
#include <vector>

namespace gearkit::gear {

enum class Iso1328Edition { iso2013, iso1995 };

/// "ISO 1328-1:2013" or "ISO 1328-1:1995".
const char* to_string(Iso1328Edition edition);

/// Rounding of ISO 1328-1:2013 5.2.3 (the 1995 tables follow the same rule), in µm: values above
/// 10 µm to the nearest whole µm, from 5 to 10 µm to the nearest 0.5 µm, below 5 µm to the nearest
/// 0.1 µm (halves away from zero). NaN stays NaN.
double round_iso1328(double value_um);

/// Step between neighbouring classes, (sqrt 2)^(A - 5) (ISO 1328-1:2013 5.2.2; the 1995 edition's
/// 2^(0.5 (Q - 5)) is the same factor).
double class_step_factor(int A);

// ---- ISO 1328-1:2013 clause 5.3, unrounded, µm (d, m_n, b in mm, > 0) ----

/// Single pitch tolerance, formula (5): f_pT = (0.001 d + 0.4 m_n + 5) (sqrt 2)^(A - 5).
double single_pitch_tolerance(double d, double m_n, int A);

/// Total cumulative pitch tolerance, formula (6):
/// F_pT = (0.002 d + 0.55 sqrt(d) + 0.7 m_n + 12) (sqrt 2)^(A - 5).
double total_cumulative_pitch_tolerance(double d, double m_n, int A);

/// Profile slope tolerance (+-), formula (7): f_HalphaT = (0.4 m_n + 0.001 d + 4) (sqrt 2)^(A - 5).
double profile_slope_tolerance(double d, double m_n, int A);

/// Profile form tolerance, formula (8): f_falphaT = (0.55 m_n + 5) (sqrt 2)^(A - 5).
double profile_form_tolerance(double m_n, int A);

/// Total profile tolerance, formula (9): F_alphaT = sqrt(f_HalphaT^2 + f_falphaT^2), from the
/// unrounded components.
double total_profile_tolerance(double d, double m_n, int A);

/// Helix slope tolerance (+-), formula (10): f_HbetaT = (0.05 sqrt(d) + 0.35 sqrt(b) + 4) (sqrt 2)^(A - 5).
double helix_slope_tolerance(double d, double b, int A);

/// Helix form tolerance, formula (11): f_fbetaT = (0.07 sqrt(d) + 0.45 sqrt(b) + 4) (sqrt 2)^(A - 5).
double helix_form_tolerance(double d, double b, int A);

/// Total helix tolerance, formula (12): F_betaT = sqrt(f_HbetaT^2 + f_fbetaT^2), unrounded components.
double total_helix_tolerance(double d, double b, int A);

/// Runout tolerance of the 2013 edition: F_rT = 0.9 F_pT (unrounded F_pT).
double runout_tolerance(double d, double m_n, int A);

// ---- ISO 1328-1:1995 clause 6 and ISO 1328-2:1997, unrounded, µm ----
// d, m_n, b are the geometric means of the tabulated ranges (iso1328_1995_range_mean), Q the grade.

/// Geometric mean sqrt(lo hi) of the range (lo, hi] of `limits` that holds `value` (the first range
/// includes its lower limit), as the 1995 tables are built. Values outside the table are clamped to
/// its first or last range. `limits` ascending, at least two entries.
double iso1328_1995_range_mean(double value, const std::vector<double>& limits);

/// Range limits of the 1995 tables, mm: reference diameter (5 .. 10000), normal module (0.5 .. 70)
/// and face width (4 .. 1000) of ISO 1328-1:1995; module (0.2 .. 10) and diameter (5 .. 1000) of
/// the radial composite tables of ISO 1328-2:1997.
const std::vector<double>& iso1328_1995_diameter_limits();
const std::vector<double>& iso1328_1995_module_limits();
const std::vector<double>& iso1328_1995_face_width_limits();
const std::vector<double>& iso1328_2_1997_module_limits();
const std::vector<double>& iso1328_2_1997_diameter_limits();

/// f_pt = (0.3 (m + 0.4 sqrt(d)) + 4) 2^(0.5 (Q - 5)).
double single_pitch_tolerance_1995(double d, double m_n, int Q);
/// F_p = (0.3 m + 1.25 sqrt(d) + 7) 2^(0.5 (Q - 5)).
double total_cumulative_pitch_tolerance_1995(double d, double m_n, int Q);
/// F_alpha = (3.2 sqrt(m) + 0.22 sqrt(d) + 0.7) 2^(0.5 (Q - 5)).
double total_profile_tolerance_1995(double d, double m_n, int Q);
/// f_falpha = (2.5 sqrt(m) + 0.17 sqrt(d) + 0.5) 2^(0.5 (Q - 5)) (Annex B).
double profile_form_tolerance_1995(double d, double m_n, int Q);
/// f_Halpha = (2 sqrt(m) + 0.14 sqrt(d) + 0.5) 2^(0.5 (Q - 5)) (Annex B).
double profile_slope_tolerance_1995(double d, double m_n, int Q);
/// F_beta = (0.1 sqrt(d) + 0.63 sqrt(b) + 4.2) 2^(0.5 (Q - 5)).
double total_helix_tolerance_1995(double d, double b, int Q);
/// f_fbeta = f_Hbeta = (0.07 sqrt(d) + 0.45 sqrt(b) + 3) 2^(0.5 (Q - 5)) (Annex B).
double helix_form_tolerance_1995(double d, double b, int Q);
/// Runout, ISO 1328-2:1997 Annex B: F_r = 0.8 F_p = (0.24 m + 1.0 sqrt(d) + 5.6) 2^(0.5 (Q - 5)).
double runout_tolerance_1997(double d, double m_n, int Q);
/// Total radial composite tolerance, ISO 1328-2:1997: F_i'' = (3.2 m + 1.01 sqrt(d) + 6.4) 2^(0.5 (Q - 5)).
double total_radial_composite_tolerance_1997(double d, double m_n, int Q);
/// Tooth-to-tooth radial composite tolerance, ISO 1328-2:1997: f_i'' = (2.96 m + 0.01 sqrt(d) + 0.8) 2^(0.5 (Q - 5)).
double tooth_to_tooth_radial_composite_tolerance_1997(double d, double m_n, int Q);

// ---- one gear, all tolerances ----

struct ToleranceInput {
  double d = 0;       ///< reference diameter magnitude, mm
  double m_n = 0;     ///< normal module, mm
  double b = 0;       ///< face width, mm; 0: no helix tolerances (NaN)
  int z = 0;          ///< number of teeth (magnitude); 0: not checked against the scope
  double beta = 0;    ///< helix angle, rad (scope check only)
  int grade = 0;      ///< class A (2013, 1..11) or grade Q (1995, 0..12)
  Iso1328Edition edition = Iso1328Edition::iso2013;
};

/// Rounded tolerances of one gear, µm. NaN where the edition defines none for the input: helix
/// tolerances without a face width, radial composite tolerances outside ISO 1328-2:1997 (grades
/// 4..12, m_n 0.2..10 mm, d 5..1000 mm).
struct FlankTolerances {
  Iso1328Edition edition = Iso1328Edition::iso2013;
  int grade = 0;
  double f_pT = 0, F_pT = 0;                    ///< single pitch, total cumulative pitch
  double f_HalphaT = 0, f_falphaT = 0, F_alphaT = 0;  ///< profile slope, form, total
  double f_HbetaT = 0, f_fbetaT = 0, F_betaT = 0;     ///< helix slope, form, total
  double F_rT = 0;                              ///< runout
  double F_idT = 0, f_idT = 0;                  ///< radial composite total and tooth-to-tooth (ISO 1328-2:1997)
  /// Where the gear lies outside the edition's range of application: one sentence each. ISO
  /// 1328-1:2013 forbids extrapolation (values then computed anyway, to be agreed between the
  /// parties); the 1995 values come from the nearest tabulated range.
  std::vector<std::string> outside_scope;
};

/// Smallest and largest grade of an edition: 1..11 (2013), 0..12 (1995).
int min_grade(Iso1328Edition edition);
int max_grade(Iso1328Edition edition);

/// All tolerances of one gear. @throws std::domain_error if d or m_n is not > 0, b < 0, or the
/// grade is outside the edition's range.
FlankTolerances flank_tolerances(const ToleranceInput& input);

}  // namespace gearkit::gear
