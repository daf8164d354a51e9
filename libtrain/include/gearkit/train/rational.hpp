#pragma once
// Exact arithmetic for gear trains. Speeds, ratios and ideal torques of a train are rational
// multiples of its inputs (tooth counts are integers), so the core computes with arbitrary
// precision rationals (Boost.Multiprecision on GMP's mpq_t): no overflow can happen at all; a
// 100-stage train whose ratio has a 90-digit denominator is still exact. GMP rather than
// cpp_rational because a chain of stages multiplies small fractions into large ones, where GMP's
// gcd is some 15 times faster.
// Construct fractions with make_rational() when the denominator may be negative: Boost 1.74's
// two-argument constructors mishandle a negative denominator.
#include <boost/multiprecision/gmp.hpp>
#include <string>

namespace gearkit::train {

using Rational = boost::multiprecision::mpq_rational;
using Integer = boost::multiprecision::mpz_int;

/// "47/72", "-3", "0" (reduced, sign on the numerator).
std::string to_fraction_string(const Rational& r);

/// num/den with the sign moved to the numerator. @throws std::invalid_argument if den == 0.
Rational make_rational(const Integer& num, const Integer& den);

/// The nearest double (for printing and for inputs that are physical measurements).
double to_double(const Rational& r);

/// "47/72 = 0.652778": the fraction and its decimal with `digits` significant figures after the
/// point (fixed notation below 1e6 in magnitude, scientific above). An integer prints alone ("1").
std::string to_fraction_and_decimal(const Rational& r, int digits = 6);

/// The simplest fraction within `tolerance` of `value` (continued fractions). Used to turn a
/// decimal input such as an efficiency 0.98 into 49/50 so that the rest stays exact.
/// @throws std::invalid_argument if `value` is not finite or tolerance <= 0.
Rational rational_from_double(double value, double tolerance = 1e-12);

}  // namespace gearkit::train
