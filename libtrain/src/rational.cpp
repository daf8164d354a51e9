#include <gearkit/train/rational.hpp>

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace gearkit::train {

std::string to_fraction_string(const Rational& r) {
  const Integer num = boost::multiprecision::numerator(r);
  const Integer den = boost::multiprecision::denominator(r);
  if (den == 1) return num.str();
  return num.str() + "/" + den.str();
}

Rational make_rational(const Integer& num, const Integer& den) {
  if (den == 0) throw std::invalid_argument("make_rational: zero denominator");
  return den < 0 ? Rational(Integer(-num), Integer(-den)) : Rational(num, den);
}

double to_double(const Rational& r) { return r.convert_to<double>(); }

std::string to_fraction_and_decimal(const Rational& r, int digits) {
  const std::string fraction = to_fraction_string(r);
  if (boost::multiprecision::denominator(r) == 1) return fraction;
  const double value = to_double(r);
  const std::string decimal = std::fabs(value) < 1e6 && std::fabs(value) >= 1e-4
                                  ? fmt::format("{:.{}f}", value, digits)
                                  : fmt::format("{:.{}e}", value, digits);
  return fraction + " = " + decimal;
}

Rational rational_from_double(double value, double tolerance) {
  if (!std::isfinite(value)) throw std::invalid_argument("rational_from_double: value is not finite");
  if (!(tolerance > 0)) throw std::invalid_argument("rational_from_double: tolerance must be positive");
  // Continued-fraction convergents h/k of |value|; stop at the first within tolerance.
  if (std::fabs(value) > 1e15) throw std::invalid_argument("rational_from_double: |value| above 1e15");
  const bool negative = value < 0;
  double x = std::fabs(value);
  Integer h_prev = 1, h = static_cast<long long>(std::floor(x));
  Integer k_prev = 0, k = 1;
  double frac = x - std::floor(x);
  for (int i = 0; i < 64; ++i) {
    const Rational candidate(h, k);
    if (std::fabs(to_double(candidate) - std::fabs(value)) <= tolerance || frac < 1e-300) break;
    x = 1.0 / frac;
    if (x > 1e15) break;  // the remainder is below double resolution
    const double a_floor = std::floor(x);
    frac = x - a_floor;
    const Integer a = static_cast<long long>(a_floor);
    const Integer h_next = a * h + h_prev;
    const Integer k_next = a * k + k_prev;
    h_prev = h;
    k_prev = k;
    h = h_next;
    k = k_next;
  }
  const Rational result(h, k);
  return negative ? Rational(-result) : result;
}

}  // namespace gearkit::train
