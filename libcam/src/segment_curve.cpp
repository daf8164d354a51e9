// Piecewise polynomial segment curves: cubic spline and pchip tables, polynomials from
// boundary conditions.
#include "segment_curve.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace gearkit::cam {
namespace {

/// p(u) and its first three derivatives (ascending coefficients), by repeated synthetic
/// division (Horner): d[k] accumulates the k-th derivative divided by k!.
std::array<double, 4> horner(const std::vector<double>& c, double u) {
  std::array<double, 4> d{0, 0, 0, 0};
  for (std::size_t j = c.size(); j-- > 0;) {
    d[3] = d[3] * u + d[2];
    d[2] = d[2] * u + d[1];
    d[1] = d[1] * u + d[0];
    d[0] = d[0] * u + c[j];
  }
  d[2] *= 2, d[3] *= 6;
  return d;
}

/// Second derivatives M of the interpolating cubic spline through (x, y), from the continuity of
/// the first derivative at the inner knots plus the end conditions. Tables have tens of points,
/// so a dense LU is enough.
std::vector<double> spline_second_derivatives(const std::vector<double>& x, const std::vector<double>& y,
                                              TableEnds ends) {
  const int n = static_cast<int>(x.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  auto h = [&](int i) { return x[i + 1] - x[i]; };
  auto slope = [&](int i) { return (y[i + 1] - y[i]) / h(i); };
  for (int i = 1; i + 1 < n; ++i) {
    A(i, i - 1) = h(i - 1);
    A(i, i) = 2 * (h(i - 1) + h(i));
    A(i, i + 1) = h(i);
    b(i) = 6 * (slope(i) - slope(i - 1));
  }
  switch (ends) {
    case TableEnds::natural:
      A(0, 0) = 1;
      A(n - 1, n - 1) = 1;
      break;
    case TableEnds::zero_slope:
      A(0, 0) = 2 * h(0), A(0, 1) = h(0), b(0) = 6 * slope(0);
      A(n - 1, n - 2) = h(n - 2), A(n - 1, n - 1) = 2 * h(n - 2), b(n - 1) = -6 * slope(n - 2);
      break;
    case TableEnds::periodic:
      // M_0 = M_{n-1}, and the slope at the last knot equals the slope at the first.
      A(n - 1, 0) = 1, A(n - 1, n - 1) = -1;
      A(0, 0) = 2 * (h(0) + h(n - 2)), A(0, 1) = h(0), A(0, n - 2) = h(n - 2);
      b(0) = 6 * (slope(0) - slope(n - 2));
      break;
  }
  const Eigen::VectorXd m = A.partialPivLu().solve(b);
  return {m.data(), m.data() + n};
}

/// The cubic on [0, 1] in u with values y0, y1 and slopes d0, d1 per unit of theta (h = width).
std::vector<double> hermite_cubic(double y0, double y1, double d0, double d1, double h) {
  return {y0, h * d0, 3 * (y1 - y0) - h * (2 * d0 + d1), 2 * (y0 - y1) + h * (d0 + d1)};
}

/// Fritsch-Butland slope at an inner point between secants d_prev (width h_prev) and d_next.
double harmonic_slope(double d_prev, double d_next, double h_prev, double h_next) {
  if (d_prev * d_next <= 0) return 0;  // a local extremum (or flat): the curve turns here
  const double w1 = 2 * h_next + h_prev, w2 = h_next + 2 * h_prev;
  return (w1 + w2) / (w1 / d_prev + w2 / d_next);
}

/// Moler's shape-preserving three-point end slope (pchip's "pchipend").
double end_slope(double h0, double h1, double d0, double d1) {
  double d = ((2 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
  if (d * d0 <= 0) return 0;
  if (d0 * d1 < 0 && std::abs(d) > 3 * std::abs(d0)) return 3 * d0;
  return d;
}

double factorial_ratio(int j, int k) {  // j! / (j - k)!
  double r = 1;
  for (int i = 0; i < k; ++i) r *= j - i;
  return r;
}

/// The conditions of one end as a list {order, value per rad^order}.
std::vector<std::pair<int, double>> conditions_of(const EndConditions& e, const char* which) {
  const std::optional<double> given[4] = {e.s, e.v, e.a, e.j};
  std::vector<std::pair<int, double>> out;
  for (int k = 0; k < 4; ++k) {
    if (!given[k]) continue;
    if (static_cast<int>(out.size()) != k) {
      throw std::invalid_argument(std::string("the ") + which + " conditions skip an order: give s, v, a, j in order " +
                                  "(a without v, or j without a, has no unique polynomial)");
    }
    if (!std::isfinite(*given[k])) throw std::invalid_argument(std::string("the ") + which + " conditions must be finite");
    out.emplace_back(k, *given[k]);
  }
  if (out.empty()) throw std::invalid_argument(std::string("the ") + which + " conditions need at least s");
  return out;
}

}  // namespace

PiecewisePolynomial::PiecewisePolynomial(std::vector<double> knots, std::vector<std::vector<double>> coefficients)
    : x_(std::move(knots)), c_(std::move(coefficients)) {}

Motion PiecewisePolynomial::eval_piece(std::size_t k, double theta) const {
  const double h = x_[k + 1] - x_[k];
  const double u = std::clamp((theta - x_[k]) / h, 0.0, 1.0);
  const auto d = horner(c_[k], u);
  return {d[0], d[1] / h, d[2] / (h * h), d[3] / (h * h * h)};
}

Motion PiecewisePolynomial::at(double theta) const {
  const auto it = std::upper_bound(x_.begin(), x_.end(), theta);
  const std::size_t k = std::clamp<std::size_t>(static_cast<std::size_t>(it - x_.begin()), 1, x_.size() - 1) - 1;
  return eval_piece(k, theta);
}

Motion PiecewisePolynomial::left_at(double theta) const {
  const auto it = std::lower_bound(x_.begin(), x_.end(), theta);
  const std::size_t k = std::clamp<std::size_t>(static_cast<std::size_t>(it - x_.begin()), 1, x_.size() - 1) - 1;
  return eval_piece(k, theta);
}

std::vector<double> PiecewisePolynomial::inner_breaks() const { return {x_.begin() + 1, x_.end() - 1}; }

std::shared_ptr<PiecewisePolynomial> cubic_spline(const std::vector<double>& x, const std::vector<double>& y,
                                                  TableEnds ends) {
  const std::vector<double> M = spline_second_derivatives(x, y, ends);
  std::vector<std::vector<double>> c;
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    const double h = x[k + 1] - x[k];
    const double b = (y[k + 1] - y[k]) / h - h * (2 * M[k] + M[k + 1]) / 6;
    c.push_back({y[k], b * h, M[k] * h * h / 2, (M[k + 1] - M[k]) * h * h / 6});
  }
  return std::make_shared<PiecewisePolynomial>(x, std::move(c));
}

std::shared_ptr<PiecewisePolynomial> pchip(const std::vector<double>& x, const std::vector<double>& y, TableEnds ends) {
  const std::size_t n = x.size();
  std::vector<double> h(n - 1), delta(n - 1), d(n, 0.0);
  for (std::size_t k = 0; k + 1 < n; ++k) h[k] = x[k + 1] - x[k], delta[k] = (y[k + 1] - y[k]) / h[k];
  for (std::size_t k = 1; k + 1 < n; ++k) d[k] = harmonic_slope(delta[k - 1], delta[k], h[k - 1], h[k]);
  if (ends == TableEnds::periodic) {
    d[0] = d[n - 1] = harmonic_slope(delta[n - 2], delta[0], h[n - 2], h[0]);
  } else if (ends == TableEnds::natural) {
    d[0] = n > 2 ? end_slope(h[0], h[1], delta[0], delta[1]) : delta[0];
    d[n - 1] = n > 2 ? end_slope(h[n - 2], h[n - 3], delta[n - 2], delta[n - 3]) : delta[0];
  }
  std::vector<std::vector<double>> c;
  for (std::size_t k = 0; k + 1 < n; ++k) c.push_back(hermite_cubic(y[k], y[k + 1], d[k], d[k + 1], h[k]));
  return std::make_shared<PiecewisePolynomial>(x, std::move(c));
}

std::shared_ptr<PiecewisePolynomial> polynomial_from_conditions(double x0, double x1, const EndConditions& start,
                                                                const EndConditions& end) {
  const auto at0 = conditions_of(start, "start"), at1 = conditions_of(end, "end");
  const int n = static_cast<int>(at0.size() + at1.size());
  const double beta = x1 - x0;
  // In u = (theta - x0) / beta: d^k y/du^k = beta^k d^k s/dtheta^k.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b(n);
  int row = 0;
  for (const auto& [k, value] : at0) {
    A(row, k) = factorial_ratio(k, k);  // only u^k survives at u = 0
    b(row++) = value * std::pow(beta, k);
  }
  for (const auto& [k, value] : at1) {
    for (int j = k; j < n; ++j) A(row, j) = factorial_ratio(j, k);
    b(row++) = value * std::pow(beta, k);
  }
  // Hermite interpolation with consecutive orders at each end always has a unique solution.
  const Eigen::VectorXd a = A.fullPivLu().solve(b);
  return std::make_shared<PiecewisePolynomial>(std::vector<double>{x0, x1},
                                               std::vector<std::vector<double>>{{a.data(), a.data() + n}});
}

}  // namespace gearkit::cam
