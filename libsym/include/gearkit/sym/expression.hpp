#pragma once
// Comparing formulas the way a teacher does: two expressions are the same if their difference
// vanishes once sines and cosines of sums are expanded (sin(a + b) = sin a cos b + cos a sin b)
// and the result is brought to a normal rational form. Used to check the generated equations
// against the ones a course writes, term by term.
#include <string>

namespace gearkit::sym {

/// True if `a` and `b` (GiNaC syntax: "-l1*cos(phi1)+d", "sin(phi2-phi1)") are equal as
/// functions of their symbols after trigonometric expansion and rational normalisation.
/// @throws std::invalid_argument if either does not parse.
bool equivalent(const std::string& a, const std::string& b);

/// True if a = b or a = -b in the sense of equivalent(): two rows of Phi(q) = 0 that differ
/// only in sign are the same equation.
bool equivalent_up_to_sign(const std::string& a, const std::string& b);

}  // namespace gearkit::sym
