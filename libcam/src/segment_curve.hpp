#pragma once
// The curves of table and polynomial segments (internal to libcam): s(theta) with its first
// three derivatives per radian, for the cam angle theta in [x0, x1] of the segment.
#include <gearkit/cam/motion_program.hpp>

#include <memory>
#include <vector>

namespace gearkit::cam {

class SegmentCurve {
 public:
  virtual ~SegmentCurve() = default;
  /// s and derivatives at theta (clamped to the segment); at an inner break, the value after it.
  virtual Motion at(double theta) const = 0;
  /// The limit from the left at theta (differs from at() only at inner breaks).
  virtual Motion left_at(double theta) const = 0;
  /// Cam angles inside the segment where a derivative of order <= 3 may jump.
  virtual std::vector<double> inner_breaks() const = 0;
};

/// Piecewise polynomial on knots x_0 < ... < x_n: piece k in u = (theta - x_k) / (x_{k+1} - x_k),
/// coefficients in ascending powers of u.
class PiecewisePolynomial : public SegmentCurve {
 public:
  PiecewisePolynomial(std::vector<double> knots, std::vector<std::vector<double>> coefficients);
  Motion at(double theta) const override;
  Motion left_at(double theta) const override;
  std::vector<double> inner_breaks() const override;
  const std::vector<double>& knots() const { return x_; }

 private:
  Motion eval_piece(std::size_t k, double theta) const;
  std::vector<double> x_;
  std::vector<std::vector<double>> c_;
};

/// Interpolating cubic spline (C2) through (x, y) with the given ends (de Boor, "A Practical
/// Guide to Splines", ch. IV).
std::shared_ptr<PiecewisePolynomial> cubic_spline(const std::vector<double>& x, const std::vector<double>& y,
                                                  TableEnds ends);

/// Monotone piecewise cubic Hermite interpolation (Fritsch & Carlson, SIAM J. Numer. Anal. 17
/// (1980) 238-246, with the weighted harmonic-mean slopes of Fritsch & Butland, SIAM J. Sci.
/// Stat. Comput. 5 (1984) 300-304, as in Moler's pchip): on every interval the curve stays
/// between its two end values.
std::shared_ptr<PiecewisePolynomial> pchip(const std::vector<double>& x, const std::vector<double>& y, TableEnds ends);

/// The polynomial on [x0, x1] meeting the end conditions (derivatives per radian), of degree
/// (number of conditions - 1). Both ends must give s. @throws std::invalid_argument if the
/// conditions skip an order or the system is singular.
std::shared_ptr<PiecewisePolynomial> polynomial_from_conditions(double x0, double x1, const EndConditions& start,
                                                                const EndConditions& end);

/// Quintic (or lower, with fewer points) clamped uniform B-spline whose control polygon is
/// (x_i, y_i), as the function y(x) of the parametric curve (x(u), y(u)); zero_slope ends add
/// three control points with the end value over the first and last intervals (quarter steps),
/// making velocity, acceleration and jerk vanish at both ends. Piegl & Tiller, "The NURBS
/// Book", 2nd ed., sec. 2.3 (basis functions and their derivatives, A2.2-A2.3).
std::shared_ptr<SegmentCurve> bspline_table(const std::vector<double>& x, const std::vector<double>& y, TableEnds ends);

}  // namespace gearkit::cam
