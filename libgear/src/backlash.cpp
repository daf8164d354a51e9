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

Backlash backlash_at(const BacklashInput& in) {
  const double j_t = circumferential_backlash(in);
  return {j_t, normal_backlash(j_t, working_pressure_angle_at(in), in.beta_b)};
}

BacklashInput at_temperature(const BacklashInput& in, double growth1, double growth2, double growth_housing) {
  BacklashInput out = in;
  const double k1 = 1.0 + growth1, k2 = 1.0 + growth2;
  out.d1 *= k1;
  out.d_b1 *= k1;
  out.s_t1 *= k1;
  out.d2 *= k2;
  out.d_b2 *= k2;
  out.s_t2 *= k2;
  out.a *= 1.0 + growth_housing;
  return out;
}

BacklashInput with_centre_distance_deviation(BacklashInput in, double A_a) {
  in.a += in.a < 0.0 ? -A_a : A_a;
  return in;
}

BacklashRange backlash_range(const BacklashInput& nominal, double beta, const PairLimits& l) {
  const double cos_beta = std::cos(beta);
  auto state = [&](double A_sn1, double A_sn2, double A_a) {
    BacklashInput in = nominal;
    in.s_t1 += A_sn1 / cos_beta;
    in.s_t2 += A_sn2 / cos_beta;
    return backlash_at(with_centre_distance_deviation(in, A_a));
  };
  const Backlash tight_e = state(l.A_sne1, l.A_sne2, l.A_ae), tight_i = state(l.A_sne1, l.A_sne2, l.A_ai);
  const Backlash loose_e = state(l.A_sni1, l.A_sni2, l.A_ae), loose_i = state(l.A_sni1, l.A_sni2, l.A_ai);
  BacklashRange r;
  r.min = tight_e.j_n <= tight_i.j_n ? tight_e : tight_i;
  r.max = loose_e.j_n >= loose_i.j_n ? loose_e : loose_i;
  return r;
}

}  // namespace gearkit::gear
