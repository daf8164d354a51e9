#pragma once
// Torques as a model file gives them (constants, tables against the angle, expressions, constant
// power), read with their place in the file and turned into curves or functions for libdyn.
#include <gearkit/dyn/curve.hpp>
#include <gearkit/dyn/expression.hpp>
#include <gearkit/io/error.hpp>

#include <yaml-cpp/yaml.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace gearkit::plugins::dyn {

namespace gd = gearkit::dyn;

/// A torque given in the file: a constant, a table against the shaft angle, an expression of
/// theta [rad], omega [rad/s] and t [s], or a constant power (torque P / omega).
struct TorqueLaw {
  enum class Kind { constant, table, expression, constant_power };
  Kind kind = Kind::constant;
  std::string what;                 ///< "resisting torque of the load", for messages
  io::SourceMark mark;
  double value = 0;                 ///< N*m (constant) or W (constant_power)
  std::vector<double> angle, torque;  ///< table, rad and N*m
  std::vector<io::SourceMark> row_marks;
  std::string expression;
  std::map<std::string, double> parameters;
  int samples = 720;                ///< intervals per cycle when an expression is tabulated
  double scale = 1;                 ///< multiplies the torque
  bool balance = false;             ///< scale so that the cycle's energies balance
};

/// The law as a periodic curve over [0, cycle] rad of its shaft.
/// @throws io::InputError at the law's place if a table does not cover the cycle or is not
///         periodic, an expression uses omega or t, or the law is a constant power.
gd::PiecewiseLinear curve_of(const TorqueLaw& law, double cycle);

/// The law as a function of (theta, omega, t). Tables repeat with their own range.
/// @throws io::InputError at the law's place for a malformed expression.
std::function<double(double, double, double)> function_of(const TorqueLaw& law);

/// Reads a torque law: a scalar torque, or a mapping with exactly one of constant, table,
/// expression (with parameters, samples) or power, and an optional scale (a number or 'balance').
/// @throws io::InputError at the offending node.
TorqueLaw read_law(const YAML::Node& node, const std::string& file, const std::string& what);

}  // namespace gearkit::plugins::dyn
