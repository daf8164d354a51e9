#pragma once
// Torque laws typed as formulas in a model file ("116*(0.3 + 0.7*(omega/w0)^2 - (omega/w0)^4)"),
// evaluated with muParser (libmuparser-dev). Only arithmetic, the usual functions (sin, cos,
// sqrt, exp, abs, min, max, ...) and the constant _pi are available: an expression cannot
// reach files or the program, so a model file stays data.
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace gearkit::dyn {

class Expression {
 public:
  /// Compiles `text` with the given variable names (their values are passed to operator() in
  /// the same order) and named constants.
  /// @throws std::invalid_argument with muParser's reason and the character position when the
  ///         text is malformed, empty, or uses a name that is neither a variable, a constant nor
  ///         a built-in function.
  Expression(std::string text, std::vector<std::string> variables,
             const std::map<std::string, double>& constants = {});

  /// The value for `values` (one per variable, SI).
  /// @throws std::domain_error if the result is not finite (division by zero, sqrt(-1)); the
  ///         message names the expression and the variable values.
  double operator()(std::span<const double> values) const;
  double operator()(std::initializer_list<double> values) const {
    return (*this)(std::span<const double>(values.begin(), values.size()));
  }

  const std::string& text() const { return text_; }
  const std::vector<std::string>& variables() const { return variables_; }

 private:
  struct Impl;
  std::string text_;
  std::vector<std::string> variables_;
  // Shared and not thread-safe: muParser evaluates from bound variable storage.
  std::shared_ptr<Impl> impl_;
};

}  // namespace gearkit::dyn
