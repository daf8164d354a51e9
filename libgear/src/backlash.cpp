#include <gearkit/gear/backlash.hpp>
#include <gearkit/gear/involute.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gearkit::gear {

double working_pressure_angle_at(const BacklashInput& in) {
  const double c = (in.d_b1 + in.d_b2) / (2.0 * in.a);
  if (!(c > 0.0 && c <= 1.0)) {
    throw std::domain_error("backlash: the base circles do not fit the centre distance");
  }
  return std::acos(c);
}

double circumferential_backlash(const BacklashInput& in) {
  const double alpha_w = working_pressure_angle_at(in);
  const double zs = in.z1 + in.z2;
  const double d_w1 = 2.0 * in.a * in.z1 / zs;
  const double d_w2 = 2.0 * in.a * in.z2 / zs;
  const double inv_t = involute(in.alpha_t);
  const double inv_w = involute(alpha_w);
  const double s_w1 = d_w1 * (in.s_t1 / in.d1 + inv_t - inv_w);
  const double s_w2 = d_w2 * (in.s_t2 / in.d2 + inv_t - inv_w);
  const double p_w = std::numbers::pi * d_w1 / in.z1;
  return p_w - s_w1 - s_w2;
}

double normal_backlash(double j_wt, double alpha_wt, double beta_b) {
  return j_wt * std::cos(alpha_wt) * std::cos(beta_b);
}

double allowance_for_backlash(const BacklashInput& in, double alpha_n, double j_bn_target) {
  const double j0 = normal_backlash(circumferential_backlash(in), working_pressure_angle_at(in), in.beta_b);
  return -(j_bn_target - j0) / (2.0 * std::cos(alpha_n));
}

}  // namespace gearkit::gear
