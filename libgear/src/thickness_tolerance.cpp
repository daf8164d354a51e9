#include <gearkit/gear/thickness_tolerance.hpp>

#include <gearkit/gear/iso286.hpp>

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace gearkit::gear {

double recommended_min_backlash(double a, double m_n) {
  return 2.0 / 3.0 * (0.06 + 0.0005 * std::fabs(a) + 0.03 * m_n);
}

double radial_infeed_tolerance(int grade, double d) {
  // Odd grades are whole IT grades (5: IT8, 7: IT9, 9: IT10), even grades 1.26 = sqrt(1.6) times
  // the IT grade below (4: 1.26 IT7, 6: 1.26 IT8, 8: 1.26 IT9): one IT grade every two grades.
  if (grade < 0 || grade > 12) {
    throw std::domain_error(fmt::format("radial infeed tolerance: defined for accuracy grades 0..12, found {}", grade));
  }
  // Grade 0 (ISO 1328-1:1995) continues the rule downwards: one 1.26 step finer than grade 1 (IT6).
  if (grade == 0) return standard_tolerance(6, std::fabs(d)) / 1.26;
  if (grade % 2 != 0) return standard_tolerance((grade + 11) / 2, std::fabs(d));
  return 1.26 * standard_tolerance(grade / 2 + 5, std::fabs(d));
}

double tooth_thickness_tolerance(double F_r, double b_r, double alpha_n) {
  return 2.0 * std::tan(alpha_n) * std::hypot(F_r, b_r);
}

ThicknessAllowances measurement_allowances(const ThicknessAllowances& allowances, double F_r, double alpha_n) {
  const double runout_term = 0.72 * F_r * std::tan(alpha_n);
  return {allowances.A_sne - runout_term, allowances.A_sni + runout_term};
}

double span_allowance(double A_sn, double alpha_n) { return A_sn * std::cos(alpha_n); }

}  // namespace gearkit::gear
