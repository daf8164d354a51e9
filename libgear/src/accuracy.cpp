#include <gearkit/gear/accuracy.hpp>

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace gearkit::gear {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDeg = std::numbers::pi / 180.0;

double nearest(double value, double step) { return std::round(value / step) * step; }

}  // namespace

const char* to_string(Iso1328Edition edition) {
  return edition == Iso1328Edition::iso2013 ? "ISO 1328-1:2013" : "ISO 1328-1:1995";
}

double round_iso1328(double value_um) {
  if (!std::isfinite(value_um)) return value_um;
  const double v = std::fabs(value_um);
  const double r = v > 10.0 ? nearest(v, 1.0) : v >= 5.0 ? nearest(v, 0.5) : nearest(v, 0.1);
  return std::copysign(r, value_um);
}

double class_step_factor(int A) { return std::pow(2.0, 0.5 * (A - 5)); }

double single_pitch_tolerance(double d, double m_n, int A) {
  return (0.001 * d + 0.4 * m_n + 5.0) * class_step_factor(A);
}

double total_cumulative_pitch_tolerance(double d, double m_n, int A) {
  return (0.002 * d + 0.55 * std::sqrt(d) + 0.7 * m_n + 12.0) * class_step_factor(A);
}

double profile_slope_tolerance(double d, double m_n, int A) {
  return (0.4 * m_n + 0.001 * d + 4.0) * class_step_factor(A);
}

double profile_form_tolerance(double m_n, int A) { return (0.55 * m_n + 5.0) * class_step_factor(A); }

double total_profile_tolerance(double d, double m_n, int A) {
  return std::hypot(profile_slope_tolerance(d, m_n, A), profile_form_tolerance(m_n, A));
}

double helix_slope_tolerance(double d, double b, int A) {
  return (0.05 * std::sqrt(d) + 0.35 * std::sqrt(b) + 4.0) * class_step_factor(A);
}

double helix_form_tolerance(double d, double b, int A) {
  return (0.07 * std::sqrt(d) + 0.45 * std::sqrt(b) + 4.0) * class_step_factor(A);
}

double total_helix_tolerance(double d, double b, int A) {
  return std::hypot(helix_slope_tolerance(d, b, A), helix_form_tolerance(d, b, A));
}

double runout_tolerance(double d, double m_n, int A) { return 0.9 * total_cumulative_pitch_tolerance(d, m_n, A); }

// ---- 1995 / 1997 ----

double iso1328_1995_range_mean(double value, const std::vector<double>& limits) {
  if (limits.size() < 2) throw std::invalid_argument("iso1328_1995_range_mean: at least two limits needed");
  std::size_t i = 1;
  while (i + 1 < limits.size() && value > limits[i]) ++i;
  return std::sqrt(limits[i - 1] * limits[i]);
}

const std::vector<double>& iso1328_1995_diameter_limits() {
  static const std::vector<double> v{5, 20, 50, 125, 280, 560, 1000, 1600, 2500, 4000, 6000, 8000, 10000};
  return v;
}

const std::vector<double>& iso1328_1995_module_limits() {
  static const std::vector<double> v{0.5, 2, 3.5, 6, 10, 16, 25, 40, 70};
  return v;
}

const std::vector<double>& iso1328_1995_face_width_limits() {
  static const std::vector<double> v{4, 10, 20, 40, 80, 160, 250, 400, 650, 1000};
  return v;
}

const std::vector<double>& iso1328_2_1997_module_limits() {
  static const std::vector<double> v{0.2, 0.5, 0.8, 1.0, 1.5, 2.5, 4.0, 6.0, 10.0};
  return v;
}

const std::vector<double>& iso1328_2_1997_diameter_limits() {
  static const std::vector<double> v{5, 20, 50, 125, 280, 560, 1000};
  return v;
}

double single_pitch_tolerance_1995(double d, double m_n, int Q) {
  return (0.3 * (m_n + 0.4 * std::sqrt(d)) + 4.0) * class_step_factor(Q);
}

double total_cumulative_pitch_tolerance_1995(double d, double m_n, int Q) {
  return (0.3 * m_n + 1.25 * std::sqrt(d) + 7.0) * class_step_factor(Q);
}

double total_profile_tolerance_1995(double d, double m_n, int Q) {
  return (3.2 * std::sqrt(m_n) + 0.22 * std::sqrt(d) + 0.7) * class_step_factor(Q);
}

double profile_form_tolerance_1995(double d, double m_n, int Q) {
  return (2.5 * std::sqrt(m_n) + 0.17 * std::sqrt(d) + 0.5) * class_step_factor(Q);
}

double profile_slope_tolerance_1995(double d, double m_n, int Q) {
  return (2.0 * std::sqrt(m_n) + 0.14 * std::sqrt(d) + 0.5) * class_step_factor(Q);
}

double total_helix_tolerance_1995(double d, double b, int Q) {
  return (0.1 * std::sqrt(d) + 0.63 * std::sqrt(b) + 4.2) * class_step_factor(Q);
}

double helix_form_tolerance_1995(double d, double b, int Q) {
  return (0.07 * std::sqrt(d) + 0.45 * std::sqrt(b) + 3.0) * class_step_factor(Q);
}

double runout_tolerance_1997(double d, double m_n, int Q) {
  return (0.24 * m_n + 1.0 * std::sqrt(d) + 5.6) * class_step_factor(Q);
}

double total_radial_composite_tolerance_1997(double d, double m_n, int Q) {
  return (3.2 * m_n + 1.01 * std::sqrt(d) + 6.4) * class_step_factor(Q);
}

double tooth_to_tooth_radial_composite_tolerance_1997(double d, double m_n, int Q) {
  return (2.96 * m_n + 0.01 * std::sqrt(d) + 0.8) * class_step_factor(Q);
}

// ---- aggregate ----

int min_grade(Iso1328Edition edition) { return edition == Iso1328Edition::iso2013 ? 1 : 0; }
int max_grade(Iso1328Edition edition) { return edition == Iso1328Edition::iso2013 ? 11 : 12; }

namespace {

void check_range(std::vector<std::string>& notes, const char* what, double value, double lo, double hi,
                 const char* unit) {
  if (value < lo || value > hi) {
    notes.push_back(fmt::format("{} = {:g}{} outside {:g}..{:g}{}", what, value, unit, lo, hi, unit));
  }
}

void tolerances_2013(const ToleranceInput& in, FlankTolerances& t) {
  const int A = in.grade;
  t.f_pT = round_iso1328(single_pitch_tolerance(in.d, in.m_n, A));
  t.F_pT = round_iso1328(total_cumulative_pitch_tolerance(in.d, in.m_n, A));
  t.f_HalphaT = round_iso1328(profile_slope_tolerance(in.d, in.m_n, A));
  t.f_falphaT = round_iso1328(profile_form_tolerance(in.m_n, A));
  t.F_alphaT = round_iso1328(total_profile_tolerance(in.d, in.m_n, A));
  if (in.b > 0.0) {
    t.f_HbetaT = round_iso1328(helix_slope_tolerance(in.d, in.b, A));
    t.f_fbetaT = round_iso1328(helix_form_tolerance(in.d, in.b, A));
    t.F_betaT = round_iso1328(total_helix_tolerance(in.d, in.b, A));
  }
  t.F_rT = round_iso1328(runout_tolerance(in.d, in.m_n, A));
  // Clause 1: 5 <= z <= 1000, 5 <= d <= 15000 mm, 0.5 <= m_n <= 70 mm, 4 <= b <= 1200 mm, beta <= 45 deg.
  if (in.z > 0) check_range(t.outside_scope, "z", in.z, 5, 1000, "");
  check_range(t.outside_scope, "d", in.d, 5, 15000, " mm");
  check_range(t.outside_scope, "m_n", in.m_n, 0.5, 70, " mm");
  if (in.b > 0.0) check_range(t.outside_scope, "b", in.b, 4, 1200, " mm");
  check_range(t.outside_scope, "beta", std::fabs(in.beta) / kDeg, 0, 45, " deg");
}

void tolerances_1995(const ToleranceInput& in, FlankTolerances& t) {
  const int Q = in.grade;
  const double d = iso1328_1995_range_mean(in.d, iso1328_1995_diameter_limits());
  const double m = iso1328_1995_range_mean(in.m_n, iso1328_1995_module_limits());
  t.f_pT = round_iso1328(single_pitch_tolerance_1995(d, m, Q));
  t.F_pT = round_iso1328(total_cumulative_pitch_tolerance_1995(d, m, Q));
  t.f_HalphaT = round_iso1328(profile_slope_tolerance_1995(d, m, Q));
  t.f_falphaT = round_iso1328(profile_form_tolerance_1995(d, m, Q));
  t.F_alphaT = round_iso1328(total_profile_tolerance_1995(d, m, Q));
  if (in.b > 0.0) {
    const double b = iso1328_1995_range_mean(in.b, iso1328_1995_face_width_limits());
    t.f_HbetaT = round_iso1328(helix_form_tolerance_1995(d, b, Q));
    t.f_fbetaT = t.f_HbetaT;
    t.F_betaT = round_iso1328(total_helix_tolerance_1995(d, b, Q));
  }
  t.F_rT = round_iso1328(runout_tolerance_1997(d, m, Q));
  check_range(t.outside_scope, "d", in.d, 5, 10000, " mm");
  check_range(t.outside_scope, "m_n", in.m_n, 0.5, 70, " mm");
  if (in.b > 0.0) check_range(t.outside_scope, "b", in.b, 4, 1000, " mm");
}

// ISO 1328-2:1997 covers grades 4..12, 0.2 <= m_n <= 10 mm, 5 <= d <= 1000 mm; no values elsewhere.
void radial_composite_1997(const ToleranceInput& in, FlankTolerances& t) {
  const bool covered = in.grade >= 4 && in.grade <= 12 && in.m_n >= 0.2 && in.m_n <= 10.0 && in.d >= 5.0 &&
                       in.d <= 1000.0;
  if (!covered) {
    t.F_idT = t.f_idT = kNaN;
    return;
  }
  const double d = iso1328_1995_range_mean(in.d, iso1328_2_1997_diameter_limits());
  const double m = iso1328_1995_range_mean(in.m_n, iso1328_2_1997_module_limits());
  t.F_idT = round_iso1328(total_radial_composite_tolerance_1997(d, m, in.grade));
  t.f_idT = round_iso1328(tooth_to_tooth_radial_composite_tolerance_1997(d, m, in.grade));
}

}  // namespace

FlankTolerances flank_tolerances(const ToleranceInput& in) {
  if (!(in.d > 0.0) || !(in.m_n > 0.0) || !(in.b >= 0.0)) {
    throw std::domain_error("flank tolerances: expected d > 0, m_n > 0 and b >= 0");
  }
  if (in.grade < min_grade(in.edition) || in.grade > max_grade(in.edition)) {
    throw std::domain_error(fmt::format("flank tolerances: {} defines grades {}..{}, found {}", to_string(in.edition),
                                        min_grade(in.edition), max_grade(in.edition), in.grade));
  }
  FlankTolerances t;
  t.edition = in.edition;
  t.grade = in.grade;
  t.f_HbetaT = t.f_fbetaT = t.F_betaT = kNaN;
  if (in.edition == Iso1328Edition::iso2013) {
    tolerances_2013(in, t);
  } else {
    tolerances_1995(in, t);
  }
  radial_composite_1997(in, t);
  return t;
}

}  // namespace gearkit::gear
