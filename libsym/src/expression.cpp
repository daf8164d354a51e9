#include <gearkit/sym/expression.hpp>

#include "trig.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace gearkit::sym {

namespace {

GiNaC::ex parse(GiNaC::parser& reader, const std::string& text) {
  try {
    return reader(text);
  } catch (const std::exception& e) {
    throw std::invalid_argument(fmt::format("cannot read the expression '{}': {}", text, e.what()));
  }
}

bool vanishes(const GiNaC::ex& e) { return detail::expand_trig(e).expand().normal().is_zero(); }

}  // namespace

bool equivalent(const std::string& a, const std::string& b) {
  GiNaC::parser reader;  // one symbol table: the same name is the same symbol in a and b
  return vanishes(parse(reader, a) - parse(reader, b));
}

bool equivalent_up_to_sign(const std::string& a, const std::string& b) {
  GiNaC::parser reader;
  const GiNaC::ex x = parse(reader, a), y = parse(reader, b);
  return vanishes(x - y) || vanishes(x + y);
}

}  // namespace gearkit::sym
