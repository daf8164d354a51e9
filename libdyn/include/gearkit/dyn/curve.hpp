#pragma once
// Piecewise-linear curves of one variable: torque against shaft angle (a textbook's torque
// diagram), motor torque against speed. Linear pieces are what the seeds draw, and they keep
// every integral, crossing and energy extreme exact (no quadrature error).
//
// Units are the caller's; gearkit::dyn uses SI throughout (rad, N*m, rad/s).
#include <functional>
#include <vector>

namespace gearkit::dyn {

/// y(x) through the points (x_i, y_i), linear in between.
///
/// x must be non-decreasing; two consecutive points with the same x make a step (the value
/// jumps there; at the step itself the curve takes the right-hand value). A periodic curve
/// repeats with period x_back - x_front outside its table; its first and last values must be
/// equal (write a jump at the end explicitly as two points with the same x).
/// A non-periodic curve holds its end values outside its table.
class PiecewiseLinear {
 public:
  /// @throws std::invalid_argument if fewer than 2 points, x and y differ in length, a value is
  ///         not finite, x decreases, three points share one x, x_back <= x_front, or (periodic)
  ///         the first and last values differ by more than 1e-9 of the largest |y|.
  PiecewiseLinear(std::vector<double> x, std::vector<double> y, bool periodic);

  /// A constant over [x0, x1] (periodic, so it repeats).
  static PiecewiseLinear constant(double value, double x0, double x1);

  double operator()(double x) const;  ///< right-hand value at steps
  double left_value(double x) const;  ///< left-hand limit (differs from operator() only at steps)

  /// Integral of y from a to b (b < a gives the negative). Periodic curves accept any a, b;
  /// non-periodic ones extend their end values.
  double integral(double a, double b) const;

  /// Mean value over one table range: integral(x_front, x_back) / (x_back - x_front).
  double mean() const;

  /// The same curve with every y multiplied by k.
  PiecewiseLinear scaled(double k) const;
  /// The same curve with x multiplied by k (k > 0): e.g. table angles from one shaft to another.
  PiecewiseLinear stretched(double k) const;

  double max_value() const;

  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  bool periodic() const { return periodic_; }
  double x_front() const { return x_.front(); }
  double x_back() const { return x_.back(); }
  double range() const { return x_.back() - x_.front(); }

 private:
  double wrap(double x) const;                 ///< into [x_front, x_back) for periodic curves
  double integral_from_front(double x) const;  ///< x inside the table range

  std::vector<double> x_, y_;
  std::vector<double> cumulative_;  ///< integral from x_front to x_i
  bool periodic_ = false;
};

/// Samples f at n + 1 equally spaced points over [x0, x1] into a piecewise-linear curve.
/// The linear interpolation error is f''(x) h^2 / 8 at most (h = (x1 - x0) / n).
/// @throws std::invalid_argument if n < 1, x1 <= x0, or f returns a non-finite value (the
///         message names the x).
PiecewiseLinear sample(const std::function<double(double)>& f, double x0, double x1, int n, bool periodic);

/// f - g on the union of both tables' breakpoints (steps kept), over their common range.
/// @throws std::invalid_argument if the ranges differ by more than 1e-9 of the range.
PiecewiseLinear difference(const PiecewiseLinear& f, const PiecewiseLinear& g);

}  // namespace gearkit::dyn
