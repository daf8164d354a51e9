#include "symbolic_system.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <sstream>

namespace gearkit::sym {

using GiNaC::ex;

GiNaC::exmap SymbolicSystem::values(const CoordinateState& state) const {
  GiNaC::exmap m;
  for (std::size_t k = 0; k < params.size(); ++k) m[params[k]] = param_values[k];
  for (std::size_t k = 0; k < q.size(); ++k) {
    m[q[k]] = state.q[static_cast<Eigen::Index>(k)];
    m[qd[k]] = state.qd.size() > 0 ? state.qd[static_cast<Eigen::Index>(k)] : 0.0;
  }
  return m;
}

namespace detail {

std::string tex_name(const std::string& name) {
  static const std::array<const char*, 20> greek = {"alpha", "beta",  "gamma", "delta", "epsilon", "theta", "lambda",
                                                    "mu",    "rho",   "sigma", "tau",   "phi",     "psi",   "omega",
                                                    "eta",   "kappa", "nu",    "xi",    "zeta",    "chi"};
  std::size_t cut = name.size();
  while (cut > 0 && std::isdigit(static_cast<unsigned char>(name[cut - 1]))) --cut;
  std::string base = name.substr(0, cut), index = name.substr(cut);
  for (const char* g : greek)
    if (base == g) base = base == "phi" ? "\\varphi" : "\\" + base;
  return index.empty() ? base : base + "_{" + index + "}";
}

Expression print(const GiNaC::ex& e) {
  std::ostringstream text, latex;
  text << e;
  latex << GiNaC::latex << e;
  return {text.str(), latex.str()};
}

Expression print_fraction(const GiNaC::ex& num, const GiNaC::ex& den) {
  if (den.is_equal(1)) return print(num);
  // A negative numeric factor of the numerator goes in front of the fraction.
  ex n = num;
  bool negative = false;
  const ex lead = GiNaC::is_a<GiNaC::mul>(num) ? num.op(num.nops() - 1) : num;
  if (GiNaC::is_a<GiNaC::numeric>(lead) && GiNaC::ex_to<GiNaC::numeric>(lead).is_negative()) {
    negative = true;
    n = -num;
  }
  const Expression a = print(n), b = print(den);
  const std::string sign = negative ? "-" : "";
  return {sign + "(" + a.text + ")/(" + b.text + ")", sign + "\\frac{" + a.latex + "}{" + b.latex + "}"};
}

GiNaC::ex number(double x) {
  const double r = std::round(x);
  if (std::abs(x - r) <= 1e-9 * std::max(1.0, std::abs(x))) return GiNaC::numeric(static_cast<long>(r));
  return GiNaC::numeric(x);
}

}  // namespace detail
}  // namespace gearkit::sym
