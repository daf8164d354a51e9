#include "trig.hpp"

#include <algorithm>
#include <optional>
#include <vector>

namespace gearkit::sym::detail {

using GiNaC::ex;

namespace {

struct TrigFactor {
  bool is_sin = false;
  ex arg;
};

// One term of a sum as coefficient times its first-power sines and cosines.
struct TrigTerm {
  ex coeff = 1;
  std::vector<TrigFactor> trig;
  ex rebuild() const {
    ex r = coeff;
    for (const auto& f : trig) r *= f.is_sin ? GiNaC::sin(f.arg) : GiNaC::cos(f.arg);
    return r;
  }
};

TrigTerm split_term(const ex& t) {
  TrigTerm r;
  auto take = [&r](const ex& f) {
    if (GiNaC::is_the_function<GiNaC::sin_SERIAL>(f)) r.trig.push_back({true, f.op(0)});
    else if (GiNaC::is_the_function<GiNaC::cos_SERIAL>(f)) r.trig.push_back({false, f.op(0)});
    else r.coeff *= f;
  };
  if (GiNaC::is_a<GiNaC::mul>(t))
    for (std::size_t i = 0; i < t.nops(); ++i) take(t.op(i));
  else
    take(t);
  return r;
}

bool normalises_to_zero(const ex& e) { return e.expand().normal().is_zero(); }

bool same_factor(const TrigFactor& f, const TrigFactor& g) { return f.is_sin == g.is_sin && f.arg.is_equal(g.arg); }

// Trig factors both terms share move into their coefficients: l4 sin(a) sin(x) cos(y) and
// l4 sin(a) cos(x) sin(y) pair like sin(x) cos(y) and cos(x) sin(y).
void strip_common(TrigTerm& a, TrigTerm& b) {
  for (std::size_t i = 0; i < a.trig.size();) {
    auto it = std::find_if(b.trig.begin(), b.trig.end(), [&](const TrigFactor& g) { return same_factor(a.trig[i], g); });
    if (it == b.trig.end()) {
      ++i;
      continue;
    }
    const ex f = a.trig[i].is_sin ? GiNaC::sin(a.trig[i].arg) : GiNaC::cos(a.trig[i].arg);
    a.coeff *= f;
    b.coeff *= f;
    b.trig.erase(it);
    a.trig.erase(a.trig.begin() + static_cast<std::ptrdiff_t>(i));
  }
}

// a = c f(x) g(y) and b = d h(x) k(y) (same two arguments): the single term they make, if any.
std::optional<ex> pair_terms(TrigTerm a, TrigTerm b) {
  strip_common(a, b);
  if (a.trig.size() != 2 || b.trig.size() != 2) return std::nullopt;
  const ex& x = a.trig[0].arg;
  const ex& y = a.trig[1].arg;
  if (x.is_equal(y)) return std::nullopt;
  if (b.trig[0].arg.is_equal(y) && b.trig[1].arg.is_equal(x)) std::swap(b.trig[0], b.trig[1]);
  if (!b.trig[0].arg.is_equal(x) || !b.trig[1].arg.is_equal(y)) return std::nullopt;
  const bool same = normalises_to_zero(a.coeff - b.coeff), opposite = normalises_to_zero(a.coeff + b.coeff);
  if (!same && !opposite) return std::nullopt;
  const ex& c = a.coeff;
  const bool as = a.trig[0].is_sin, at = a.trig[1].is_sin, bs = b.trig[0].is_sin, bt = b.trig[1].is_sin;
  if (as && !at && !bs && bt)  // c sin x cos y +- c cos x sin y
    return same ? c * GiNaC::sin(x + y) : c * GiNaC::sin(x - y);
  if (!as && at && bs && !bt)  // c cos x sin y +- c sin x cos y
    return same ? c * GiNaC::sin(x + y) : c * GiNaC::sin(y - x);
  if (!as && !at && bs && bt)  // c cos x cos y +- c sin x sin y
    return same ? c * GiNaC::cos(x - y) : c * GiNaC::cos(x + y);
  if (as && at && !bs && !bt)  // c sin x sin y +- c cos x cos y
    return same ? c * GiNaC::cos(x - y) : -c * GiNaC::cos(x + y);
  return std::nullopt;
}

// One pass over the terms; true if it combined a pair.
bool combine_once(ex& e) {
  const ex x = e.expand();
  if (!GiNaC::is_a<GiNaC::add>(x)) return false;
  std::vector<TrigTerm> terms;
  for (std::size_t i = 0; i < x.nops(); ++i) terms.push_back(split_term(x.op(i)));
  for (std::size_t i = 0; i < terms.size(); ++i)
    for (std::size_t j = i + 1; j < terms.size(); ++j)
      if (auto c = pair_terms(terms[i], terms[j])) {
        ex rest = *c;
        for (std::size_t k = 0; k < terms.size(); ++k)
          if (k != i && k != j) rest += terms[k].rebuild();
        e = rest;
        return true;
      }
  return false;
}

// sin and cos of a sum or of a negated argument, expanded one level at a time.
struct ExpandTrig : GiNaC::map_function {
  ex operator()(const ex& e) override {
    const bool s = GiNaC::is_the_function<GiNaC::sin_SERIAL>(e), c = GiNaC::is_the_function<GiNaC::cos_SERIAL>(e);
    if (!s && !c) return e.map(*this);
    const ex arg = e.op(0).expand();
    if (GiNaC::is_a<GiNaC::add>(arg)) {
      const ex u = arg.op(0), v = arg - arg.op(0);
      const ex su = (*this)(GiNaC::sin(u)), cu = (*this)(GiNaC::cos(u));
      const ex sv = (*this)(GiNaC::sin(v)), cv = (*this)(GiNaC::cos(v));
      return s ? su * cv + cu * sv : cu * cv - su * sv;
    }
    if (GiNaC::is_a<GiNaC::mul>(arg)) {
      const ex k = arg.op(arg.nops() - 1);
      if (GiNaC::is_a<GiNaC::numeric>(k) && GiNaC::ex_to<GiNaC::numeric>(k).is_negative())
        return s ? -(*this)(GiNaC::sin(-arg)) : (*this)(GiNaC::cos(-arg));
    }
    return e;
  }
};

}  // namespace

ex combine_trig(const ex& e) {
  ex r = e.expand();
  for (int pass = 0; pass < 64 && combine_once(r); ++pass) {
  }
  return r;
}

ex expand_trig(const ex& e) {
  ExpandTrig f;
  return f(e).expand();
}

Fraction simplify_ratio(const ex& e) {
  const ex nd = e.normal().numer_denom();
  ex num = combine_trig(nd.op(0)), den = combine_trig(nd.op(1));
  // A leading minus in the denominator reads better in front of the fraction.
  if (GiNaC::is_a<GiNaC::mul>(den) || GiNaC::is_a<GiNaC::numeric>(den)) {
    const ex k = GiNaC::is_a<GiNaC::numeric>(den) ? den : den.op(den.nops() - 1);
    if (GiNaC::is_a<GiNaC::numeric>(k) && GiNaC::ex_to<GiNaC::numeric>(k).is_negative()) {
      num = -num;
      den = -den;
    }
  }
  return {num, den};
}

}  // namespace gearkit::sym::detail
