#include <gearkit/dyn/curve.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "number_text.hpp"

namespace gearkit::dyn {

namespace {

double trapezoid(double x0, double y0, double x1, double y1) { return 0.5 * (y0 + y1) * (x1 - x0); }

double lerp(double x0, double y0, double x1, double y1, double x) {
  return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
}

}  // namespace

PiecewiseLinear::PiecewiseLinear(std::vector<double> x, std::vector<double> y, bool periodic)
    : x_(std::move(x)), y_(std::move(y)), periodic_(periodic) {
  if (x_.size() != y_.size())
    throw std::invalid_argument("curve: " + std::to_string(x_.size()) + " abscissae but " +
                                std::to_string(y_.size()) + " values");
  if (x_.size() < 2)
    throw std::invalid_argument("curve: expected at least 2 points, found " + std::to_string(x_.size()));
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (!std::isfinite(x_[i]) || !std::isfinite(y_[i]))
      throw std::invalid_argument("curve: point " + std::to_string(i + 1) + " is not finite");
    if (i > 0 && x_[i] < x_[i - 1])
      throw std::invalid_argument("curve: abscissae must not decrease, found " + detail::num(x_[i], 9) + " after " +
                                  detail::num(x_[i - 1], 9) + " at point " + std::to_string(i + 1));
    if (i > 1 && x_[i] == x_[i - 1] && x_[i] == x_[i - 2])
      throw std::invalid_argument("curve: three points share the abscissa " + detail::num(x_[i], 9) +
                                  " (a step needs exactly two)");
  }
  if (!(x_.back() > x_.front()))
    throw std::invalid_argument("curve: the table spans no range (first and last abscissa are both " +
                                detail::num(x_.front(), 9) + ")");
  if (periodic_) {
    double scale = 0;
    for (double v : y_) scale = std::max(scale, std::abs(v));
    if (std::abs(y_.front() - y_.back()) > 1e-9 * std::max(scale, 1e-300))
      throw std::invalid_argument("curve is not periodic: value " + detail::num(y_.front(), 9) + " at the start (" +
                                  detail::num(x_.front(), 9) + ") differs from " + detail::num(y_.back(), 9) + " at the end (" +
                                  detail::num(x_.back(), 9) + ")");
  }
  cumulative_.assign(x_.size(), 0.0);
  for (std::size_t i = 1; i < x_.size(); ++i)
    cumulative_[i] = cumulative_[i - 1] + trapezoid(x_[i - 1], y_[i - 1], x_[i], y_[i]);
}

PiecewiseLinear PiecewiseLinear::constant(double value, double x0, double x1) {
  return PiecewiseLinear({x0, x1}, {value, value}, true);
}

double PiecewiseLinear::wrap(double x) const {
  if (!periodic_) return x;
  const double period = range();
  double r = x - x_.front();
  r -= period * std::floor(r / period);
  if (r >= period || r < 0) r = 0;  // rounding at the period boundary
  return x_.front() + r;
}

double PiecewiseLinear::operator()(double x) const {
  const double xw = wrap(x);
  if (xw < x_.front()) return y_.front();
  if (xw >= x_.back()) return y_.back();
  const auto it = std::upper_bound(x_.begin(), x_.end(), xw);
  const auto i = static_cast<std::size_t>(it - x_.begin());  // x_[i-1] <= xw < x_[i]
  return lerp(x_[i - 1], y_[i - 1], x_[i], y_[i], xw);
}

double PiecewiseLinear::left_value(double x) const {
  double xw = wrap(x);
  if (periodic_ && xw == x_.front()) xw = x_.back();  // the left limit at the period start
  if (xw <= x_.front()) return y_.front();
  if (xw > x_.back()) return y_.back();
  const auto it = std::lower_bound(x_.begin(), x_.end(), xw);
  const auto i = static_cast<std::size_t>(it - x_.begin());  // x_[i-1] < xw <= x_[i]
  return lerp(x_[i - 1], y_[i - 1], x_[i], y_[i], xw);
}

double PiecewiseLinear::integral_from_front(double x) const {
  if (x <= x_.front()) return 0;
  if (x >= x_.back()) return cumulative_.back();
  const auto it = std::upper_bound(x_.begin(), x_.end(), x);
  const auto i = static_cast<std::size_t>(it - x_.begin()) - 1;
  return cumulative_[i] + trapezoid(x_[i], y_[i], x, lerp(x_[i], y_[i], x_[i + 1], y_[i + 1], x));
}

double PiecewiseLinear::integral(double a, double b) const {
  const auto antiderivative = [this](double x) {
    if (periodic_) {
      const double period = range();
      const double turns = std::floor((x - x_.front()) / period);
      return turns * cumulative_.back() + integral_from_front(wrap(x));
    }
    if (x < x_.front()) return (x - x_.front()) * y_.front();
    if (x > x_.back()) return cumulative_.back() + (x - x_.back()) * y_.back();
    return integral_from_front(x);
  };
  return antiderivative(b) - antiderivative(a);
}

double PiecewiseLinear::mean() const { return cumulative_.back() / range(); }

PiecewiseLinear PiecewiseLinear::scaled(double k) const {
  std::vector<double> y = y_;
  for (double& v : y) v *= k;
  return PiecewiseLinear(x_, std::move(y), periodic_);
}

PiecewiseLinear PiecewiseLinear::stretched(double k) const {
  if (!(k > 0) || !std::isfinite(k))
    throw std::invalid_argument("curve: stretch factor must be positive and finite, found " + detail::num(k, 9));
  std::vector<double> x = x_;
  for (double& v : x) v *= k;
  return PiecewiseLinear(std::move(x), y_, periodic_);
}

double PiecewiseLinear::max_value() const { return *std::max_element(y_.begin(), y_.end()); }

PiecewiseLinear sample(const std::function<double(double)>& f, double x0, double x1, int n, bool periodic) {
  if (n < 1) throw std::invalid_argument("sample: expected at least 1 interval, found " + std::to_string(n));
  if (!(x1 > x0)) throw std::invalid_argument("sample: empty range [" + detail::num(x0, 9) + ", " + detail::num(x1, 9) + "]");
  std::vector<double> x(static_cast<std::size_t>(n) + 1), y(x.size());
  for (int i = 0; i <= n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    x[k] = i == n ? x1 : x0 + (x1 - x0) * i / n;
    y[k] = f(x[k]);
    if (!std::isfinite(y[k])) throw std::invalid_argument("curve value is not finite at " + detail::num(x[k], 9));
  }
  return PiecewiseLinear(std::move(x), std::move(y), periodic);
}

PiecewiseLinear difference(const PiecewiseLinear& f, const PiecewiseLinear& g) {
  const double tol = 1e-9 * f.range();
  if (std::abs(f.x_front() - g.x_front()) > tol || std::abs(f.x_back() - g.x_back()) > tol)
    throw std::invalid_argument("curves cover different ranges: [" + detail::num(f.x_front(), 9) + ", " + detail::num(f.x_back(), 9) +
                                "] and [" + detail::num(g.x_front(), 9) + ", " + detail::num(g.x_back(), 9) + "]");
  std::vector<double> xs = f.x();
  for (double v : g.x()) xs.push_back(std::clamp(v, f.x_front(), f.x_back()));
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end(), [tol](double a, double b) { return std::abs(a - b) <= tol; }),
           xs.end());
  xs.front() = f.x_front();
  xs.back() = f.x_back();
  std::vector<double> x, y;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double xi = xs[i];
    const double right = f(xi) - g(xi);
    if (i == 0) {
      // The tables' first values, not operator(): a step at the very start must survive.
      const double first = f.y().front() - g.y().front();
      x.push_back(xi);
      y.push_back(first);
      if (right != first) {
        x.push_back(xi);
        y.push_back(right);
      }
      continue;
    }
    const double left = f.left_value(xi) - g.left_value(xi);
    x.push_back(xi);
    y.push_back(left);
    if (i + 1 < xs.size() && right != left) {
      x.push_back(xi);
      y.push_back(right);
    }
  }
  // The difference of two periodic curves is periodic. Its end must return to its start value:
  // a rounding-level mismatch is snapped, a real one is a step at the period end.
  const bool periodic = f.periodic() && g.periodic();
  if (periodic && y.back() != y.front()) {
    double scale = 0;
    for (double v : y) scale = std::max(scale, std::abs(v));
    if (std::abs(y.back() - y.front()) <= 1e-12 * scale) {
      y.back() = y.front();
    } else {
      x.push_back(x.back());
      y.push_back(y.front());
    }
  }
  return PiecewiseLinear(std::move(x), std::move(y), periodic);
}

}  // namespace gearkit::dyn
