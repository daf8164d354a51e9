#include <gearkit/gear/involute.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace gearkit::gear {

namespace {

// Taylor series of tan(a) - a; relative truncation error < 1e-16 for |a| < 0.05.
double involute_series(double a) {
  const double a2 = a * a;
  return a * a2 *
         (1.0 / 3.0 + a2 * (2.0 / 15.0 + a2 * (17.0 / 315.0 + a2 * (62.0 / 2835.0 + a2 * (1382.0 / 155925.0)))));
}

// One Halley step for f(a) = inv(a) - y, f' = tan^2 a, f'' = 2 tan a (1 + tan^2 a).
double halley_step(double a, double y) {
  const double t = std::tan(a);
  const double f = (a < 0.05 ? involute_series(a) : t - a) - y;
  const double t2 = t * t;
  const double f1 = t2;
  const double f2 = 2.0 * t * (1.0 + t2);
  return a - 2.0 * f * f1 / (2.0 * f1 * f1 - f * f2);
}

// Cube root of v > 0 without libm's cbrt: a bit-level first guess (exponent divided by three,
// error < 5 %), then two Halley steps u (u^3 + 2v) / (2u^3 + v), each cubing the relative error
// (5e-2 -> 1e-4 -> 1e-12 or better; the Halley step on alpha that follows removes the rest).
double cube_root(double v) {
  std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
  bits = bits / 3 + 0x2A9F7893782DA1CEull;
  double u = std::bit_cast<double>(bits);
  for (int i = 0; i < 2; ++i) {
    const double u3 = u * u * u;
    u = u * (u3 + 2.0 * v) / (2.0 * u3 + v);
  }
  return u;
}

}  // namespace

double involute(double alpha) {
  if (std::fabs(alpha) < 0.05) return involute_series(alpha);
  return std::tan(alpha) - alpha;
}

double inverse_involute(double inv) {
  if (!(inv >= 0.0) || !std::isfinite(inv)) {
    throw std::domain_error("inverse_involute: expected a finite value >= 0, found " + std::to_string(inv));
  }
  if (inv == 0.0) return 0.0;
  // inv(1.45 rad): the end of the range covered by the rational fit.
  constexpr double kFitEnd = 6.7885;
  if (inv <= kFitEnd) {
    // alpha = u P(s) / Q(s), u = cbrt(3 inv), s = u^2: least-squares fit of the exact inverse
    // over 0 < alpha <= 1.45 rad (relative error < 3e-7), exact to first order at 0
    // (alpha ~ (3 inv)^(1/3)). One Halley step then cubes the error away.
    const double u = cube_root(3.0 * inv);
    const double s = u * u;
    const double p = 1.0000000064855166 + s * (0.26494539795875027 + s * (0.038988459619100704 + s * 0.001148357976203855));
    const double q = 1.0 + s * (0.39827894434946004 + s * (0.074948298456924495 + s * (0.0055861904101545783 + s * 4.2006961189594203e-05)));
    const double a0 = u * p / q;
    return halley_step(a0, inv);
  }
  // Near pi/2: alpha = atan(inv + alpha) is a contraction with factor cos^2(alpha) < 0.015.
  double a = std::atan(inv + 1.5);
  a = std::atan(inv + a);
  a = halley_step(a, inv);
  return halley_step(a, inv);
}

double pressure_angle_at(double d_b, double d_y) {
  const double c = d_b / d_y;
  if (!(c > 0.0) || c > 1.0) {
    throw std::domain_error("pressure_angle_at: diameter " + std::to_string(d_y) +
                            " lies inside the base circle of diameter " + std::to_string(d_b));
  }
  return std::acos(c);
}

}  // namespace gearkit::gear
