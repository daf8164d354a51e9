#pragma once
// Trigonometric rewriting on GiNaC expressions (GiNaC itself does not combine products of sines
// and cosines): the two identities a course uses to shorten velocity ratios, and their inverse
// for comparing formulas.
#include <ginac/ginac.h>

namespace gearkit::sym::detail {

/// Pairs terms c sin(x) cos(y) +- c cos(x) sin(y) into c sin(x +- y) and c cos(x) cos(y) -+
/// c sin(x) sin(y) into c cos(x +- y), repeatedly, on the expanded expression.
GiNaC::ex combine_trig(const GiNaC::ex& e);

/// Expands sin and cos of sums and of negated arguments into products of sin and cos of the
/// single terms.
GiNaC::ex expand_trig(const GiNaC::ex& e);

/// A ratio as num/den with common factors cancelled, each trig-combined, and the sign on the
/// numerator.
struct Fraction {
  GiNaC::ex num, den;
};
Fraction simplify_ratio(const GiNaC::ex& e);

}  // namespace gearkit::sym::detail
