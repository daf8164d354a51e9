#include <gearkit/dyn/expression.hpp>

#include <muParser.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace gearkit::dyn {

struct Expression::Impl {
  mu::Parser parser;
  std::vector<double> storage;  // sized once: muParser keeps pointers into it
};

Expression::Expression(std::string text, std::vector<std::string> variables,
                       const std::map<std::string, double>& constants)
    : text_(std::move(text)), variables_(std::move(variables)), impl_(std::make_shared<Impl>()) {
  if (text_.find_first_not_of(" \t") == std::string::npos)
    throw std::invalid_argument("expression is empty");
  impl_->storage.assign(variables_.size(), 0.0);
  try {
    for (std::size_t i = 0; i < variables_.size(); ++i)
      impl_->parser.DefineVar(variables_[i], &impl_->storage[i]);
    for (const auto& [name, value] : constants) impl_->parser.DefineConst(name, value);
    impl_->parser.SetExpr(text_);
    // Compiles now so that syntax errors and unknown names surface while reading the model.
    (void)impl_->parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    throw std::invalid_argument("expression '" + text_ + "': " + e.GetMsg() + " (at character " +
                                std::to_string(e.GetPos() + 1) + ")");
  }
}

double Expression::operator()(std::span<const double> values) const {
  if (values.size() != impl_->storage.size())
    throw std::invalid_argument("expression '" + text_ + "': expected " + std::to_string(impl_->storage.size()) +
                                " values, found " + std::to_string(values.size()));
  std::copy(values.begin(), values.end(), impl_->storage.begin());
  double result = 0;
  try {
    result = impl_->parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    throw std::domain_error("expression '" + text_ + "': " + e.GetMsg());
  }
  if (!std::isfinite(result)) {
    std::string where;
    for (std::size_t i = 0; i < values.size(); ++i) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%s%s = %.6g", i ? ", " : "", variables_[i].c_str(), values[i]);
      where += buf;
    }
    throw std::domain_error("expression '" + text_ + "' is not finite at " + (where.empty() ? "its constants" : where));
  }
  return result;
}

}  // namespace gearkit::dyn
