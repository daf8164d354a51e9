#pragma once
// The GiNaC side of Equations: the symbols and expressions the strings were printed from, kept
// so that evaluate() substitutes numbers without parsing text again.
#include <gearkit/sym/loop_equations.hpp>

#include <ginac/ginac.h>

#include <vector>

namespace gearkit::sym {

class SymbolicSystem {
 public:
  std::vector<GiNaC::symbol> q, qd, qdd;  ///< per coordinate: value, rate, second rate
  std::vector<GiNaC::symbol> params;      ///< dimension symbols
  std::vector<double> param_values;       ///< mm or rad
  std::vector<GiNaC::ex> phi, gamma, ratios;
  std::vector<std::vector<GiNaC::ex>> phi_q;

  /// Substitutions: every parameter, and q, qd of `state` (qdd is not needed by any of the
  /// expressions kept).
  GiNaC::exmap values(const CoordinateState& state) const;
};

namespace detail {

/// The LaTeX name of a symbol: phi1 -> \varphi_{1}, alpha -> \alpha, l3 -> l_{3}, h1 -> h_{1}.
std::string tex_name(const std::string& name);

/// e as GiNaC reads it back, and as LaTeX.
Expression print(const GiNaC::ex& e);

/// num/den printed as a fraction: "-(l1*sin(phi1))/(l3*sin(phi2))", "-\\frac{...}{...}".
Expression print_fraction(const GiNaC::ex& num, const GiNaC::ex& den);

/// A length or coordinate offset as an exact integer when it is one (150, not 150.0).
GiNaC::ex number(double x);

}  // namespace detail
}  // namespace gearkit::sym
